// Loss, reordering and duplicate accounting for a stream of sequence-numbered packets (UDP). A
// number skipped when a newer packet arrives is counted missing at once; if it arrives later,
// within a window of kWindow packets, it is counted reordered instead of lost. See
// docs/time-sync.md, "Losses and reordering".
#pragma once

#include <bit>
#include <cstdint>

namespace armtrack {

/// What SequenceTracker::add made of a packet.
enum class SequenceStatus {
  InOrder,    ///< newer than every packet before (the first packet too)
  Reordered,  ///< older than the newest, missing until now, within the window: use it
  Duplicate,  ///< seen before: drop it
  TooLate,    ///< older than the window: it stays counted lost; drop it
};

/// Sequence numbers are unbounded (64-bit); a caller with a wrapping counter unwraps it first.
/// Plain data, no allocation. Not thread-safe.
class SequenceTracker {
 public:
  static constexpr std::uint64_t kWindow = 64;  ///< how far back a late packet is still taken

  /// Takes the packet with sequence number seq.
  SequenceStatus add(std::uint64_t seq) {
    if (!m_started) {
      m_started = true;
      m_highest = seq;
      m_seen = 1;
      return SequenceStatus::InOrder;
    }
    if (seq > m_highest) {
      const std::uint64_t shift = seq - m_highest;
      m_missing += shift - 1;
      m_seen = shift >= kWindow ? 1 : (m_seen << shift) | 1u;
      m_highest = seq;
      return SequenceStatus::InOrder;
    }
    const std::uint64_t back = m_highest - seq;
    if (back >= kWindow) {
      ++m_tooLate;
      return SequenceStatus::TooLate;
    }
    const std::uint64_t bit = std::uint64_t{1} << back;
    if (m_seen & bit) {
      ++m_duplicates;
      return SequenceStatus::Duplicate;
    }
    m_seen |= bit;
    ++m_reordered;
    return SequenceStatus::Reordered;
  }

  /// Forgets the position (the sender's counter restarted); the counters are kept.
  void restart() { m_started = false; }

  /// Numbers skipped when a newer packet arrived (some may arrive later: reordered()).
  std::uint64_t missing() const { return m_missing; }
  std::uint64_t reordered() const { return m_reordered; }  ///< missing ones that arrived late
  std::uint64_t lost() const { return m_missing - m_reordered; }
  std::uint64_t duplicates() const { return m_duplicates; }
  std::uint64_t tooLate() const { return m_tooLate; }  ///< arrived older than the window
  bool started() const { return m_started; }

 private:
  bool m_started = false;
  std::uint64_t m_highest = 0;
  std::uint64_t m_seen = 0;  ///< bit i: packet m_highest - i has arrived
  std::uint64_t m_missing = 0, m_reordered = 0, m_duplicates = 0, m_tooLate = 0;
};

}  // namespace armtrack
