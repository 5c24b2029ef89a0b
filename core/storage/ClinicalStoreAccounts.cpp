// Accounts, sign-in, the access rule's refusals and the administrator's acts on the whole
// database (backup, migration) of ClinicalStore (docs/storage.md, "Security").
#include <QDateTime>
#include <algorithm>

#include "core/storage/AuditLog.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/PasswordHash.h"
#include "core/storage/TextRules.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

constexpr int kFreeAttempts = 3;  // wrong passwords before sign-in slows down
constexpr int kMaxWaitSeconds = 300;
/// Names without an account whose failed sign-ins are counted (sign_in_failures); beyond it the
/// rows of the longest-quiet names are dropped, so a flood of random names cannot grow it.
constexpr int kMaxUnknownNames = 10000;
/// How much of a name without an account is kept (its key, the audit entry), in code points.
constexpr int kMaxKeptNameLength = 200;

std::string text(const QString& s) {
  return s.toStdString();
}

/// The first n code points of s.
QString clipped(const QString& s, int n) {
  qsizetype i = 0;
  for (int k = 0; k < n && i < s.size(); ++k)
    i += (s[i].isHighSurrogate() && i + 1 < s.size() && s[i + 1].isLowSurrogate()) ? 2 : 1;
  return s.left(i);
}

/// A name as messages quote it: one line, at most an account name's length (and "...").
std::string quoted(const QString& name) {
  const QString shown = clipped(name, kMaxAccountNameLength);
  return "'" + text(escapedForLine(shown)) + (shown.size() < name.size() ? "...'" : "'");
}

User userFrom(const QSqlQuery& q) {
  User u;
  u.id = q.value(0).toLongLong();
  u.name = q.value(1).toString();
  u.role = parseRole(q.value(2).toString()).value_or(Role::Home);
  if (!q.value(3).isNull()) u.patientId = q.value(3).toLongLong();
  u.failedAttempts = q.value(4).toInt();
  u.disabled = q.value(5).toInt() != 0;
  return u;
}

const QString kUserColumns = "id, name, role, patient_id, failed_attempts, disabled";

/// Seconds still to wait after failures consecutive wrong passwords, the last at lastFailed:
/// 2^(n-3) s after the third (at most kMaxWaitSeconds); 0 when none.
qint64 waitLeft(int failures, const QDateTime& lastFailed) {
  if (failures < kFreeAttempts || !lastFailed.isValid()) return 0;
  const int wait = std::min(kMaxWaitSeconds, 1 << std::min(failures - kFreeAttempts, 9));
  const qint64 since = lastFailed.secsTo(QDateTime::currentDateTimeUtc());
  return since < wait ? wait - since : 0;
}

/// Counts a wrong sign-in for a name without an account (inside a transaction).
void countUnknownFailure(Database& db, const QString& key) {
  const QString now = utcNow();
  if (db.exec("UPDATE sign_in_failures SET failed_attempts = failed_attempts + 1, "
              "last_failed_at = ? WHERE name_key = ?",
              {now, key})
          .numRowsAffected() > 0)
    return;
  db.exec(
      "INSERT INTO sign_in_failures (name_key, failed_attempts, last_failed_at) "
      "VALUES (?, 1, ?)",
      {key, now});
  QSqlQuery n = db.exec("SELECT count(*) FROM sign_in_failures");
  const qint64 excess = n.next() ? n.value(0).toLongLong() - kMaxUnknownNames : 0;
  n.finish();
  if (excess > 0)
    db.exec(
        "DELETE FROM sign_in_failures WHERE name_key IN (SELECT name_key FROM "
        "sign_in_failures ORDER BY last_failed_at, name_key LIMIT ?)",
        {excess});
}

}  // namespace

void ClinicalStore::initialise(const QString& adminName, const std::string& password) {
  if (adminName.trimmed().isEmpty())
    throw StorageError(Kind::Usage, "the administrator needs a name");
  checkName("administrator's name", adminName, kMaxAccountNameLength);
  if (password.empty()) throw StorageError(Kind::Usage, "the administrator needs a password");
  checkNewPassword(password);
  QSqlQuery q = m_db.exec("SELECT count(*) FROM users");
  const bool any = q.next() && q.value(0).toLongLong() > 0;
  q.finish();
  if (any)
    throw StorageError(Kind::Exists,
                       "the database already has accounts; sign in as an "
                       "administrator and use 'user add'");
  const QString hash = QString::fromStdString(PasswordHash::hash(password));
  m_db.transaction([&] {
    m_db.insert(
        "INSERT INTO users (name, name_key, role, password_hash, created_at) "
        "VALUES (?, ?, ?, ?, ?)",
        {adminName, nameKey(adminName), "admin", hash, utcNow()});
    appendAudit(m_db, {adminName, "create", "database", m_db.url().display(), {}});
  });
}

