// Home programmes and the patient's own outcome of a home session, of ClinicalStore
// (docs/storage.md, "Home programmes").
#include <QJsonDocument>
#include <cmath>

#include "core/storage/ClinicalStore.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

constexpr int kMaxSets = 20;
constexpr int kMaxRepetitions = 200;
constexpr double kMaxRestS = 3600;
constexpr int kMaxCommentChars = 2000;

std::string text(const QString& s) {
  return s.toStdString();
}

void checkExercise(const ProgrammeItem& item) {
  if (item.sessionsPerWeek < 0) throw StorageError(Kind::Usage, "sessions per week must be >= 0");
  if (item.position < 0) throw StorageError(Kind::Usage, "the position must be >= 1");
  if (item.sets < 1 || item.sets > kMaxSets)
    throw StorageError(Kind::Usage, "sets must be 1-" + std::to_string(kMaxSets) + ", got " +
                                        std::to_string(item.sets));
  if (item.repetitions && (*item.repetitions < 1 || *item.repetitions > kMaxRepetitions))
    throw StorageError(Kind::Usage, "repetitions must be 1-" + std::to_string(kMaxRepetitions) +
                                        ", got " + std::to_string(*item.repetitions));
  if (item.targetMinDeg.has_value() != item.targetMaxDeg.has_value())
    throw StorageError(Kind::Usage, "give both ends of the target range, or neither");
  if (item.targetMinDeg &&
      !(std::isfinite(*item.targetMinDeg) && std::isfinite(*item.targetMaxDeg) &&
        *item.targetMinDeg < *item.targetMaxDeg && std::abs(*item.targetMinDeg) <= 360 &&
        std::abs(*item.targetMaxDeg) <= 360))
    throw StorageError(Kind::Usage, "the target range needs finite min < max within +-360 deg");
  if (!(std::isfinite(item.restS) && item.restS >= 0 && item.restS <= kMaxRestS))
    throw StorageError(Kind::Usage, "the rest between sets must be 0-3600 s");
  checkTrunkLimit(item.trunkLimitDeg);
}

QVariant optional(const std::optional<int>& v) {
  return v ? QVariant(*v) : QVariant();
}

QVariant optional(const std::optional<double>& v) {
  return v ? QVariant(*v) : QVariant();
}

}  // namespace

void checkTrunkLimit(const std::optional<double>& limitDeg) {
  if (limitDeg && !(std::isfinite(*limitDeg) && *limitDeg >= kMinTrunkLimitDeg &&
                    *limitDeg <= kMaxTrunkLimitDeg))
    throw StorageError(Kind::Usage,
                       "the trunk limit must be 1-90 deg of trunk flexion (e.g. 15), or off; got " +
                           QString::number(*limitDeg).toStdString());
}

QString trunkLimitText(const std::optional<double>& limitDeg) {
  return limitDeg ? QStringLiteral("trunk limit %1 deg").arg(*limitDeg)
                  : QStringLiteral("trunk limit off");
}

void ClinicalStore::assignProtocol(const QString& patientCode, const QString& protocolName,
                                   int sessionsPerWeek, const QString& notes) {
  ProgrammeItem item;
  item.protocolName = protocolName;
  item.sessionsPerWeek = sessionsPerWeek;
  item.notes = notes;
  // Assigning again keeps the entry's place in the programme.
  require(isStaff(), "change home programmes");
  for (const ProgrammeItem& old : programme(patientCode))
    if (old.protocolName == protocolName) item.position = old.position;
  setProgrammeExercise(patientCode, item);
}

void ClinicalStore::setProgrammeExercise(const QString& patientCode, const ProgrammeItem& item) {
  require(isStaff(), "change home programmes");
  checkExercise(item);
  const qint64 patientId = visiblePatientId(patientCode);
  const qint64 protocolId = protocol(item.protocolName).id;
  m_db.transaction([&] {
    m_db.exec("DELETE FROM programmes WHERE patient_id = ? AND protocol_id = ?",
              {patientId, protocolId});
    int position = item.position;
    if (position == 0) {
      QSqlQuery q = m_db.exec(
          "SELECT coalesce(max(position), 0) FROM programmes WHERE patient_id = ?", {patientId});
      position = (q.next() ? q.value(0).toInt() : 0) + 1;
    } else {
      m_db.exec(
          "UPDATE programmes SET position = position + 1 WHERE patient_id = ? AND "
          "position >= ?",
          {patientId, position});
    }
    m_db.exec(
        "INSERT INTO programmes (patient_id, protocol_id, sessions_per_week, notes, created_at, "
        "position, sets, repetitions, target_min_deg, target_max_deg, rest_s, trunk_limit_deg) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
        {patientId, protocolId, item.sessionsPerWeek, item.notes, utcNow(), position, item.sets,
         optional(item.repetitions), optional(item.targetMinDeg), optional(item.targetMaxDeg),
         item.restS, optional(item.trunkLimitDeg)});
    renumberProgramme(patientId);
    audit("update", "programme", patientCode,
          "set " + item.protocolName +
              (item.trunkLimitDeg ? ", " + trunkLimitText(item.trunkLimitDeg) : QString()));
  });
}

