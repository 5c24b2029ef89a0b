#include "core/io/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <random>
#include <system_error>

namespace armtrack {

namespace fs = std::filesystem;

AtomicFileError::AtomicFileError(fs::path target, const std::string& message)
    : std::runtime_error(target.string() + ": " + message),
      m_target(std::move(target)),
      m_message(message) {}

AtomicFile::AtomicFile(fs::path target) : m_target(std::move(target)) {
  std::random_device rd;
  const unsigned long long tag = (static_cast<unsigned long long>(rd()) << 32) ^ rd();
  char hex[17];
  const auto r = std::to_chars(hex, hex + 16, tag, 16);
  m_tmp = m_target;
  m_tmp.replace_filename("." + m_target.filename().string() + ".tmp-" + std::string(hex, r.ptr));
  // 0600 whatever the umask (which can only take bits away; fchmod puts them back): what ArmTrack
  // writes may be a patient's data, and the rename keeps the mode. O_EXCL | O_NOFOLLOW: never a
  // file or link someone else put there.
  errno = 0;
  const int fd = ::open(m_tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                        S_IRUSR | S_IWUSR);
  if (fd < 0) fail("cannot create temporary file \"" + m_tmp.string() + "\"", errno);
  if (::fchmod(fd, S_IRUSR | S_IWUSR) != 0 || !(m_file = ::fdopen(fd, "wb"))) {
    const int err = errno;
    ::close(fd);
    std::error_code ec;
    fs::remove(m_tmp, ec);
    fail("cannot create temporary file \"" + m_tmp.string() + "\"", err);
  }
}

AtomicFile::~AtomicFile() {
  if (m_file) std::fclose(m_file);
  if (!m_published) {
    std::error_code ec;
    fs::remove(m_tmp, ec);
  }
}

void AtomicFile::write(std::string_view data) {
  if (!m_file) fail("write after the file was finished", 0);
  errno = 0;
  if (std::fwrite(data.data(), 1, data.size(), m_file) != data.size()) fail("write failed", errno);
}

void AtomicFile::finish() {
  if (!m_file) return;
  std::FILE* f = m_file;
  m_file = nullptr;
  errno = 0;
  const bool flushed = std::fflush(f) == 0;
  const int flushErr = errno;
  // On disk before the rename: otherwise a crash soon after can leave an empty target.
  const bool synced = flushed && ::fsync(::fileno(f)) == 0;
  const int syncErr = errno;
  const bool closed = std::fclose(f) == 0;
  if (!flushed) fail("write failed", flushErr);
  if (!synced) fail("writing to disk failed", syncErr);
  if (!closed) fail("closing the file failed", errno);
}

void AtomicFile::publish() {
  finish();
  std::error_code ec;
  fs::rename(m_tmp, m_target, ec);
  if (ec) fail("cannot rename \"" + m_tmp.string() + "\" into place: " + ec.message(), 0);
  m_published = true;
  // The rename itself lives in the directory: sync it too (best effort; some file systems refuse).
  const fs::path dir = m_target.has_parent_path() ? m_target.parent_path() : fs::path(".");
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

void AtomicFile::fail(const std::string& message, int err) const {
  throw AtomicFileError(m_target,
                        err != 0 ? message + ": " + std::generic_category().message(err) : message);
}

}  // namespace armtrack
