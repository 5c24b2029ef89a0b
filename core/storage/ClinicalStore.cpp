// Accounts, sign-in, patients, protocols and the audit log of ClinicalStore.
#include "core/storage/ClinicalStore.h"

#include <QDateTime>
#include <algorithm>
#include <cmath>

#include "core/kinematics/ClinicalAngles.h"
#include "core/storage/AuditLog.h"
#include "core/storage/PasswordHash.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

constexpr int kFreeAttempts = 3;  // wrong passwords before sign-in slows down
constexpr int kMaxWaitSeconds = 300;

std::string text(const QString& s) {
  return s.toStdString();
}

User userFrom(const QSqlQuery& q) {
  User u;
  u.id = q.value(0).toLongLong();
  u.name = q.value(1).toString();
  u.role = parseRole(q.value(2).toString()).value_or(Role::Home);
  if (!q.value(3).isNull()) u.patientId = q.value(3).toLongLong();
  u.failedAttempts = q.value(4).toInt();
  return u;
}

Patient patientFrom(const QSqlQuery& q) {
  Patient p;
  p.id = q.value(0).toLongLong();
  p.code = q.value(1).toString();
  p.name = q.value(2).toString();
  p.birthDate = q.value(3).toString();
  p.sex = q.value(4).toString();
  p.affectedSide = q.value(5).toString();
  p.diagnosis = q.value(6).toString();
  p.segmentLengthsJson = q.value(7).toString();
  p.notes = q.value(8).toString();
  return p;
}

Protocol protocolFrom(const QSqlQuery& q) {
  Protocol p;
  p.id = q.value(0).toLongLong();
  p.name = q.value(1).toString();
  p.angleKey = q.value(2).toString();
  p.targetMinDeg = q.value(3).toDouble();
  p.targetMaxDeg = q.value(4).toDouble();
  p.repetitions = q.value(5).toInt();
  p.side = q.value(6).toString();
  return p;
}

const QString kUserColumns = "id, name, role, patient_id, failed_attempts";
const QString kPatientColumns =
    "id, code, name, birth_date, sex, affected_side, diagnosis, segment_lengths_json, notes";
const QString kProtocolColumns =
    "id, name, angle_key, target_min_deg, target_max_deg, repetitions, side";

QVariant nullable(const QString& s) {
  return s.isEmpty() ? QVariant() : QVariant(s);
}

void checkPatient(const Patient& p) {
  if (p.code.trimmed().isEmpty()) throw StorageError(Kind::Usage, "a patient needs a code");
  if (p.name.trimmed().isEmpty()) throw StorageError(Kind::Usage, "a patient needs a name");
  if (!p.birthDate.isEmpty() && !QDate::fromString(p.birthDate, Qt::ISODate).isValid())
    throw StorageError(Kind::Usage, "birth date must be YYYY-MM-DD");
  if (!p.sex.isEmpty() && p.sex != "f" && p.sex != "m" && p.sex != "x")
    throw StorageError(Kind::Usage, "sex must be f, m or x");
  if (!p.affectedSide.isEmpty() &&
      !QStringList{"left", "right", "both", "none"}.contains(p.affectedSide))
    throw StorageError(Kind::Usage, "side must be left, right, both or none");
}

void checkProtocol(const Protocol& p) {
  if (p.name.trimmed().isEmpty()) throw StorageError(Kind::Usage, "a protocol needs a name");
  QStringList keys;
  for (const ClinicalAngleInfo& a : clinicalAngleInfo())
    keys << QString::fromUtf8(a.key.data(), static_cast<qsizetype>(a.key.size()));
  if (!keys.contains(p.angleKey))
    throw StorageError(Kind::Usage, text("unknown clinical angle '" + p.angleKey +
                                         "'; valid keys: " + keys.join(", ")));
  if (!std::isfinite(p.targetMinDeg) || !std::isfinite(p.targetMaxDeg) ||
      p.targetMinDeg > p.targetMaxDeg)
    throw StorageError(Kind::Usage, "the target range needs finite min <= max (deg)");
  if (p.repetitions < 0) throw StorageError(Kind::Usage, "repetitions must be >= 0");
  if (!QStringList{"left", "right", "either"}.contains(p.side))
    throw StorageError(Kind::Usage, "the protocol's side must be left, right or either");
}

}  // namespace

