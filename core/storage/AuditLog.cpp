#include "core/storage/AuditLog.h"

#include <QCryptographicHash>
#include <QRegularExpression>
#include <QSqlQuery>
#include <QStringList>
#include <vector>

namespace armtrack::storage {

namespace {

// The advisory lock appenders take on PostgreSQL (the migrations take 7261540).
constexpr const char* kAuditLockSql = "SELECT pg_advisory_xact_lock(7261541)";
// Rows read (verifying) or rewritten (chaining in the migration) at a time.
constexpr int kBatchRows = 1000;
const QString kColumns =
    "id, at, user_name, action, object_type, object_id, detail, prev_hash, hash";

// Text as the database gives it back: through UTF-8 once (a lone surrogate becomes U+FFFD on
// the way in), so the hash of what is stored is the hash computed here.
QString asStored(const QString& s) {
  return QString::fromUtf8(s.toUtf8());
}

ChainedAuditEntry entryFrom(const QSqlQuery& q) {
  ChainedAuditEntry e;
  e.id = q.value(0).toLongLong();
  e.at = q.value(1).toString();
  e.userName = q.value(2).toString();
  e.action = q.value(3).toString();
  e.objectType = q.value(4).toString();
  e.objectId = q.value(5).toString();
  e.detail = q.value(6).toString();
  e.prevHash = q.value(7).toString();
  e.hash = q.value(8).toString();
  return e;
}

// The next entries after id `after` (none: from the first), in id order, at most kBatchRows.
std::vector<ChainedAuditEntry> entriesAfter(Database& db, std::optional<qint64> after) {
  std::vector<ChainedAuditEntry> batch;
  const QString limit = " ORDER BY id LIMIT " + QString::number(kBatchRows);
  QSqlQuery q =
      after ? db.exec("SELECT " + kColumns + " FROM audit_log WHERE id > ?" + limit, {*after})
            : db.exec("SELECT " + kColumns + " FROM audit_log" + limit);
  while (q.next()) batch.push_back(entryFrom(q));
  return batch;
}

bool isHash(const QString& s) {
  static const QRegularExpression hex("^[0-9a-f]{64}$");
  return hex.match(s).hasMatch();
}

// What is wrong with entry e, which does not fit after the entry before it (previous: its id;
// none for the first entry).
QString describeBreak(const ChainedAuditEntry& e, std::optional<qint64> previousId, bool prevFits,
                      bool ownFits) {
  const QString entry = "entry " + QString::number(e.id);
  if (e.hash.isEmpty())
    return entry +
           " was inserted: it has no hash, so ArmTrack did not write it (a row added by hand, or "
           "by a program older than schema 6)";
  if (!ownFits && prevFits)
    return entry + " was edited (or written in by hand): its content does not match its hash";
  if (!ownFits)
    return entry +
           " was inserted or replaced: neither its previous hash nor its own hash fits the chain";
  if (!previousId)
    return entry +
           " is the first entry but does not start the chain: the entries before it were "
           "deleted";
  const qint64 previous = *previousId;
  QString why = entry + " does not follow entry " + QString::number(previous) +
                ": its previous hash is not entry " + QString::number(previous) + "'s hash";
  if (e.id - previous > 1)
    return why + ": entr" + (e.id - previous > 2 ? "ies " : "y ") + QString::number(previous + 1) +
           (e.id - previous > 2 ? " to " + QString::number(e.id - 1) + " were" : " was") +
           " deleted";
  return why + ": entries between them were deleted, or entry " + QString::number(previous) +
         " was rewritten with a new hash";
}

// The append-only triggers chainAuditLogAndMakeItAppendOnly creates, by engine.
QStringList guardTriggers(const Database& db) {
  return db.isPostgres() ? QStringList{"audit_log_no_change", "audit_log_no_truncate"}
                         : QStringList{"audit_log_no_update", "audit_log_no_delete"};
}

// Which of the append-only triggers are missing or disabled (PostgreSQL's owner can disable
// them without dropping them); empty when all are in force.
QStringList missingGuards(Database& db) {
  QStringList present;
  QSqlQuery q =
      db.isPostgres()
          ? db.exec(
                "SELECT tgname FROM pg_trigger WHERE tgrelid = 'audit_log'::regclass AND NOT "
                "tgisinternal AND tgenabled <> 'D'")
          : db.exec(
                "SELECT name FROM sqlite_master WHERE type = 'trigger' AND tbl_name = "
                "'audit_log'");
  while (q.next()) present << q.value(0).toString();
  QStringList missing;
  for (const QString& name : guardTriggers(db))
    if (!present.contains(name)) missing << name;
  return missing;
}

}  // namespace

QString auditGenesisHash() {
  return QString(64, QChar('0'));
}

QString auditEntryHash(const ChainedAuditEntry& e) {
  QCryptographicHash h(QCryptographicHash::Sha256);
  const auto field = [&](const QByteArray& utf8) {
    const auto n = static_cast<quint32>(utf8.size());
    const char length[4] = {static_cast<char>(n >> 24), static_cast<char>((n >> 16) & 0xff),
                            static_cast<char>((n >> 8) & 0xff), static_cast<char>(n & 0xff)};
    h.addData(QByteArrayView(length, 4));
    h.addData(utf8);
  };
  field("armtrack-audit-v1");
  field(QByteArray::number(e.id));
  for (const QString* s :
       {&e.at, &e.userName, &e.action, &e.objectType, &e.objectId, &e.detail, &e.prevHash})
    field(s->toUtf8());
  return QString::fromLatin1(h.result().toHex());
}

void appendAudit(Database& db, const AuditEvent& event) {
  const auto append = [&] {
    // PostgreSQL: one appender at a time from here to its commit, so the entry read below is
    // still the newest when this one is inserted (READ COMMITTED: each statement sees what was
    // committed before it began). SQLite: the transaction holds the write lock already.
    if (db.isPostgres()) db.exec(kAuditLockSql);
    ChainedAuditEntry e;
    e.id = 1;
    e.prevHash = auditGenesisHash();
    {
      QSqlQuery last = db.exec("SELECT id, hash FROM audit_log ORDER BY id DESC LIMIT 1");
      if (last.next()) {
        e.id = last.value(0).toLongLong() + 1;
        e.prevHash = last.value(1).toString();
      }
    }
    e.at = utcNow();
    e.userName = asStored(event.userName);
    e.action = asStored(event.action);
    e.objectType = asStored(event.objectType);
    e.objectId = asStored(event.objectId);
    e.detail = asStored(event.detail);
    e.hash = auditEntryHash(e);
    db.exec(
        "INSERT INTO audit_log (" + kColumns + ") VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
        {e.id, e.at, e.userName, e.action, e.objectType, e.objectId, e.detail, e.prevHash, e.hash});
  };
  if (db.inTransaction())
    append();
  else
    db.transaction(append);
}

std::optional<AuditAnchor> AuditAnchor::parse(const QString& text) {
  const qsizetype colon = text.indexOf(':');
  if (colon <= 0) return std::nullopt;
  bool ok = false;
  const qint64 id = text.left(colon).toLongLong(&ok);
  const QString hash = text.mid(colon + 1).toLower();
  if (!ok || id <= 0 || !isHash(hash)) return std::nullopt;
  return AuditAnchor{id, hash};
}

QString AuditAnchor::text() const {
  return QString::number(id) + ":" + hash;
}

AuditChainReport verifyAuditChain(Database& db, const std::optional<AuditAnchor>& expect) {
  AuditChainReport report;
  QString expectedPrev = auditGenesisHash();
  std::optional<qint64> previous;
  std::optional<QString> anchorHash;  // the stored hash of entry expect->id, once seen
  for (std::optional<qint64> after;;) {
    const std::vector<ChainedAuditEntry> batch = entriesAfter(db, after);
    for (const ChainedAuditEntry& e : batch) {
      ++report.entries;
      const bool prevFits = e.prevHash == expectedPrev;
      const bool ownFits = e.hash == auditEntryHash(e);
      if (!prevFits || !ownFits) {
        ++report.brokenLinks;
        if (report.brokenAt == 0) {
          report.brokenAt = e.id;
          report.problem = describeBreak(e, previous, prevFits, ownFits);
        }
      }
      if (expect && e.id == expect->id) anchorHash = e.hash;
      // The next entry is judged against what is stored here, so one forged entry is one
      // broken link, not every link after it.
      expectedPrev = e.hash;
      previous = e.id;
    }
    if (batch.size() < static_cast<std::size_t>(kBatchRows)) break;
    after = batch.back().id;
  }
  if (previous) report.newest = AuditAnchor{*previous, expectedPrev};
  if (const QStringList missing = missingGuards(db); !missing.isEmpty())
    report.guardProblem = "the triggers that keep it append-only are missing or disabled (" +
                          missing.join(", ") +
                          "): ArmTrack never removes them, so someone did, outside it";
  if (expect) {
    const QString kept = "entry " + QString::number(expect->id);
    if (!anchorHash && (!previous || *previous < expect->id))
      report.anchorProblem =
          kept + " is gone: the log now ends " +
          (!previous ? QString("empty") : "at entry " + QString::number(*previous)) +
          ", so its newest entries were deleted (the tail was cut off)";
    else if (!anchorHash)
      report.anchorProblem = kept + " is gone: it was deleted";
    else if (*anchorHash != expect->hash)
      report.anchorProblem = kept + " has hash " + *anchorHash + ", not the one kept (" +
                             expect->hash + "): the log was rewritten from that entry or before";
  }
  return report;
}

void chainAuditLogAndMakeItAppendOnly(Database& db) {
  // Chain what is there, in id order, a batch of rows per statement (one statement per row
  // would take minutes for a large log on a PostgreSQL server over the network). The values are
  // our own: ids and hex digits.
  QString prev = auditGenesisHash();
  for (std::optional<qint64> after;;) {
    std::vector<ChainedAuditEntry> batch = entriesAfter(db, after);
    if (batch.empty()) break;
    QStringList rows;
    for (ChainedAuditEntry& e : batch) {
      e.prevHash = prev;
      e.hash = auditEntryHash(e);
      prev = e.hash;
      rows << "(" + QString::number(e.id) + ", '" + e.prevHash + "', '" + e.hash + "')";
    }
    db.exec("WITH v (id, p, h) AS (VALUES " + rows.join(", ") +
            ") UPDATE audit_log SET prev_hash = v.p, hash = v.h FROM v WHERE audit_log.id = v.id");
    if (batch.size() < static_cast<std::size_t>(kBatchRows)) break;
    after = batch.back().id;
  }
  // Append-only from here on: ArmTrack never changes or deletes an entry. Whoever holds the file
  // or the database role can still drop these triggers; the chain is what shows it then.
  if (db.isPostgres()) {
    db.exec(
        "CREATE OR REPLACE FUNCTION audit_log_append_only() RETURNS trigger LANGUAGE plpgsql AS "
        "$$ BEGIN RAISE EXCEPTION 'the audit log is append-only: % of its entries is refused', "
        "TG_OP; END $$");
    db.exec(
        "CREATE TRIGGER audit_log_no_change BEFORE UPDATE OR DELETE ON audit_log FOR EACH ROW "
        "EXECUTE FUNCTION audit_log_append_only()");
    db.exec(
        "CREATE TRIGGER audit_log_no_truncate BEFORE TRUNCATE ON audit_log FOR EACH STATEMENT "
        "EXECUTE FUNCTION audit_log_append_only()");
  } else {
    db.exec(
        "CREATE TRIGGER audit_log_no_update BEFORE UPDATE ON audit_log BEGIN SELECT "
        "RAISE(ABORT, 'the audit log is append-only: an entry cannot be changed'); END");
    db.exec(
        "CREATE TRIGGER audit_log_no_delete BEFORE DELETE ON audit_log BEGIN SELECT "
        "RAISE(ABORT, 'the audit log is append-only: an entry cannot be deleted'); END");
  }
}

}  // namespace armtrack::storage
