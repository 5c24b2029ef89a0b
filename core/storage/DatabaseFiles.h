// A SQLite database's files on disk (docs/storage.md, "Files and permissions"): which paths are
// its files, private files and folders, whether it can be written, and what an opening check
// left beside it. POSIX and Qt Core only; used by Database and by the callers that write outputs.
#pragma once

#include <QString>
#include <QStringList>
#include <optional>

namespace armtrack::storage {

/// The name of the file that writing to `path` would write over when it is the SQLite database
/// at dbPath or one of its companions (dbPath-wal, -shm, -journal), else an empty string.
/// Compared by identity, not by spelling: symbolic links are followed (also a dangling one), a
/// hard link or a path through ".." is the same device and inode, and a companion that does not
/// exist yet is matched by its folder's device and inode and its name. The companions beside
/// dbPath as given and beside the file it resolves to both count.
QString sqliteFileAt(const QString& dbPath, const QString& path);

/// Creates path as a new, empty file with mode 0600 whatever the umask. Never follows a symbolic
/// link and never opens an existing file (O_EXCL). Returns an empty string, or the operating
/// system's reason (e.g. "File exists").
QString createPrivateFile(const QString& path);

/// Creates folder and every missing folder above it with mode 0700 whatever the umask; folders
/// that exist are left as they are. Returns an empty string, or why not (naming the folder that
/// cannot be made and what to do).
QString makePrivateFolders(const QString& folder);

/// ArmTrack's own data folder (QStandardPaths::AppDataLocation, on Linux
/// ~/.local/share/ArmTrack/ArmTrack), made as makePrivateFolders does. When it exists already and
/// belongs to this user, it and the organisation folder above it (named after
/// QCoreApplication::organizationName()) are tightened to 0700. Throws StorageError(Io) when
/// there is no such folder on this system or it cannot be made.
QString privateAppDataFolder();

/// Why the SQLite database at dbPath cannot be written by this process, or an empty string when
/// it can: the file itself is not writable, or its folder is not and the -wal and -shm SQLite
/// would need there are missing or not writable (it creates them to write, and to read a
/// database in WAL mode without the immutable flag). Names the path and the system's reason.
QString sqliteReadOnlyReason(const QString& dbPath);

/// The companions (-wal, -shm) of dbPath that do not exist now: what a check about to open the
/// database may create and should remove again (removeCheckLeftovers).
QStringList missingCompanions(const QString& dbPath);
/// Removes what a read-only connection to dbPath created (created: from missingCompanions before
/// it opened) once it has closed, while no other connection uses the database: the -wal when it
/// is empty, and the -shm (the index of that log, which SQLite fills in) when the -wal is gone or
/// empty. "No other connection" is SQLite's own test: a write lock on the -shm's DMS byte, held
/// while removing, which every connection to a WAL database holds a read lock on. Anything else,
/// and every file that was there before, is left alone. Call it only when this process has no
/// connection of its own to the file.
void removeCheckLeftovers(const QString& dbPath, const QStringList& created);

/// SQLite URI for opening dbPath with the immutable flag and read-only mode (file:/abs/path with
/// '%', '?' and '#' escaped, then ?mode=ro&immutable=1).
QString immutableUri(const QString& dbPath);

}  // namespace armtrack::storage
