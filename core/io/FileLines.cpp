// The recording reader's file access and its checks at the door (docs/recording-format.md,
// "Limits").
#include "core/io/FileLines.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "core/io/Recording.h"
#include "core/io/RecordingFormat.h"

namespace armtrack::recording_detail {

namespace fs = std::filesystem;

namespace {

constexpr std::size_t kChunk = std::size_t{1} << 20;

/// A byte that text never holds: the C0 controls other than tab, LF and CR, and DEL.
constexpr bool isControl(unsigned char c) {
  return (c < 0x20 && c != '\t' && c != '\n' && c != '\r') || c == 0x7f;
}

std::string kindOfMode(mode_t mode) {
  if (S_ISDIR(mode)) return kindOf(fs::file_type::directory);
  if (S_ISFIFO(mode)) return kindOf(fs::file_type::fifo);
  if (S_ISCHR(mode)) return kindOf(fs::file_type::character);
  if (S_ISBLK(mode)) return kindOf(fs::file_type::block);
  if (S_ISSOCK(mode)) return kindOf(fs::file_type::socket);
  return kindOf(fs::file_type::unknown);
}

}  // namespace

std::string kindOf(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::fifo:
      return "a FIFO (named pipe)";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a file";
  }
}

void notARegularFile(const std::string& file, const std::string& kind,
                     const std::string& expected) {
  throw RecordingError(
      file, 0, 0, "cannot open file: it is " + kind + ", not a regular file (" + expected + ")");
}

std::size_t findControl(const char* p, std::size_t n) {
  // Blocks of 64 bytes are tested without branches, in a form GCC vectorises at -O2 (about
  // 5 GB/s here, against 0.9 GB/s byte by byte); only a block that holds a control byte is
  // searched byte by byte.
  constexpr std::size_t kBlock = 64;
  std::size_t i = 0;
  for (; i + kBlock <= n; i += kBlock) {
    unsigned char any = 0;
    for (std::size_t k = 0; k < kBlock; ++k) {
      const auto c = static_cast<unsigned char>(p[i + k]);
      any |= static_cast<unsigned char>((c < 0x20) & (c != '\t') & (c != '\n') & (c != '\r'));
      any |= static_cast<unsigned char>(c == 0x7f);
    }
    if (any) break;
  }
  for (; i < n; ++i) {
    if (isControl(static_cast<unsigned char>(p[i]))) return i;
  }
  return n;
}

FileLines::FileLines(const fs::path& path) : m_name(path.string()) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status))
    notARegularFile(m_name, kindOf(status.type()));
  // O_NONBLOCK: a FIFO or a device put in the file's place since must not block open(); a regular
  // file ignores the flag.
  errno = 0;
  m_fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (m_fd < 0) throw RecordingError(m_name, 0, 0, "cannot open file: " + osReason(errno));
  try {
    struct stat st {};
    if (::fstat(m_fd, &st) != 0)
      throw RecordingError(m_name, 0, 0, "cannot open file: " + osReason(errno));
    if (!S_ISREG(st.st_mode)) notARegularFile(m_name, kindOfMode(st.st_mode));
    m_size = static_cast<std::uint64_t>(st.st_size);
    if (m_size > RecordingLimits::kMaxFileBytes) tooLarge(m_size);
    m_buf.resize(kChunk + RecordingLimits::kMaxLineBytes + 1);
    // The first look: a little is read and checked before anything is parsed, so a binary file
    // (or a sparse one, whose holes read as NULs) is refused having read only that.
    read(RecordingLimits::kSniffBytes);
    if (m_control != kNone) binaryContent();
  } catch (...) {
    ::close(m_fd);
    throw;
  }
}

FileLines::~FileLines() {
  ::close(m_fd);
}

