// Buffered CSV output of numeric rows for the armtrack-cli commands, written atomically to a file
// (temporary file beside the target, renamed into place on commit) or streamed to an ostream.
#pragma once

#include <cstdio>
#include <filesystem>
#include <optional>
#include <ostream>
#include <string>

namespace armtrack::cli {

/// Writes a header line and rows "t,v0,v1,..." of doubles in their shortest round-trip form.
/// With a target, rows go to a temporary file ".<name>.tmp-<random hex>" beside it that commit()
/// renames into place; without commit() the temporary file is removed. Without a target, rows go
/// to *out. Errors throw std::runtime_error naming the file.
class CsvOutput {
 public:
  /// header is the first line without its newline. out must be given when target is empty.
  CsvOutput(std::string header, std::optional<std::filesystem::path> target,
            std::ostream* out = nullptr);
  CsvOutput(const CsvOutput&) = delete;
  CsvOutput& operator=(const CsvOutput&) = delete;
  ~CsvOutput();

  /// Appends the row "t,values[0],...,values[n-1]".
  void row(double t, const double* values, int n);
  /// Writes out what is buffered and, with a target, closes the file and renames it into place.
  void commit();

 private:
  void flush();
  [[noreturn]] void fail(const std::string& message, int err) const;

  std::ostream* m_out = nullptr;
  std::optional<std::filesystem::path> m_target;
  std::filesystem::path m_tmp;
  std::FILE* m_file = nullptr;
  std::string m_buf;
  bool m_committed = false;
};

}  // namespace armtrack::cli
