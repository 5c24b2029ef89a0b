// A bounded hand-off of batches between two threads, so that reading, estimating and writing a
// recording overlap while the memory in flight stays a fixed number of batches.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <mutex>
#include <vector>

namespace armtrack::cli {

/// One producer fills batches, one consumer empties them, in order. There are `depth` batches in
/// all, made once and recycled, so the producer waits when the consumer falls behind and memory
/// does not grow. Either side may end the exchange: the producer with finish() (after its last
/// batch, or with the exception that stopped it), the consumer with stop() (the producer's next
/// acquire() then returns nullptr). The consumer sees the producer's exception after the batches
/// sent before it, as a serial loop would have met it.
template <typename Batch>
class Handoff {
 public:
  explicit Handoff(std::size_t depth) : m_batches(depth) {
    for (Batch& b : m_batches) m_free.push_back(&b);
  }
  Handoff(const Handoff&) = delete;
  Handoff& operator=(const Handoff&) = delete;

  /// Producer: an empty batch to fill (as the consumer left it; clear it first), or nullptr
  /// when the consumer has stopped.
  Batch* acquire() {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [&] { return m_stopped || !m_free.empty(); });
    if (m_stopped) return nullptr;
    Batch* b = m_free.front();
    m_free.pop_front();
    return b;
  }
  /// Producer: passes a filled batch (from acquire) to the consumer.
  void send(Batch* b) {
    {
      std::lock_guard lock(m_mutex);
      m_full.push_back(b);
    }
    m_changed.notify_all();
  }
  /// Producer: nothing more comes; error, when set, is rethrown by the consumer's receive()
  /// after the batches already sent.
  void finish(std::exception_ptr error = nullptr) {
    {
      std::lock_guard lock(m_mutex);
      m_finished = true;
      m_error = error;
    }
    m_changed.notify_all();
  }

  /// Consumer: the next batch, or nullptr after the last one. Rethrows the producer's error.
  Batch* receive() {
    std::unique_lock lock(m_mutex);
    m_changed.wait(lock, [&] { return m_finished || !m_full.empty(); });
    if (!m_full.empty()) {
      Batch* b = m_full.front();
      m_full.pop_front();
      return b;
    }
    if (m_error) std::rethrow_exception(m_error);
    return nullptr;
  }
  /// Consumer: gives a batch back for the producer to fill again.
  void release(Batch* b) {
    {
      std::lock_guard lock(m_mutex);
      m_free.push_back(b);
    }
    m_changed.notify_all();
  }
  /// Consumer: wants no more batches; the producer's acquire() returns nullptr from now on.
  void stop() {
    {
      std::lock_guard lock(m_mutex);
      m_stopped = true;
    }
    m_changed.notify_all();
  }

 private:
  std::vector<Batch> m_batches;
  std::mutex m_mutex;
  std::condition_variable m_changed;
  std::deque<Batch*> m_free, m_full;
  bool m_finished = false, m_stopped = false;
  std::exception_ptr m_error;
};

}  // namespace armtrack::cli