QString roleName(Role role) {
  switch (role) {
    case Role::Admin:
      return "admin";
    case Role::Therapist:
      return "therapist";
    case Role::Home:
      return "home";
  }
  return "home";
}

std::optional<Role> parseRole(const QString& name) {
  if (name == "admin") return Role::Admin;
  if (name == "therapist") return Role::Therapist;
  if (name == "home") return Role::Home;
  return std::nullopt;
}

ClinicalStore::ClinicalStore(Database& db) : m_db(db) {
  m_interruptedOnOpen = markDeadRecordingsInterrupted();
}

void ClinicalStore::initialise(const QString& adminName, const std::string& password) {
  if (adminName.trimmed().isEmpty())
    throw StorageError(Kind::Usage, "the administrator needs a name");
  if (password.empty()) throw StorageError(Kind::Usage, "the administrator needs a password");
  QSqlQuery q = m_db.exec("SELECT count(*) FROM users");
  const bool any = q.next() && q.value(0).toLongLong() > 0;
  q.finish();
  if (any)
    throw StorageError(Kind::Exists,
                       "the database already has accounts; sign in as an "
                       "administrator and use 'user add'");
  const QString hash = QString::fromStdString(PasswordHash::hash(password));
  m_db.transaction([&] {
    m_db.insert("INSERT INTO users (name, role, password_hash, created_at) VALUES (?, ?, ?, ?)",
                {adminName, "admin", hash, utcNow()});
    appendAudit(m_db, {adminName, "create", "database", m_db.url().display(), {}});
  });
}