bool FileLines::next(std::string_view& line, int& number, bool& terminated) {
  for (;;) {
    if (m_p == m_end && !refill()) return false;
    const char* base = m_buf.data();
    const char* nl = static_cast<const char*>(std::memchr(base + m_p, '\n', m_end - m_p));
    if (!nl) {
      // The line goes on past what is buffered: refuse it once it is too long, without reading
      // the rest of it; otherwise read on.
      if (m_end - m_p > RecordingLimits::kMaxLineBytes) lineTooLong();
      if (!m_eof) {
        refill();
        continue;
      }
    }
    const std::size_t end = nl ? static_cast<std::size_t>(nl - base) : m_end;
    if (end - m_p > RecordingLimits::kMaxLineBytes) lineTooLong();
    if (m_control < m_consumed + end) binaryContent();  // on this line
    if (m_line == std::numeric_limits<int>::max()) {
      throw RecordingError(m_name, m_line, 0,
                           "more lines than a recording can have (" + std::to_string(m_line) +
                               "): is it the right file?");
    }
    std::string_view s(base + m_p, end - m_p);
    m_p = nl ? end + 1 : end;
    ++m_line;
    if (m_line == 1 && s.starts_with("\xEF\xBB\xBF")) s.remove_prefix(3);  // UTF-8 BOM
    if (!s.empty() && s.back() == '\r') s.remove_suffix(1);
    if (!s.empty() && s.front() == '#') continue;
    if (s.find_first_not_of(" \t") == std::string_view::npos) continue;
    line = s;
    number = m_line;
    terminated = nl != nullptr;
    return true;
  }
}

// Moves the unread tail (at most one line, kMaxLineBytes) to the front and fills the buffer
// behind it. False when nothing more could be read.
bool FileLines::refill() {
  if (m_eof) return false;
  std::memmove(m_buf.data(), m_buf.data() + m_p, m_end - m_p);
  m_consumed += m_p;
  m_end -= m_p;
  m_p = 0;
  return read(m_buf.size() - m_end) > 0;
}

// Reads up to want bytes after m_end (fewer only at the end of the file) and looks for the
// first control byte among them. Returns the bytes read.
std::size_t FileLines::read(std::size_t want) {
  std::size_t got = 0;
  while (got < want) {
    const ssize_t n = ::read(m_fd, m_buf.data() + m_end + got, want - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw RecordingError(m_name, 0, 0, "cannot read file: " + osReason(errno));
    if (n == 0) {
      m_eof = true;
      break;
    }
    got += static_cast<std::size_t>(n);
  }
  if (m_control == kNone) {
    const std::size_t at = findControl(m_buf.data() + m_end, got);
    if (at < got) m_control = m_consumed + m_end + at;
  }
  m_end += got;
  if (m_consumed + m_end > RecordingLimits::kMaxFileBytes) tooLarge(m_consumed + m_end);
  return got;
}

// The first control byte (m_control: buffered, at or after m_p) as an error naming its line and
// column (the field, counting commas as a row does).
void FileLines::binaryContent() const {
  const auto at = static_cast<std::size_t>(m_control - m_consumed);
  int line = m_line + 1;
  int column = 1;
  for (std::size_t i = m_p; i < at; ++i) {
    if (m_buf[i] == '\n') {
      ++line;
      column = 1;
    } else if (m_buf[i] == ',') {
      ++column;
    }
  }
  char byte[8];
  std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(m_buf[at]));
  if (m_control < RecordingLimits::kSniffBytes) {
    throw RecordingError(m_name, line, column,
                         std::string("binary content (byte ") + byte +
                             "): not a recording CSV (is it the right file?)");
  }
  throw RecordingError(m_name, line, column,
                       std::string("binary content (byte ") + byte + " at byte " +
                           std::to_string(m_control) +
                           " of the file): a recording CSV is text; the file is damaged from "
                           "here on, or is not a recording (is it the right file?)");
}

void FileLines::lineTooLong() const {
  // A control byte among the line's first bytes says more than its length.
  if (m_control <= m_consumed + m_p + RecordingLimits::kMaxLineBytes) binaryContent();
  throw RecordingError(
      m_name, m_line + 1, 0,
      "line longer than " + std::to_string(RecordingLimits::kMaxLineBytes) +
          " bytes (a recording's rows are under 1 KiB): not a recording CSV, or a damaged one "
          "(is it the right file?)");
}

void FileLines::tooLarge(std::uint64_t bytes) const {
  throw RecordingError(
      m_name, 0, 0,
      "the file is " + std::to_string(bytes) + " bytes, more than a recording can be (" +
          std::to_string(RecordingLimits::kMaxFileBytes >> 30) +
          " GiB; 12 h at 1 kHz with every column is about 20 GB): is it the right file?");
}

}  // namespace armtrack::recording_detail
