// Buffered CSV output of numeric rows for the armtrack-cli commands, written atomically to a file
// (temporary file beside the target, renamed into place on commit) or streamed to an ostream.
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/io/AtomicFile.h"

namespace armtrack::cli {

/// Refuses an output before any work is done: throws std::runtime_error naming the path when it is
/// a directory, when its folder does not exist, or when it exists and overwrite is false ("...
/// exists; pass --overwrite to replace it"). With recording, the sidecar beside it
/// (core/io/Recording.h, sidecarPath) is checked the same way, and a name whose sidecar would be
/// the file itself (ending in .json) is refused.
void checkOutputPath(const std::filesystem::path& target, bool overwrite, bool recording = false);

/// Removes every "--overwrite" from args (the words after the command name); true when there was
/// one. For commands whose own options do not list it (calibrate): the dispatcher checks the
/// output with checkOutputPath instead.
bool takeOverwriteFlag(std::vector<std::string>& args);
/// The value of "--name VALUE" or "--name=VALUE" in args (the last one), without parsing the rest.
std::optional<std::string> rawOptionValue(const std::vector<std::string>& args,
                                          std::string_view name);

/// Writes a header line and rows "t,v0,v1,..." of doubles in their shortest round-trip form.
/// With a target, rows go through an AtomicFile (core/io/AtomicFile.h): commit() puts the whole
/// file in place, without it the target is untouched. Without a target, rows go
/// to *out. Errors throw std::runtime_error naming the file.
class CsvOutput {
 public:
  /// header is the first line without its newline. out must be given when target is empty.
  CsvOutput(std::string header, std::optional<std::filesystem::path> target,
            std::ostream* out = nullptr);
  CsvOutput(const CsvOutput&) = delete;
  CsvOutput& operator=(const CsvOutput&) = delete;
  ~CsvOutput();

  /// Appends the row "t,values[0],...,values[n-1]"; a non-finite value is an empty cell.
  void row(double t, const double* values, int n);
  /// The header's number of columns.
  int columns() const { return m_columns; }
  /// Writes out what is buffered and, with a target, closes the file and renames it into place.
  void commit();

 private:
  void flush();
  /// Runs a file step; a failure becomes std::runtime_error "<target>: <what went wrong>".
  template <typename F>
  static void guarded(F&& step) {
    try {
      step();
    } catch (const AtomicFileError& e) {
      throw std::runtime_error(e.what());
    }
  }

  std::ostream* m_out = nullptr;
  std::optional<std::filesystem::path> m_target;
  std::optional<AtomicFile> m_file;
  std::string m_buf;
  int m_columns = 0;
};

}  // namespace armtrack::cli
