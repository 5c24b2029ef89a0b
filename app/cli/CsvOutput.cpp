#include "app/cli/CsvOutput.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include "core/io/Recording.h"

namespace armtrack::cli {

namespace {

constexpr std::size_t kFlushBytes = std::size_t{1} << 20;

void checkOne(const std::filesystem::path& target, bool overwrite, const char* what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const std::string name = target.string();
  const fs::file_status st = fs::status(target, ec);
  if (fs::is_directory(st))
    throw std::runtime_error(name + ": is a directory; give a file name for the " + what);
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(folder, ec))
    throw std::runtime_error(name + ": the folder " + folder.string() + " does not exist");
  if (!fs::exists(fs::symlink_status(target, ec))) return;
  // A recording in progress holds a lock on its file (RecordingWriter): say so first, since
  // replacing the file would leave that recording writing into a file that has no name.
  if (const int fd = ::open(target.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK); fd >= 0) {
    const bool locked = ::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    ::close(fd);
    if (locked)
      throw std::runtime_error(name +
                               ": another recording is being written to this file; it cannot be "
                               "replaced until that recording ends");
  }
  if (!overwrite)
    throw std::runtime_error(name + ": exists; pass --overwrite to replace it, or choose another " +
                             "file name for the " + what);
}

}  // namespace

void checkOutputPath(const std::filesystem::path& target, bool overwrite, bool recording) {
  if (!recording) {
    checkOne(target, overwrite, "output");
    return;
  }
  const std::filesystem::path json = armtrack::sidecarPath(target);
  if (json == target)
    throw std::runtime_error(target.string() +
                             ": a recording's name must not end in .json, the extension of its "
                             "sidecar; use e.g. .csv");
  checkOne(target, overwrite, "recording");
  checkOne(json, overwrite, "recording's sidecar");
}

bool takeOverwriteFlag(std::vector<std::string>& args) {
  const auto end = std::remove(args.begin(), args.end(), std::string("--overwrite"));
  const bool found = end != args.end();
  args.erase(end, args.end());
  return found;
}

std::optional<std::string> rawOptionValue(const std::vector<std::string>& args,
                                          std::string_view name) {
  std::optional<std::string> value;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == name && i + 1 < args.size()) {
      value = args[++i];
    } else if (a.size() > name.size() && a.starts_with(name) && a[name.size()] == '=') {
      value = a.substr(name.size() + 1);
    }
  }
  return value;
}

CsvOutput::CsvOutput(std::string header, std::optional<std::filesystem::path> target,
                     std::ostream* out)
    : m_out(out),
      m_target(std::move(target)),
      m_columns(1 + static_cast<int>(std::count(header.begin(), header.end(), ','))) {
  if (m_target) {
    guarded([&] { m_file.emplace(*m_target); });
  } else if (!m_out) {
    throw std::invalid_argument("CsvOutput: neither a target file nor an output stream");
  }
  m_buf.reserve(kFlushBytes + 256);
  m_buf = std::move(header);
  m_buf += '\n';
}

CsvOutput::~CsvOutput() = default;  // an uncommitted file's temporary file goes with m_file

void CsvOutput::row(double t, const double* values, int n) {
  char num[32];
  m_buf.append(num, std::to_chars(num, num + sizeof num, t).ptr);
  for (int k = 0; k < n; ++k) {
    m_buf += ',';
    if (std::isfinite(values[k]))  // a value the data cannot give is an empty cell
      m_buf.append(num, std::to_chars(num, num + sizeof num, values[k]).ptr);
  }
  m_buf += '\n';
  if (m_buf.size() >= kFlushBytes) flush();
}

void CsvOutput::flush() {
  if (m_buf.empty()) return;
  if (m_file) {
    guarded([&] { m_file->write(m_buf); });
  } else {
    m_out->write(m_buf.data(), static_cast<std::streamsize>(m_buf.size()));
  }
  m_buf.clear();
}

void CsvOutput::commit() {
  flush();
  if (!m_file) {
    m_out->flush();
    if (!*m_out) throw std::runtime_error("writing to standard output failed");
    return;
  }
  guarded([&] { m_file->commit(); });
}

}  // namespace armtrack::cli