// A name with an account and one without cost the same: the same two lookups, an Argon2id
// verification (against PasswordHash::dummyHash() when there is no account), the same
// throttling and messages, one transaction counting the failure and auditing it.
const User& ClinicalStore::signIn(const QString& name, const std::string& password) {
  const std::string refused = "wrong user name or password for " + quoted(name);
  const QString key = nameKey(name);
  const QString keptKey = clipped(key, kMaxKeptNameLength);
  QSqlQuery q = m_db.exec(
      "SELECT " + kUserColumns + ", password_hash, last_failed_at FROM users WHERE name_key = ?",
      {key});
  const bool known = q.next();
  User u;
  std::string hash = PasswordHash::dummyHash();
  QDateTime lastFailed;
  if (known) {
    u = userFrom(q);
    hash = q.value(6).toString().toStdString();
    lastFailed = QDateTime::fromString(q.value(7).toString(), Qt::ISODateWithMs);
  }
  q.finish();
  QSqlQuery f = m_db.exec(
      "SELECT failed_attempts, last_failed_at FROM sign_in_failures WHERE name_key = ?", {keptKey});
  int failures = u.failedAttempts;
  if (f.next() && !known) {
    failures = f.value(0).toInt();
    lastFailed = QDateTime::fromString(f.value(1).toString(), Qt::ISODateWithMs);
  }
  f.finish();
  // Who the log names: the account, or the name as typed (clipped).
  const QString who = known ? u.name : clipped(name, kMaxKeptNameLength);
  const QString why = known ? "wrong password" : "no such account";
  if (const qint64 wait = waitLeft(failures, lastFailed); wait > 0) {
    appendAudit(m_db, {who, "sign-in-failed", "user", who,
                       (known ? QString() : why + ", ") + "too soon after " +
                           QString::number(failures) + " failures: password not checked"});
    throw StorageError(Kind::Authentication, "too many wrong passwords for " + quoted(name) +
                                                 ": try again in " + std::to_string(wait) + " s");
  }
  if (!PasswordHash::verify(hash, password) || !known) {
    m_db.transaction([&] {
      if (known)
        m_db.exec(
            "UPDATE users SET failed_attempts = failed_attempts + 1, last_failed_at = ? "
            "WHERE id = ?",
            {utcNow(), u.id});
      else
        countUnknownFailure(m_db, keptKey);
      appendAudit(m_db, {who, "sign-in-failed", "user", who, why});
    });
    throw StorageError(Kind::Authentication, refused);
  }
  // Only after the password: a stranger learns no more about a disabled name than any other.
  if (u.disabled) {
    appendAudit(m_db, {u.name, "sign-in-failed", "user", u.name, "account disabled"});
    throw StorageError(
        Kind::Authentication,
        "the account " + quoted(u.name) + " is disabled: an administrator can enable it again");
  }
  if (u.failedAttempts != 0) {
    m_db.exec("UPDATE users SET failed_attempts = 0, last_failed_at = NULL WHERE id = ?", {u.id});
    u.failedAttempts = 0;
  }
  m_user = u;
  return *m_user;
}

const User& ClinicalStore::user() const {
  if (!m_user) throw StorageError(Kind::Authentication, "not signed in");
  return *m_user;
}

void ClinicalStore::require(bool allowed, const QString& what) const {
  if (!allowed) deny(what);
}

void ClinicalStore::deny(const QString& what, const std::string& message) const {
  const User& u = user();
  const AuditEvent event{u.name, "access-denied", "user", u.name, what};
  Database& db = m_db;
  try {
    // After the transaction the caller may be in, so that its rollback keeps the entry.
    db.afterTransaction([&db, event] { appendAudit(db, event); });
  } catch (const StorageError&) {  // a log that cannot be written does not lift the refusal
  }
  throw StorageError(Kind::AccessDenied, message.empty()
                                             ? text("account '" + escapedForLine(u.name) + "' (" +
                                                    roleName(u.role) + ") may not " + what)
                                             : message);
}

bool ClinicalStore::isStaff() const {
  return user().role != Role::Home;
}

