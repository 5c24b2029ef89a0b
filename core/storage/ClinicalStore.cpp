// Patients, protocols and the audit log of ClinicalStore (accounts and sign-in:
// ClinicalStoreAccounts.cpp).
#include "core/storage/ClinicalStore.h"

#include <QDate>
#include <cmath>

#include "core/kinematics/ClinicalAngles.h"
#include "core/storage/AuditLog.h"
#include "core/storage/TextRules.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

std::string text(const QString& s) {
  return s.toStdString();
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
  if (!q.value(7).isNull()) p.trunkLimitDeg = q.value(7).toDouble();
  return p;
}

const QString kPatientColumns =
    "id, code, name, birth_date, sex, affected_side, diagnosis, segment_lengths_json, notes";
const QString kProtocolColumns =
    "id, name, angle_key, target_min_deg, target_max_deg, repetitions, side, trunk_limit_deg";

QVariant nullable(const QString& s) {
  return s.isEmpty() ? QVariant() : QVariant(s);
}

/// newCode: the code is a new value (adding), not the key of an existing patient (updating).
void checkPatient(const Patient& p, bool newCode) {
  if (p.code.trimmed().isEmpty()) throw StorageError(Kind::Usage, "a patient needs a code");
  if (p.name.trimmed().isEmpty()) throw StorageError(Kind::Usage, "a patient needs a name");
  if (newCode) checkName("patient code", p.code, kMaxCodeLength);
  checkName("patient's name", p.name, kMaxNameLength);
  checkFreeText("diagnosis", p.diagnosis);
  checkFreeText("patient's notes", p.notes);
  if (!p.birthDate.isEmpty() && !QDate::fromString(p.birthDate, Qt::ISODate).isValid())
    throw StorageError(Kind::Usage, "birth date must be YYYY-MM-DD");
  if (!p.sex.isEmpty() && p.sex != "f" && p.sex != "m" && p.sex != "x")
    throw StorageError(Kind::Usage, "sex must be f, m or x");
  if (!p.affectedSide.isEmpty() &&
      !QStringList{"left", "right", "both", "none"}.contains(p.affectedSide))
    throw StorageError(Kind::Usage, "side must be left, right, both or none");
}

/// newName: the name is a new value (adding), not the key of an existing protocol (updating).
void checkProtocol(const Protocol& p, bool newName) {
  if (p.name.trimmed().isEmpty()) throw StorageError(Kind::Usage, "a protocol needs a name");
  if (newName) checkName("protocol name", p.name, kMaxNameLength);
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
  checkTrunkLimit(p.trunkLimitDeg);
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

qint64 ClinicalStore::visiblePatientId(const QString& code) {
  QSqlQuery q = m_db.exec("SELECT id FROM patients WHERE code_key = ?", {nameKey(code)});
  const bool found = q.next();
  const qint64 id = found ? q.value(0).toLongLong() : 0;
  if (!found || (user().role == Role::Home && user().patientId != id))
    throw StorageError(Kind::NotFound,
                       text("unknown patient '" + code + "': check the code with 'patient list'"));
  return id;
}

qint64 ClinicalStore::addPatient(const Patient& p) {
  require(isStaff(), "add patients");
  checkPatient(p, true);
  const QString key = nameKey(p.code);
  refuseTakenKey("patients", "code", "code_key", key, "a patient with the code", p.code);
  qint64 id = 0;
  m_db.transaction([&] {
    id = m_db.insert(
        "INSERT INTO patients (code, code_key, name, birth_date, sex, affected_side, diagnosis, "
        "segment_lengths_json, notes, created_at) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
        {p.code, key, p.name, nullable(p.birthDate), nullable(p.sex), nullable(p.affectedSide),
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
  checkPatient(p, false);
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
  checkProtocol(p, true);
  const QString key = nameKey(p.name);
  refuseTakenKey("protocols", "name", "name_key", key, "a protocol", p.name);
  qint64 id = 0;
  m_db.transaction([&] {
    id = m_db.insert(
        "INSERT INTO protocols (name, name_key, angle_key, target_min_deg, target_max_deg, "
        "repetitions, side, trunk_limit_deg) VALUES (?, ?, ?, ?, ?, ?, ?, ?)",
        {p.name, key, p.angleKey, p.targetMinDeg, p.targetMaxDeg, p.repetitions, p.side,
         p.trunkLimitDeg ? QVariant(*p.trunkLimitDeg) : QVariant()});
    audit("create", "protocol", p.name,
          p.trunkLimitDeg ? trunkLimitText(p.trunkLimitDeg) : QString());
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
  QSqlQuery q = m_db.exec("SELECT " + kProtocolColumns + " FROM protocols WHERE name_key = ?",
                          {nameKey(name)});
  if (!q.next()) throw StorageError(Kind::NotFound, text("unknown protocol '" + name + "'"));
  return protocolFrom(q);
}

std::optional<qint64> ClinicalStore::protocolId(const QString& name) {
  if (name.isEmpty()) return std::nullopt;
  return protocol(name).id;
}

void ClinicalStore::updateProtocol(const Protocol& p) {
  require(isStaff(), "change protocols");
  checkProtocol(p, false);
  m_db.transaction([&] {
    // The trunk limit's change is named in the audit log: it changes what patients are told.
    const std::optional<double> before = protocol(p.name).trunkLimitDeg;
    if (m_db.exec("UPDATE protocols SET angle_key = ?, target_min_deg = ?, target_max_deg = ?, "
                  "repetitions = ?, side = ?, trunk_limit_deg = ? WHERE name_key = ?",
                  {p.angleKey, p.targetMinDeg, p.targetMaxDeg, p.repetitions, p.side,
                   p.trunkLimitDeg ? QVariant(*p.trunkLimitDeg) : QVariant(), nameKey(p.name)})
            .numRowsAffected() == 0)
      throw StorageError(Kind::NotFound, text("unknown protocol '" + p.name + "'"));
    audit("update", "protocol", p.name,
          before != p.trunkLimitDeg ? trunkLimitText(p.trunkLimitDeg) : QString());
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

void ClinicalStore::refuseTakenKey(const QString& table, const QString& column,
                                   const QString& keyColumn, const QString& key,
                                   const QString& what, const QString& value) {
  QSqlQuery q =
      m_db.exec("SELECT " + column + " FROM " + table + " WHERE " + keyColumn + " = ?", {key});
  if (!q.next()) return;
  const QString stored = escapedForLine(q.value(0).toString());
  throw StorageError(Kind::Exists, text(what + " '" + stored +
                                        "' exists; names and codes are compared without "
                                        "regard to case, so '" +
                                        escapedForLine(value) + "' is the same: choose another"));
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