const User& ClinicalStore::signIn(const QString& name, const std::string& password) {
  const std::string refused = "wrong user name or password for '" + text(name) + "'";
  QSqlQuery q = m_db.exec("SELECT " + kUserColumns +
                              ", password_hash, last_failed_at FROM users "
                              "WHERE name = ?",
                          {name});
  if (!q.next()) {
    PasswordHash::verify("", password);  // no early answer for an unknown name
    throw StorageError(Kind::Authentication, refused);
  }
  User u = userFrom(q);
  const std::string hash = q.value(5).toString().toStdString();
  const QDateTime lastFailed = QDateTime::fromString(q.value(6).toString(), Qt::ISODateWithMs);
  q.finish();
  if (u.failedAttempts >= kFreeAttempts && lastFailed.isValid()) {
    const int wait = std::min(kMaxWaitSeconds, 1 << std::min(u.failedAttempts - kFreeAttempts, 9));
    const qint64 since = lastFailed.secsTo(QDateTime::currentDateTimeUtc());
    if (since < wait)
      throw StorageError(Kind::Authentication, "too many wrong passwords for '" + text(name) +
                                                   "': try again in " +
                                                   std::to_string(wait - since) + " s");
  }
  if (!PasswordHash::verify(hash, password)) {
    m_db.exec(
        "UPDATE users SET failed_attempts = failed_attempts + 1, last_failed_at = ? "
        "WHERE id = ?",
        {utcNow(), u.id});
    appendAudit(m_db, {name, "sign-in-failed", "user", name, {}});
    throw StorageError(Kind::Authentication, refused);
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
  if (!allowed)
    throw StorageError(Kind::AccessDenied, text("account '" + user().name + "' (" +
                                                roleName(user().role) + ") may not " + what));
}

bool ClinicalStore::isStaff() const {
  return user().role != Role::Home;
}

qint64 ClinicalStore::addUser(const QString& name, Role role, const std::string& password,
                              const QString& patientCode) {
  require(user().role == Role::Admin, "add accounts");
  if (name.trimmed().isEmpty()) throw StorageError(Kind::Usage, "an account needs a name");
  if (password.empty()) throw StorageError(Kind::Usage, "an account needs a password");
  QVariant patientId;
  if (role == Role::Home) {
    if (patientCode.isEmpty())
      throw StorageError(Kind::Usage, "a home account needs its patient (--patient CODE)");
    patientId = visiblePatientId(patientCode);
  } else if (!patientCode.isEmpty()) {
    throw StorageError(Kind::Usage, "only home accounts are linked to a patient");
  }
  const QString hash = QString::fromStdString(PasswordHash::hash(password));
  qint64 id = 0;
  m_db.transaction([&] {
    id = m_db.insert(
        "INSERT INTO users (name, role, password_hash, patient_id, created_at) "
        "VALUES (?, ?, ?, ?, ?)",
        {name, roleName(role), hash, patientId, utcNow()});
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
  require(user().role == Role::Admin || user().name == name, "change another's password");
  if (password.empty()) throw StorageError(Kind::Usage, "an account needs a password");
  const QString hash = QString::fromStdString(PasswordHash::hash(password));
  if (m_db.exec("UPDATE users SET password_hash = ?, failed_attempts = 0 WHERE name = ?",
                {hash, name})
          .numRowsAffected() == 0)
    throw StorageError(Kind::NotFound, text("no account '" + name + "'"));
  audit("update", "user", name, "password");
}

void ClinicalStore::removeUser(const QString& name) {
  require(user().role == Role::Admin, "remove accounts");
  if (name == user().name) throw StorageError(Kind::Usage, "an administrator cannot remove itself");
  if (m_db.exec("DELETE FROM users WHERE name = ?", {name}).numRowsAffected() == 0)
    throw StorageError(Kind::NotFound, text("no account '" + name + "'"));
  audit("delete", "user", name);
}

qint64 ClinicalStore::visiblePatientId(const QString& code) {
  QSqlQuery q = m_db.exec("SELECT id FROM patients WHERE code = ?", {code});
  const bool found = q.next();
  const qint64 id = found ? q.value(0).toLongLong() : 0;
  if (!found || (user().role == Role::Home && user().patientId != id))
    throw StorageError(Kind::NotFound,
                       text("unknown patient '" + code + "': check the code with 'patient list'"));
  return id;
}

qint64 ClinicalStore::addPatient(const Patient& p) {
  require(isStaff(), "add patients");
  checkPatient(p);
  qint64 id = 0;
  m_db.transaction([&] {
    id = m_db.insert(
        "INSERT INTO patients (code, name, birth_date, sex, affected_side, diagnosis, "
        "segment_lengths_json, notes, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?)",
        {p.code, p.name, nullable(p.birthDate), nullable(p.sex), nullable(p.affectedSide),
         p.diagnosis, p.segmentLengthsJson.isEmpty() ? "{}" : p.segmentLengthsJson, p.notes,
         utcNow()});
    audit("create", "patient", p.code);
  });
  return id;
}

std::vector<Patient> ClinicalStore::listPatients() {
  std::vector<Patient> patients;
  QSqlQuery q = user().role == Role::Home
                    ? m_db.exec("SELECT " + kPatientColumns + " FROM patients WHERE id = ?",
                                {user().patientId.value_or(-1)})
                    : m_db.exec("SELECT " + kPatientColumns + " FROM patients ORDER BY code");
  while (q.next()) patients.push_back(patientFrom(q));
  return patients;
}

Patient ClinicalStore::patient(const QString& code) {
  const qint64 id = visiblePatientId(code);
  QSqlQuery q = m_db.exec("SELECT " + kPatientColumns + " FROM patients WHERE id = ?", {id});
  q.next();
  return patientFrom(q);
}

void ClinicalStore::updatePatient(const Patient& p) {
  require(isStaff(), "change patients");
  checkPatient(p);
  const qint64 id = visiblePatientId(p.code);
  m_db.transaction([&] {
    m_db.exec(
        "UPDATE patients SET name = ?, birth_date = ?, sex = ?, affected_side = ?, "
        "diagnosis = ?, segment_lengths_json = ?, notes = ? WHERE id = ?",
        {p.name, nullable(p.birthDate), nullable(p.sex), nullable(p.affectedSide), p.diagnosis,
         p.segmentLengthsJson.isEmpty() ? "{}" : p.segmentLengthsJson, p.notes, id});
    audit("update", "patient", p.code);
  });
}

void ClinicalStore::removePatient(const QString& code) {
  require(user().role == Role::Admin, "remove patients");
  const qint64 id = visiblePatientId(code);
  m_db.transaction([&] {
    m_db.exec("DELETE FROM sessions WHERE patient_id = ?", {id});
    m_db.exec("DELETE FROM users WHERE patient_id = ?", {id});
    m_db.exec("DELETE FROM patients WHERE id = ?", {id});
    audit("delete", "patient", code);
  });
}

qint64 ClinicalStore::addProtocol(const Protocol& p) {
  require(isStaff(), "add protocols");
  checkProtocol(p);
  qint64 id = 0;
  m_db.transaction([&] {
    id = m_db.insert(
        "INSERT INTO protocols (name, angle_key, target_min_deg, target_max_deg, "
        "repetitions, side) VALUES (?, ?, ?, ?, ?, ?)",
        {p.name, p.angleKey, p.targetMinDeg, p.targetMaxDeg, p.repetitions, p.side});
    audit("create", "protocol", p.name);
  });
  return id;
}

std::vector<Protocol> ClinicalStore::listProtocols() {
  user();
  std::vector<Protocol> protocols;
  QSqlQuery q = m_db.exec("SELECT " + kProtocolColumns + " FROM protocols ORDER BY name");
  while (q.next()) protocols.push_back(protocolFrom(q));
  return protocols;
}

Protocol ClinicalStore::protocol(const QString& name) {
  user();
  QSqlQuery q = m_db.exec("SELECT " + kProtocolColumns + " FROM protocols WHERE name = ?", {name});
  if (!q.next()) throw StorageError(Kind::NotFound, text("unknown protocol '" + name + "'"));
  return protocolFrom(q);
}

std::optional<qint64> ClinicalStore::protocolId(const QString& name) {
  if (name.isEmpty()) return std::nullopt;
  return protocol(name).id;
}

void ClinicalStore::updateProtocol(const Protocol& p) {
  require(isStaff(), "change protocols");
  checkProtocol(p);
  m_db.transaction([&] {
    if (m_db.exec("UPDATE protocols SET angle_key = ?, target_min_deg = ?, target_max_deg = ?, "
                  "repetitions = ?, side = ? WHERE name = ?",
                  {p.angleKey, p.targetMinDeg, p.targetMaxDeg, p.repetitions, p.side, p.name})
            .numRowsAffected() == 0)
      throw StorageError(Kind::NotFound, text("unknown protocol '" + p.name + "'"));
    audit("update", "protocol", p.name);
  });
}

void ClinicalStore::removeProtocol(const QString& name) {
  require(isStaff(), "remove protocols");
  m_db.transaction([&] {
    const qint64 id = protocol(name).id;
    m_db.exec("UPDATE sessions SET protocol_id = NULL WHERE protocol_id = ?", {id});
    m_db.exec("DELETE FROM protocols WHERE id = ?", {id});
    audit("delete", "protocol", name);
  });
}

std::vector<AuditEntry> ClinicalStore::auditLog() {
  require(user().role == Role::Admin, "read the audit log");
  std::vector<AuditEntry> log;
  QSqlQuery q = m_db.exec(
      "SELECT id, at, user_name, action, object_type, object_id, detail "
      "FROM audit_log ORDER BY id");
  while (q.next())
    log.push_back({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(),
                   q.value(3).toString(), q.value(4).toString(), q.value(5).toString(),
                   q.value(6).toString()});
  return log;
}

void ClinicalStore::audit(const QString& action, const QString& objectType, const QString& objectId,
                          const QString& detail) {
  appendAudit(m_db, {user().name, action, objectType, objectId, detail});
}

}  // namespace armtrack::storage
