// Checks at the door of the recording reader (issue 24, item 8): what is not a regular file, a
// file too large to be a recording, binary content (a sparse file's holes read as NULs), control
// bytes anywhere, over-long lines, and a sidecar that is not a small regular file. Each is refused
// with the file, line and column, having read little: the bytes this process read are counted by
// the kernel (/proc/self/io), not by the reader.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>

#include "core/io/Recording.h"
#include "tests/core/io/RecordingTestSupport.h"

namespace armtrack {
namespace {

using namespace armtrack::recording_test;

/// Bytes this process has read so far through read() and its kin (the "rchar" of
/// /proc/self/io), or nothing where the kernel does not say.
std::optional<std::uint64_t> processBytesRead() {
  std::ifstream in("/proc/self/io");
  std::string key;
  std::uint64_t value = 0;
  while (in >> key >> value) {
    if (key == "rchar:") return value;
  }
  return std::nullopt;
}

/// Runs f and returns what the process read meanwhile (bytes), with the error f threw.
struct Attempt {
  RecordingError error;
  std::uint64_t bytesRead;
};
Attempt attempt(const std::function<void()>& f) {
  const auto before = processBytesRead();
  RecordingError e = errorOf(f);
  const auto after = processBytesRead();
  return {e, before && after ? *after - *before : 0};
}

/// A file of size bytes whose first bytes are text and whose rest is a hole (reads as NULs, takes
/// no disk space).
fs::path sparseFile(const fs::path& p, const std::string& text, std::uintmax_t size) {
  {
    std::ofstream out(p, std::ios::binary);
    out << text;
  }
  fs::resize_file(p, size);
  return p;
}

/// Rows of a valid recording with the kImuHeader columns, from time index first on.
std::string imuRows(int first, int count) {
  std::string s;
  for (int i = first; i < first + count; ++i)
    s += std::to_string(i) + "e-3,0.01,-0.02,0.003,9.79,0.12,-0.05\n";
  return s;
}

/// Runs f on a thread of its own and waits for it. Should f block (a reader waiting on a FIFO
/// for data that never comes), the test fails after 20 s and unblock() is called so that f can
/// return; a watchdog, not a measurement.
RecordingError errorWithoutBlocking(const std::function<void()>& f,
                                    const std::function<void()>& unblock) {
  auto result = std::async(std::launch::async, [&] { return errorOf(f); });
  if (result.wait_for(std::chrono::seconds(20)) != std::future_status::ready)
    ADD_FAILURE() << "the reader blocked";
  unblock();
  return result.get();
}

// ---------------------------------------------------------------------------------------------
// Not a regular file

TEST_F(RecordingTest, FifoIsRefusedWithoutWaitingForAWriter) {
  const fs::path p = m_dir / "rec.csv";
  ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
  // Hold the FIFO open for writing, so that a reader that opens it does not block in open() but
  // waits for data; closing it ends that wait.
  int writer = ::open(p.c_str(), O_RDWR | O_NONBLOCK);
  ASSERT_GE(writer, 0);
  const RecordingError e =
      errorWithoutBlocking([&] { RecordingReader reader(p); }, [&] { ::close(writer); });
  expectError(e, p, 0, 0, "a FIFO (named pipe), not a regular file");
}

TEST_F(RecordingTest, DeviceAndDirectoryAreRefusedNamingWhatTheyAre) {
  expectError(readError("/dev/null"), "/dev/null", 0, 0, "a character device, not a regular file");
  const fs::path d = m_dir / "folder.csv";
  fs::create_directory(d);
  expectError(readError(d), d, 0, 0, "a directory, not a regular file");
}

TEST_F(RecordingTest, SidecarThatIsAFifoOrTooLargeIsRefused) {
  const fs::path csv = writeText("rec.csv", kImuHeader + imuRows(0, 3));
  const fs::path json = m_dir / "rec.json";
  ASSERT_EQ(::mkfifo(json.c_str(), 0600), 0);
  int writer = ::open(json.c_str(), O_RDWR | O_NONBLOCK);
  ASSERT_GE(writer, 0);
  const RecordingError e =
      errorWithoutBlocking([&] { RecordingReader reader(csv); }, [&] { ::close(writer); });
  expectError(e, json, 0, 0, "a FIFO (named pipe), not a regular file");

  // Valid JSON padded past the limit: refused by its size, before it is read.
  fs::remove(json);
  writeText("rec.json", std::string(RecordingLimits::kMaxSidecarBytes, ' ') +
                            R"({"format": "armtrack-recording", "version": 1})");
  const Attempt big = attempt([&] { RecordingReader reader(csv); });
  expectError(big.error, json, 0, 0, "more than a sidecar can be");
  EXPECT_LT(big.bytesRead, RecordingLimits::kMaxSidecarBytes);
}

// ---------------------------------------------------------------------------------------------
// Size and binary content, before parsing

TEST_F(RecordingTest, FileLargerThanTheLimitIsRefusedUnread) {
  const fs::path p = sparseFile(m_dir / "rec.csv", kImuHeader + imuRows(0, 10),
                                RecordingLimits::kMaxFileBytes + 1);
  const Attempt a = attempt([&] { RecordingReader reader(p); });
  expectError(a.error, p, 0, 0, "more than a recording can be");
  EXPECT_NE(a.error.message().find(std::to_string(RecordingLimits::kMaxFileBytes + 1)),
            std::string::npos)
      << a.error.message();
  EXPECT_LT(a.bytesRead, 4096u);
}

TEST_F(RecordingTest, SparseFileIsRefusedAtOnceAsBinary) {
  // What `truncate -s 2G f.csv` makes: 2 GB of holes.
  const fs::path p = sparseFile(m_dir / "f.csv", "", std::uintmax_t{2} << 30);
  const Attempt a = attempt([&] { RecordingReader reader(p); });
  expectError(a.error, p, 1, 1, "binary content (byte 0x00): not a recording CSV");
  EXPECT_STREQ(a.error.what(),
               (p.string() + ":1:1: binary content (byte 0x00): not a recording CSV (is it the "
                             "right file?)")
                   .c_str());
  std::cout << "2 GB sparse file: refused having read " << a.bytesRead << " bytes\n";
  EXPECT_LT(a.bytesRead, 1000000u);
}

TEST_F(RecordingTest, ValidHeaderThenNulsIsRefusedAtOnce) {
  const std::string head = "# comment\n" + kImuHeader;
  const fs::path p = sparseFile(m_dir / "rec.csv", head, head.size() + (std::uintmax_t{100} << 20));
  const Attempt a = attempt([&] { RecordingReader reader(p); });
  expectError(a.error, p, 3, 1, "binary content (byte 0x00)");
  std::cout << "header + 100 MB of NULs: refused having read " << a.bytesRead << " bytes\n";
  EXPECT_LT(a.bytesRead, 1000000u);
}

TEST_F(RecordingTest, NulsDeepInTheFileAreRefusedAtTheirLine) {
  // 2 MB of valid rows (past the first look), then 100 MB of holes.
  const std::string rows = imuRows(0, 50000);
  const std::string text = kImuHeader + rows;
  const fs::path p = sparseFile(m_dir / "rec.csv", text, text.size() + (std::uintmax_t{100} << 20));
  const auto before = processBytesRead();
  RecordingReader reader(p);
  ArmSample s;
  std::uint64_t rowsRead = 0;
  const RecordingError e = errorOf([&] {
    while (reader.next(s)) ++rowsRead;
  });
  const auto after = processBytesRead();
  // Line 1 is the header, 2..50001 the rows, 50002 the first line of NULs.
  expectError(e, p, 50002, 1, "binary content (byte 0x00 at byte " + std::to_string(text.size()));
  EXPECT_EQ(rowsRead, 50000u);
  EXPECT_EQ(reader.rows(), 50000u);
  ASSERT_TRUE(before && after);
  std::cout << "2 MB of rows + 100 MB of NULs: refused having read " << *after - *before
            << " bytes\n";
  EXPECT_LT(*after - *before, text.size() + (std::uint64_t{2} << 20));
}

TEST_F(RecordingTest, ControlByteAnywhereIsRefusedNamingLineAndColumn) {
  // Past the first 64 KiB, in the third cell of line 5002 (a 0x01 where a digit was).
  std::string text = kImuHeader + imuRows(0, 6000);
  std::size_t at = 0;
  for (int line = 1; line < 5002; ++line) at = text.find('\n', at) + 1;
  ASSERT_GT(at, RecordingLimits::kSniffBytes);
  const std::size_t cell = text.find(',', text.find(',', at) + 1) + 1;  // third field
  text[cell + 1] = '\x01';
  const fs::path p = writeCsv(text);
  expectError(readError(p), p, 5002, 3,
              "binary content (byte 0x01 at byte " + std::to_string(cell + 1));
  // In a comment too, and a DEL.
  const fs::path q = writeCsv("# made by \x7f\n" + kImuHeader + imuRows(0, 3));
  expectError(readError(q), q, 1, 1, "binary content (byte 0x7f)");
  // Tabs, CRLF line ends, a BOM and UTF-8 in comments are text.
  const fs::path ok = writeCsv(
      "\xEF\xBB\xBF# Patientin J\xC3\xBCrgens\r\nt,\tua_gx,ua_gy,ua_gz,ua_ax,"
      "ua_ay,ua_az\r\n0,\t1,2,3,4,5,6\r\n");
  EXPECT_EQ(readRecording(ok).samples.size(), 1u);
}

TEST_F(RecordingTest, EveryControlByteAndOnlyThoseIsBinary) {
  // Each byte value in a comment, past the first 64-byte block the scan tests at once.
  for (int b = 0; b < 256; ++b) {
    if (b == '\n') continue;
    std::string comment = "# " + std::string(100, 'x');
    comment[70] = static_cast<char>(b);
    const fs::path p = writeCsv(comment + "\n" + kImuHeader + imuRows(0, 2));
    const bool control = (b < 0x20 && b != '\t' && b != '\r') || b == 0x7f;
    if (control) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", b);
      expectError(readError(p), p, 1, 1, std::string("binary content (byte ") + hex + ")");
    } else {
      EXPECT_EQ(readRecording(p).samples.size(), 2u) << "byte " << b;
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Line length

TEST_F(RecordingTest, OverLongLineIsRefusedAtItsLine) {
  const std::string text =
      kImuHeader + imuRows(0, 2) + std::string(100000, '7') + "\n" + imuRows(2, 3);
  const fs::path p = writeCsv(text);
  RecordingReader reader(p);
  ArmSample s;
  EXPECT_TRUE(reader.next(s));
  EXPECT_TRUE(reader.next(s));
  const RecordingError e = errorOf([&] { reader.next(s); });
  expectError(e, p, 4, 0, "line longer than 65536 bytes");
  // A line exactly at the limit is only a bad row.
  const fs::path q = writeCsv(kImuHeader + std::string(RecordingLimits::kMaxLineBytes, '7') + "\n");
  expectError(readError(q), q, 2, 2, "row has 1 fields");
}

TEST_F(RecordingTest, OverLongLastLineIsRefusedWithoutBufferingIt) {
  // 20 MB of digits and no newline: once seen as a last line cut short and dropped, after
  // buffering all of it.
  const std::string head = kImuHeader + imuRows(0, 5);
  const fs::path p = writeCsv(head + std::string(std::size_t{20} << 20, '7'));
  const Attempt a = attempt([&] { readRecording(p); });
  expectError(a.error, p, 7, 0, "line longer than 65536 bytes");
  std::cout << "20 MB line: refused having read " << a.bytesRead << " bytes\n";
  EXPECT_LT(a.bytesRead, std::uint64_t{2} << 20);
}

}  // namespace
}  // namespace armtrack
