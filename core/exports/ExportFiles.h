// Internal helpers of the export writers (not part of the public API): a set of files written all
// or nothing, and number formatting that does not depend on the C locale.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/AtomicFile.h"

namespace armtrack::exportdetail {

/// Files of one export. add() opens a hidden temporary file beside each target (failing at once,
/// with an ExportError naming the target, when its folder is missing or not writable, or when the
/// target is a directory); write() streams into it through a buffer; commit() completes every
/// file and only then renames them into place. Destroyed without commit(), it removes every
/// temporary file and leaves the targets as they were.
class FileSet {
 public:
  FileSet() = default;
  FileSet(const FileSet&) = delete;
  FileSet& operator=(const FileSet&) = delete;
  ~FileSet();

  std::size_t add(const std::filesystem::path& target);
  void write(std::size_t file, std::string_view data);
  /// Buffer of a file, to append to; flushed by maybeFlush() and commit().
  std::string& buffer(std::size_t file) { return m_files[file].buffer; }
  void maybeFlush(std::size_t file);
  void commit();

 private:
  struct Entry {
    std::unique_ptr<AtomicFile> file;
    std::string buffer;
  };
  void flush(std::size_t file);
  std::vector<Entry> m_files;
};

/// Appends v with a fixed number of decimals ("nan"-free: callers handle non-finite values).
void appendFixed(std::string& out, double v, int decimals);
/// Appends v in the shortest form that reads back to the same double.
void appendShortest(std::string& out, double v);

}  // namespace armtrack::exportdetail
