// Internal to core/io: the recording reader's file access, with its checks at the door (a
// regular file, its size, text only, line length; docs/recording-format.md, "Limits"). Not a
// public header.
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace armtrack::recording_detail {

/// What a file that is not a regular one is, for messages: "a directory", "a FIFO (named pipe)".
std::string kindOf(std::filesystem::file_type type);
/// Throws RecordingError on file: it is kind, not a regular file; expected says what it should
/// be.
[[noreturn]] void notARegularFile(
    const std::string& file, const std::string& kind,
    const std::string& expected = "a recording is a .csv file on disk");

/// The index of the first control byte (C0 other than tab, LF, CR; DEL) in p[0, n), or n.
std::size_t findControl(const char* p, std::size_t n);

/// Reads a file in chunks and yields the lines that carry data (not blank, not comments) with
/// their physical line numbers, and whether each ended with a newline (the last line of a file
/// cut short by a kill does not). Checks at the door, each a RecordingError naming the file (and
/// the line and column where one applies): a regular file (opened without blocking, so a FIFO
/// is refused, not waited on), at most RecordingLimits::kMaxFileBytes, no control byte in the
/// first kSniffBytes (read and checked before anything is parsed) nor anywhere after, no line
/// longer than kMaxLineBytes (refused without reading the rest of it). Memory: one 1 MiB chunk
/// plus at most one line.
class FileLines {
 public:
  explicit FileLines(const std::filesystem::path& path);
  ~FileLines();
  FileLines(const FileLines&) = delete;
  FileLines& operator=(const FileLines&) = delete;

  /// The next data line (valid until the next call), or false at the end of the file.
  bool next(std::string_view& line, int& number, bool& terminated);

  /// Bytes consumed so far (the lines returned and skipped).
  std::uint64_t bytesRead() const { return m_consumed + m_p; }
  /// The file's size when it was opened.
  std::uint64_t size() const { return m_size; }

 private:
  static constexpr std::uint64_t kNone = std::numeric_limits<std::uint64_t>::max();

  bool refill();
  std::size_t read(std::size_t want);
  [[noreturn]] void binaryContent() const;
  [[noreturn]] void lineTooLong() const;
  [[noreturn]] void tooLarge(std::uint64_t bytes) const;

  std::string m_name;
  int m_fd = -1;
  std::vector<char> m_buf;       // one chunk plus the longest line allowed
  std::size_t m_p = 0;           // next unread byte in m_buf
  std::size_t m_end = 0;         // end of the bytes read into m_buf
  std::uint64_t m_consumed = 0;  // file offset of m_buf[0]
  std::uint64_t m_size = 0;
  std::uint64_t m_control = kNone;  // file offset of the first control byte read, if any
  bool m_eof = false;
  int m_line = 0;
};

}  // namespace armtrack::recording_detail