void ClinicalStore::renumberProgramme(qint64 patientId) {
  std::vector<qint64> ids;
  QSqlQuery q = m_db.exec("SELECT id FROM programmes WHERE patient_id = ? ORDER BY position, id",
                          {patientId});
  while (q.next()) ids.push_back(q.value(0).toLongLong());
  q.finish();
  for (std::size_t i = 0; i < ids.size(); ++i)
    m_db.exec("UPDATE programmes SET position = ? WHERE id = ?", {static_cast<int>(i + 1), ids[i]});
}

void ClinicalStore::unassignProtocol(const QString& patientCode, const QString& protocolName) {
  require(isStaff(), "change home programmes");
  const qint64 patientId = visiblePatientId(patientCode);
  const qint64 protocolId = protocol(protocolName).id;
  m_db.transaction([&] {
    if (m_db.exec("DELETE FROM programmes WHERE patient_id = ? AND protocol_id = ?",
                  {patientId, protocolId})
            .numRowsAffected() == 0)
      throw StorageError(
          Kind::NotFound,
          text("protocol '" + protocolName + "' is not in the programme of '" + patientCode + "'"));
    renumberProgramme(patientId);
    audit("update", "programme", patientCode, "remove " + protocolName);
  });
}

std::vector<ProgrammeItem> ClinicalStore::programme(const QString& patientCode) {
  const qint64 patientId = visiblePatientId(patientCode);
  std::vector<ProgrammeItem> items;
  QSqlQuery q = m_db.exec(
      "SELECT pr.name, g.sessions_per_week, g.notes, g.position, g.sets, g.repetitions, "
      "g.target_min_deg, g.target_max_deg, g.rest_s, g.trunk_limit_deg FROM programmes g JOIN "
      "protocols pr ON "
      "pr.id = g.protocol_id WHERE g.patient_id = ? ORDER BY g.position, g.id",
      {patientId});
  while (q.next()) {
    ProgrammeItem item;
    item.protocolName = q.value(0).toString();
    item.sessionsPerWeek = q.value(1).toInt();
    item.notes = q.value(2).toString();
    item.position = q.value(3).toInt();
    item.sets = q.value(4).toInt();
    if (!q.value(5).isNull()) item.repetitions = q.value(5).toInt();
    if (!q.value(6).isNull() && !q.value(7).isNull()) {
      item.targetMinDeg = q.value(6).toDouble();
      item.targetMaxDeg = q.value(7).toDouble();
    }
    item.restS = q.value(8).toDouble();
    if (!q.value(9).isNull()) item.trunkLimitDeg = q.value(9).toDouble();
    items.push_back(item);
  }
  return items;
}

void ClinicalStore::saveHomeOutcome(qint64 sessionId, std::optional<int> painScore,
                                    const QString& comment, const QString& summaryJson) {
  require(user().role == Role::Home, "write a patient's own comment and pain score");
  const SessionInfo s = visibleSession(sessionId);
  if (s.setting != kSettingHome)
    throw StorageError(Kind::Usage,
                       "session " + std::to_string(sessionId) + " was not recorded at home");
  if (painScore && (*painScore < 0 || *painScore > 10))
    throw StorageError(Kind::Usage,
                       "the pain score must be 0-10, got " + std::to_string(*painScore));
  if (comment.size() > kMaxCommentChars)
    throw StorageError(Kind::Usage, "the comment is longer than " +
                                        std::to_string(kMaxCommentChars) + " characters");
  if (!QJsonDocument::fromJson(summaryJson.toUtf8()).isObject())
    throw StorageError(Kind::Usage, "a home session's summary must be a JSON object");
  m_db.transaction([&] {
    m_db.exec(
        "UPDATE sessions SET pain_score = ?, patient_comment = ?, home_summary_json = ? "
        "WHERE id = ?",
        {optional(painScore), comment, summaryJson, sessionId});
    audit("update", "session", QString::number(sessionId), "home outcome");
  });
}

}  // namespace armtrack::storage
