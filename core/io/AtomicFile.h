// Files written all or nothing: a reader (or the next start after a crash or power loss) sees
// either the old file or the whole new one, never a half-written one.
#pragma once

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace armtrack {

/// A failed AtomicFile step. message() says what went wrong without the file name, so callers
/// can report it in their own error type; what() is "<target>: <message>".
class AtomicFileError : public std::runtime_error {
 public:
  AtomicFileError(std::filesystem::path target, const std::string& message);
  const std::filesystem::path& target() const { return m_target; }
  const std::string& message() const { return m_message; }

 private:
  std::filesystem::path m_target;
  std::string m_message;
};

/// Writes into a hidden temporary file beside the target (".<name>.tmp-<random hex>"), created
/// with mode 0600 whatever the umask, so the published file is readable by its owner only
/// (docs/storage.md, "Files and permissions"). finish()
/// flushes it, forces it to disk (fsync) and closes it; publish() renames it over the target and
/// forces the directory entry to disk. Destroyed before publish(), it removes the temporary file.
/// Every failure throws AtomicFileError, with the operating system's reason.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();

  void write(std::string_view data);
  void finish();
  void publish();
  /// finish() then publish().
  void commit() {
    finish();
    publish();
  }

  const std::filesystem::path& target() const { return m_target; }
  const std::filesystem::path& temporary() const { return m_tmp; }

 private:
  [[noreturn]] void fail(const std::string& message, int err) const;

  std::filesystem::path m_target;
  std::filesystem::path m_tmp;
  std::FILE* m_file = nullptr;
  bool m_published = false;
};

}  // namespace armtrack
