#include "core/exports/ExportFiles.h"

#include <algorithm>
#include <charconv>
#include <system_error>

#include "core/exports/Exports.h"

namespace armtrack {

ExportError::ExportError(std::filesystem::path path, const std::string& message)
    : std::runtime_error(path.empty() ? message : path.string() + ": " + message),
      m_path(std::move(path)) {}

namespace exportdetail {

namespace fs = std::filesystem;

namespace {
constexpr std::size_t kFlushBytes = 1 << 20;
}

FileSet::~FileSet() = default;  // each AtomicFile removes its unpublished temporary file

std::size_t FileSet::add(const fs::path& target) {
  std::error_code ec;
  if (fs::is_directory(target, ec)) throw ExportError(target, "is a directory, not a file");
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec))
    throw ExportError(target, "the folder \"" + dir.string() + "\" does not exist");
  try {
    m_files.push_back({std::make_unique<AtomicFile>(target), {}});
  } catch (const AtomicFileError& e) {
    throw ExportError(target, e.message());
  }
  return m_files.size() - 1;
}

void FileSet::write(std::size_t file, std::string_view data) {
  m_files[file].buffer.append(data);
  maybeFlush(file);
}

void FileSet::maybeFlush(std::size_t file) {
  if (m_files[file].buffer.size() >= kFlushBytes) flush(file);
}

void FileSet::flush(std::size_t file) {
  Entry& e = m_files[file];
  try {
    e.file->write(e.buffer);
  } catch (const AtomicFileError& err) {
    throw ExportError(e.file->target(), err.message());
  }
  e.buffer.clear();
}

void FileSet::commit() {
  // Every file complete and on disk before the first rename, so a failure here leaves no target
  // changed.
  for (std::size_t i = 0; i < m_files.size(); ++i) {
    flush(i);
    try {
      m_files[i].file->finish();
    } catch (const AtomicFileError& err) {
      throw ExportError(m_files[i].file->target(), err.message());
    }
  }
  for (Entry& e : m_files) {
    try {
      e.file->publish();
    } catch (const AtomicFileError& err) {
      throw ExportError(e.file->target(), err.message());
    }
  }
}

void appendFixed(std::string& out, double v, int decimals) {
  char buf[400];  // room for the largest double in fixed notation
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  // A value that rounds to zero is written "0.000000", not "-0.000000".
  char* begin = buf;
  if (*begin == '-' && std::all_of(begin + 1, r.ptr, [](char c) { return c == '0' || c == '.'; }))
    ++begin;
  out.append(begin, r.ptr);
}

void appendShortest(std::string& out, double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace exportdetail
}  // namespace armtrack
