#include "core/storage/NameKeys.h"

#include <QHash>
#include <QSet>
#include <vector>

#include "core/storage/AuditLog.h"
#include "core/storage/Database.h"
#include "core/storage/TextRules.h"

namespace armtrack::storage {

namespace {

struct KeyedColumn {
  const char* table;
  const char* column;      // the name or code
  const char* keyColumn;   // its nameKey()
  const char* index;       // the UNIQUE index on the key
  const char* objectType;  // as the audit log names the table's rows
};

void addKeys(Database& db, const KeyedColumn& c) {
  struct Row {
    qint64 id;
    QString name;
  };
  std::vector<Row> rows;
  QSet<QString> folded;  // every row's key as it stands: no new name may take one
  QSqlQuery q = db.exec(QString("SELECT id, %1 FROM %2 ORDER BY id").arg(c.column, c.table));
  while (q.next()) {
    rows.push_back({q.value(0).toLongLong(), q.value(1).toString()});
    folded.insert(nameKey(rows.back().name));
  }
  q.finish();
  QHash<QString, QString> given;  // key -> the name that took it
  const QString update =
      QString("UPDATE %1 SET %2 = ?, %3 = ? WHERE id = ?").arg(c.table, c.column, c.keyColumn);
  for (const Row& r : rows) {
    QString name = r.name;
    QString key = nameKey(name);
    if (given.contains(key)) {
      const QString older = given.value(key);
      for (int n = 2;; ++n) {
        name = r.name + "-" + QString::number(n);
        key = nameKey(name);
        if (!folded.contains(key) && !given.contains(key)) break;
      }
      appendAudit(db,
                  {"system", "rename", c.objectType, r.name,
                   "renamed to '" + name + "': it differed only in case from the older '" + older +
                       "', and from schema version 6 names are unique without "
                       "regard to case"});
    }
    given.insert(key, name);
    db.exec(update, {name, key, r.id});
  }
  db.exec(QString("CREATE UNIQUE INDEX %1 ON %2 (%3)").arg(c.index, c.table, c.keyColumn));
}

}  // namespace

void addNameKeys(Database& db) {
  for (const KeyedColumn& c :
       {KeyedColumn{"users", "name", "name_key", "users_by_name_key", "user"},
        KeyedColumn{"patients", "code", "code_key", "patients_by_code_key", "patient"},
        KeyedColumn{"protocols", "name", "name_key", "protocols_by_name_key", "protocol"}})
    addKeys(db, c);
}

}  // namespace armtrack::storage
