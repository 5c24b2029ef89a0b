// The one exception type of the storage service, with a kind so callers (the CLI, the GUI) can
// tell a wrong password from a corrupt file without parsing text.
#pragma once

#include <stdexcept>
#include <string>

namespace armtrack::storage {

/// What went wrong. The message (what()) is meant for the user and says what to do; it never
/// holds patient data other than the identifiers the caller passed in.
class StorageError : public std::runtime_error {
 public:
  enum class Kind {
    Usage,           ///< a bad argument: unknown role, malformed URL, empty name
    NotFound,        ///< no such database file, patient, session, user or protocol
    Exists,          ///< a unique name or code already taken
    Unsupported,     ///< e.g. a PostgreSQL URL before that engine is wired in
    Corrupt,         ///< not a database, failed integrity check, damaged chunk
    NewerSchema,     ///< written by a newer ArmTrack
    OlderSchema,     ///< needs `db migrate`
    Authentication,  ///< wrong user name or password, or throttled after repeated failures
    AccessDenied,    ///< the signed-in account may not do this
    Io,              ///< the engine refused a statement, the disk is full, the file is locked
  };

  StorageError(Kind kind, const std::string& message) : std::runtime_error(message), m_kind(kind) {}
  Kind kind() const { return m_kind; }

 private:
  Kind m_kind;
};

}  // namespace armtrack::storage
