// The audit log's one writer: every entry of the clinical records' audit log goes through
// appendAudit (docs/storage.md, "Audit log").
#pragma once

#include <QString>

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

/// Appends event to the audit log, stamped now (utcNow()). Inside a transaction of db it joins
/// that transaction; otherwise it runs in one of its own. Throws StorageError as Database::exec.
void appendAudit(Database& db, const AuditEvent& event);

}  // namespace armtrack::storage
