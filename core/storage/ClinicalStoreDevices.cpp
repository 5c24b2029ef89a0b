// Home devices of ClinicalStore: enrolment codes, device tokens and their revocation, and the
// service identity of armtrack-server (docs/sync.md). Codes and tokens are kept as hashes only.
#include <QDateTime>

#include "core/storage/AuditLog.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/SyncSecrets.h"
#include "core/storage/TextRules.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

constexpr qint64 kMinCodeValidityS = 60;
constexpr qint64 kMaxCodeValidityS = 30 * 24 * 3600;
const char* const kRefusedCode =
    "the enrolment code is wrong, used or expired: ask the clinic for a new one";
const char* const kRefusedToken =
    "this device is not enrolled (its token is unknown or was revoked): enrol it again with a "
    "new code from the clinic";

QString isoIn(qint64 seconds) {
  return QDateTime::currentDateTimeUtc().addSecs(seconds).toString(Qt::ISODateWithMs);
}

}  // namespace

EnrolmentCode ClinicalStore::createEnrolmentCode(const QString& homeAccount, qint64 validForS) {
  require(isStaff(), "make enrolment codes");
  if (validForS < kMinCodeValidityS || validForS > kMaxCodeValidityS)
    throw StorageError(Kind::Usage, "an enrolment code is valid for 1 minute to 30 days");
  QSqlQuery q =
      m_db.exec("SELECT id, role, disabled FROM users WHERE name_key = ?", {nameKey(homeAccount)});
  if (!q.next()) throw StorageError(Kind::NotFound, "no account of that name");
  const qint64 userId = q.value(0).toLongLong();
  if (q.value(1).toString() != "home")
    throw StorageError(Kind::Usage, "enrolment codes are for home accounts only");
  if (q.value(2).toInt() != 0)
    throw StorageError(Kind::Usage, "the account is disabled: enable it first");
  q.finish();
  EnrolmentCode code{newEnrolmentCode(), isoIn(validForS)};
  m_db.transaction([&] {
    m_db.insert(
        "INSERT INTO enrolment_codes (user_id, code_hash, created_at, expires_at) "
        "VALUES (?, ?, ?, ?)",
        {userId, secretHash("enrolment-code", normalisedEnrolmentCode(code.code)), utcNow(),
         code.expiresAt});
    appendAudit(m_db, {user().name, "enrolment-code-create", "user", QString::number(userId),
                       "valid until " + code.expiresAt});
  });
  return code;
}

DeviceEnrolment ClinicalStore::enrolDevice(const QString& code, const QString& deviceLabel) {
  const QString normal = normalisedEnrolmentCode(code);
  const auto refuse = [&](const QString& why) {
    appendAudit(m_db, {"system", "enrol-refused", "device", "-", why});
    throw StorageError(Kind::Authentication, kRefusedCode);
  };
  if (normal.isEmpty()) refuse("malformed code");
  QSqlQuery q = m_db.exec(
      "SELECT c.id, c.expires_at, c.used_at, u.id, u.disabled FROM enrolment_codes c JOIN users "
      "u ON u.id = c.user_id WHERE c.code_hash = ?",
      {secretHash("enrolment-code", normal)});
  if (!q.next()) refuse("unknown code");
  const qint64 codeId = q.value(0).toLongLong();
  const QString expiresAt = q.value(1).toString();
  const bool used = !q.value(2).isNull();
  const qint64 userId = q.value(3).toLongLong();
  const bool disabled = q.value(4).toInt() != 0;
  q.finish();
  const QString who = QString::number(userId);
  if (used) refuse("code " + QString::number(codeId) + " already used (account " + who + ")");
  if (expiresAt <= utcNow())
    refuse("code " + QString::number(codeId) + " expired (account " + who + ")");
  if (disabled) refuse("account " + who + " is disabled");
  DeviceEnrolment out;
  out.token = newDeviceToken();
  bool won = false;
  m_db.transaction([&] {
    // Used once only, even by two devices racing with the same code.
    won = m_db.exec("UPDATE enrolment_codes SET used_at = ? WHERE id = ? AND used_at IS NULL",
                    {utcNow(), codeId})
              .numRowsAffected() == 1;
    if (!won) return;
    out.deviceId = m_db.insert(
        "INSERT INTO devices (user_id, token_hash, label, created_at) VALUES (?, ?, ?, ?)",
        {userId, secretHash("device-token", out.token), deviceLabel.left(100), utcNow()});
    appendAudit(m_db, {"system", "enrol", "device", QString::number(out.deviceId),
                       "account " + who + " with code " + QString::number(codeId)});
  });
  if (!won) refuse("code " + QString::number(codeId) + " already used (account " + who + ")");
  signInWithDeviceToken(out.token);
  QSqlQuery p = m_db.exec("SELECT code FROM patients WHERE id = ?", {user().patientId.value_or(0)});
  if (p.next()) out.patientCode = p.value(0).toString();
  return out;
}

