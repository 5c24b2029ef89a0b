#include "core/storage/AuditLog.h"

namespace armtrack::storage {

void appendAudit(Database& db, const AuditEvent& e) {
  const auto insert = [&] {
    db.exec(
        "INSERT INTO audit_log (at, user_name, action, object_type, object_id, detail) "
        "VALUES (?, ?, ?, ?, ?, ?)",
        {utcNow(), e.userName, e.action, e.objectType, e.objectId, e.detail});
  };
  if (db.inTransaction())
    insert();
  else
    db.transaction(insert);
}

}  // namespace armtrack::storage
