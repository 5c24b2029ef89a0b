// Counted, human-readable problems found by the byte-level protocol parsers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>

namespace armtrack::devices {

/// One problem in the input: where it was and what was wrong.
struct ParseError {
  std::uint64_t offset = 0;  ///< byte offset in the stream (or in the datagram, see the parser)
  std::string message;       ///< readable text, e.g. "bad checksum: got 3F, computed 41"
};

/// Counts every problem and keeps the most recent ones (bounded memory). Single-threaded: owned by
/// one parser, which lives in one thread.
class ParseErrorLog {
 public:
  /// Keeps at most `capacity` recent messages; the count is unbounded.
  explicit ParseErrorLog(std::size_t capacity = 32) : m_capacity(capacity) {}

  void report(std::uint64_t offset, std::string message);

  std::uint64_t count() const { return m_count; }
  const std::deque<ParseError>& recent() const { return m_recent; }
  /// The most recent message, or "" when there was none.
  std::string last() const { return m_recent.empty() ? std::string() : m_recent.back().message; }
  void clear();

 private:
  std::size_t m_capacity;
  std::uint64_t m_count = 0;
  std::deque<ParseError> m_recent;
};

}  // namespace armtrack::devices