const User& ClinicalStore::signInWithDeviceToken(const QString& token) {
  const auto refuse = [&](const QString& why) {
    appendAudit(m_db, {"system", "sync-refused", "device", "-", why});
    throw StorageError(Kind::Authentication, kRefusedToken);
  };
  if (!looksLikeDeviceToken(token)) refuse("malformed token");
  QSqlQuery q = m_db.exec(
      "SELECT d.id, d.revoked_at, u.id, u.name, u.patient_id, u.disabled, u.role FROM devices d "
      "JOIN users u ON u.id = d.user_id WHERE d.token_hash = ?",
      {secretHash("device-token", token)});
  if (!q.next()) refuse("unknown token");
  const qint64 device = q.value(0).toLongLong();
  if (!q.value(1).isNull()) refuse("device " + QString::number(device) + " is revoked");
  User u;
  u.id = q.value(2).toLongLong();
  u.name = q.value(3).toString();
  u.patientId = q.value(4).toLongLong();
  u.disabled = q.value(5).toInt() != 0;
  u.role = Role::Home;
  if (q.value(6).toString() != "home" || q.value(4).isNull())
    refuse("device " + QString::number(device) + " belongs to no home account");
  q.finish();
  if (u.disabled) refuse("device " + QString::number(device) + ": account disabled");
  m_db.exec("UPDATE devices SET last_seen_at = ? WHERE id = ?", {utcNow(), device});
  m_user = u;
  m_deviceId = device;
  return *m_user;
}

std::vector<User> ClinicalStore::listHomeAccounts(const QString& patientCode) {
  require(isStaff(), "list home accounts");
  QSqlQuery q = m_db.exec(
      "SELECT u.id, u.name, u.patient_id, u.disabled FROM users u JOIN patients p ON p.id = "
      "u.patient_id WHERE p.code_key = ? AND u.role = 'home' ORDER BY u.name_key",
      {nameKey(patientCode)});
  std::vector<User> out;
  while (q.next()) {
    User u;
    u.id = q.value(0).toLongLong();
    u.name = q.value(1).toString();
    u.role = Role::Home;
    u.patientId = q.value(2).toLongLong();
    u.disabled = q.value(3).toInt() != 0;
    out.push_back(u);
  }
  return out;
}

std::vector<DeviceInfo> ClinicalStore::listDevices(const QString& homeAccount) {
  require(isStaff(), "list devices");
  QSqlQuery q = m_db.exec(
      "SELECT d.id, d.label, d.created_at, d.last_seen_at, d.revoked_at FROM devices d JOIN "
      "users u ON u.id = d.user_id WHERE u.name_key = ? ORDER BY d.id",
      {nameKey(homeAccount)});
  std::vector<DeviceInfo> out;
  while (q.next())
    out.push_back({q.value(0).toLongLong(), q.value(1).toString(), q.value(2).toString(),
                   q.value(3).toString(), q.value(4).toString()});
  return out;
}

void ClinicalStore::revokeDevice(qint64 deviceId) {
  require(isStaff(), "revoke devices");
  m_db.transaction([&] {
    QSqlQuery q = m_db.exec("UPDATE devices SET revoked_at = ? WHERE id = ? AND revoked_at IS NULL",
                            {utcNow(), deviceId});
    if (q.numRowsAffected() != 1)
      throw StorageError(Kind::NotFound, "no enrolled device " + std::to_string(deviceId));
    appendAudit(m_db, {user().name, "revoke", "device", QString::number(deviceId), {}});
  });
}

void ClinicalStore::signInAsService(const QString& serviceName) {
  User u;
  u.id = 0;  // no account: sessions begun as the service name no therapist
  u.name = serviceName;
  u.role = Role::Therapist;
  m_user = u;
  m_deviceId = 0;
}

}  // namespace armtrack::storage
