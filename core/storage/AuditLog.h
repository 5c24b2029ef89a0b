// The audit log's one writer and its hash chain: every entry of the clinical records' audit log
// goes through appendAudit, which links it to the entry before by a SHA-256 hash, and
// verifyAuditChain finds the first entry that no longer fits (docs/storage.md, "Audit log").
#pragma once

#include <QByteArray>
#include <QString>
#include <optional>

#include "core/storage/Database.h"

namespace armtrack::storage {

/// What one audit entry says. Identifiers only (codes, ids, account names), never clinical text.
struct AuditEvent {
  QString userName;    ///< the account acting, or "system"
  QString action;      ///< e.g. "create", "update", "delete", "export", "sign-in-failed"
  QString objectType;  ///< "patient", "session", "user", "protocol", "database"
  QString objectId;    ///< the code, id or name
  QString detail;
};

/// Appends event to the audit log, stamped now (utcNow()), as the entry after the newest one:
/// its id is the newest id + 1, prev_hash the newest entry's hash, hash auditEntryHash() of both.
/// Concurrent writers take turns (SQLite: the write transaction, BEGIN IMMEDIATE; PostgreSQL: a
/// transaction-scoped advisory lock taken before the newest entry is read), so the chain never
/// forks. Inside a transaction of db it joins that transaction, and on PostgreSQL the lock is
/// then held until that transaction ends: append last in a long transaction. Otherwise it runs
/// in one of its own. Throws StorageError as Database::exec.
void appendAudit(Database& db, const AuditEvent& event);

/// prev_hash of the first entry: 64 zeros.
QString auditGenesisHash();

/// One stored entry as the chain sees it.
struct ChainedAuditEntry {
  qint64 id = 0;
  QString at, userName, action, objectType, objectId, detail;
  QString prevHash;  ///< the previous entry's hash (lower-case hex)
  QString hash;      ///< this entry's hash (lower-case hex)
};

/// SHA-256, lower-case hex, over "armtrack-audit-v1", the id (decimal), at, user name, action,
/// object type, object id, detail and prevHash, each as its UTF-8 bytes preceded by their count
/// (4 bytes, big-endian): no two different entries encode alike. e.hash is not read.
QString auditEntryHash(const ChainedAuditEntry& e);

/// A link of the chain as a clinic keeps it elsewhere: an entry's id and hash ("ID:HASH").
struct AuditAnchor {
  qint64 id = 0;
  QString hash;
  /// Parses "ID:HASH" (HASH: 64 hex digits); nullopt when text is not that.
  static std::optional<AuditAnchor> parse(const QString& text);
  QString text() const;  ///< "ID:HASH"
};

/// What verifyAuditChain found.
struct AuditChainReport {
  qint64 entries = 0;
  std::optional<AuditAnchor> newest;  ///< the newest entry's id and stored hash (none: empty log)
  /// The first broken link: the entry where the chain stops fitting (0: none) and what is wrong,
  /// one line ("entry 7 was edited: its content does not match its hash").
  qint64 brokenAt = 0;
  QString problem;
  qint64 brokenLinks = 0;  ///< how many entries do not fit (the first and any after it)
  /// The anchor given back (expect), when it does not match: what that says (empty: it matched
  /// or none was given).
  QString anchorProblem;
  /// When the triggers that keep the table append-only are missing or disabled: which (empty:
  /// all there).
  QString guardProblem;
  bool intact() const { return brokenAt == 0 && anchorProblem.isEmpty() && guardProblem.isEmpty(); }
};

/// Reads the whole audit log in id order (a bounded number of rows at a time) and checks every
/// link: each entry's hash over its content and prev_hash, and that prev_hash is the hash of the
/// entry before (the first: auditGenesisHash()). A broken link is told as edited (its content
/// does not match its hash), deleted (its hash fits but its prev_hash is not the previous
/// entry's: entries between are gone, or the one before was rewritten) or inserted (neither
/// fits, or it has no hash). With expect, also that the entry expect.id still exists with that
/// hash: a rewritten or cut-off tail, which no broken link shows, fails that. Also that the
/// append-only triggers are there and enabled (someone who drops them has one step less to take
/// next time, and ArmTrack never drops them). No access rule:
/// callers decide (ClinicalStore::verifyAuditLog). Throws StorageError(Io).
AuditChainReport verifyAuditChain(Database& db, const std::optional<AuditAnchor>& expect = {});

/// Migration step 6's part for the audit log, in its transaction: chains the existing entries in
/// id order (they get prev_hash and hash), then makes the table append-only with triggers that
/// refuse UPDATE and DELETE (SQLite: RAISE(ABORT); PostgreSQL: a plpgsql function, TRUNCATE
/// refused too).
void chainAuditLogAndMakeItAppendOnly(Database& db);

}  // namespace armtrack::storage