qint64 ClinicalStore::addUser(const QString& name, Role role, const std::string& password,
                              const QString& patientCode) {
  require(user().role == Role::Admin, "add accounts");
  if (name.trimmed().isEmpty()) throw StorageError(Kind::Usage, "an account needs a name");
  checkName("account name", name, kMaxAccountNameLength);
  if (password.empty()) throw StorageError(Kind::Usage, "an account needs a password");
  checkNewPassword(password);
  QVariant patientId;
  if (role == Role::Home) {
    if (patientCode.isEmpty())
      throw StorageError(Kind::Usage, "a home account needs its patient (--patient CODE)");
    patientId = visiblePatientId(patientCode);
  } else if (!patientCode.isEmpty()) {
    throw StorageError(Kind::Usage, "only home accounts are linked to a patient");
  }
  const QString key = nameKey(name);
  QSqlQuery taken = m_db.exec("SELECT name FROM users WHERE name_key = ?", {key});
  if (taken.next())
    throw StorageError(Kind::Exists, "an account " + quoted(taken.value(0).toString()) +
                                         " exists; account names are compared without regard "
                                         "to case, so " +
                                         quoted(name) + " is the same name: choose another");
  taken.finish();
  const QString hash = QString::fromStdString(PasswordHash::hash(password));
  qint64 id = 0;
  m_db.transaction([&] {
    id = m_db.insert(
        "INSERT INTO users (name, name_key, role, password_hash, patient_id, created_at) "
        "VALUES (?, ?, ?, ?, ?, ?)",
        {name, key, roleName(role), hash, patientId, utcNow()});
    audit("create", "user", name, "role " + roleName(role));
  });
  return id;
}

std::vector<User> ClinicalStore::listUsers() {
  require(user().role == Role::Admin, "list accounts");
  std::vector<User> users;
  QSqlQuery q = m_db.exec("SELECT " + kUserColumns + " FROM users ORDER BY name");
  while (q.next()) users.push_back(userFrom(q));
  return users;
}

void ClinicalStore::setPassword(const QString& name, const std::string& password) {
  require(user().role == Role::Admin || nameKey(user().name) == nameKey(name),
          "change another's password");
  if (password.empty()) throw StorageError(Kind::Usage, "an account needs a password");
  checkNewPassword(password);
  QSqlQuery q = m_db.exec("SELECT id, name FROM users WHERE name_key = ?", {nameKey(name)});
  if (!q.next()) throw StorageError(Kind::NotFound, "no account " + quoted(name));
  const qint64 id = q.value(0).toLongLong();
  const QString stored = q.value(1).toString();
  q.finish();
  const QString hash = QString::fromStdString(PasswordHash::hash(password));
  m_db.transaction([&] {
    m_db.exec(
        "UPDATE users SET password_hash = ?, failed_attempts = 0, last_failed_at = NULL "
        "WHERE id = ?",
        {hash, id});
    audit("update", "user", stored, "password");
  });
}

void ClinicalStore::setUserDisabled(const QString& name, bool disabled) {
  require(user().role == Role::Admin, disabled ? "disable accounts" : "enable accounts");
  if (disabled && nameKey(name) == nameKey(user().name))
    throw StorageError(Kind::Usage, "an administrator cannot disable itself");
  QSqlQuery q =
      m_db.exec("SELECT id, name, disabled FROM users WHERE name_key = ?", {nameKey(name)});
  if (!q.next()) throw StorageError(Kind::NotFound, "no account " + quoted(name));
  const qint64 id = q.value(0).toLongLong();
  const QString stored = q.value(1).toString();
  const bool was = q.value(2).toInt() != 0;
  q.finish();
  if (was == disabled) return;  // nothing to change, nothing to audit
  m_db.transaction([&] {
    m_db.exec("UPDATE users SET disabled = ? WHERE id = ?", {disabled ? 1 : 0, id});
    audit("update", "user", stored, disabled ? "disabled" : "enabled");
  });
}

void ClinicalStore::removeUser(const QString& name) {
  require(user().role == Role::Admin, "remove accounts");
  if (nameKey(name) == nameKey(user().name))
    throw StorageError(Kind::Usage, "an administrator cannot remove itself");
  QSqlQuery q = m_db.exec("SELECT id, name FROM users WHERE name_key = ?", {nameKey(name)});
  if (!q.next()) throw StorageError(Kind::NotFound, "no account " + quoted(name));
  const qint64 id = q.value(0).toLongLong();
  const QString stored = q.value(1).toString();
  q.finish();
  m_db.transaction([&] {
    m_db.exec("DELETE FROM users WHERE id = ?", {id});
    audit("delete", "user", stored);
  });
}

void ClinicalStore::backup(const QString& outPath) {
  require(user().role == Role::Admin, "back up the database");
  m_db.backup(outPath);
  audit("backup", "database", m_db.url().display(), outPath);
}

void ClinicalStore::confirmMigration(int stepsApplied) {
  require(user().role == Role::Admin, "migrate the database");
  audit("migrate", "database", m_db.url().display(), QString("%1 step(s)").arg(stepsApplied));
}

}  // namespace armtrack::storage
