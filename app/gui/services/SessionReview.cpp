#include "app/gui/services/SessionReview.h"

#include <QJsonArray>
#include <algorithm>
#include <cmath>

namespace armtrack::gui {

ReviewData loadReview(storage::ClinicalStore& store, qint64 id) {
  ReviewData d;
  d.info = store.session(id);
  d.patient = store.patient(d.info.patientCode);
  if (!d.info.protocolName.isEmpty()) d.protocol = store.protocol(d.info.protocolName);
  d.meta = store.recordingMeta(id);
  d.analysis = storage::latestAnalysis(store, id);
  d.metrics = storage::latestMetricsJson(store, id);
  d.versions = store.estimateVersions(id);
  d.recordingStartS = store.recordingStartS(id);
  for (storage::SessionInfo& s : store.listSessions(d.info.patientCode))
    if (s.id != id) d.others.push_back(std::move(s));
  std::sort(d.others.begin(), d.others.end(),
            [](const auto& a, const auto& b) { return a.startedAt > b.startedAt; });
  store.audit("view", "session", QString::number(id));
  return d;
}

double ReviewData::timeOrigin() const {
  if (recordingStartS && std::isfinite(*recordingStartS)) return *recordingStartS;
  return analysis && !analysis->t.empty() ? analysis->t.front() : 0.0;
}

std::vector<EventMark> ReviewData::events() const {
  return parseEventMarks(info.notes.toStdString(), timeOrigin());
}

std::vector<RepetitionRow> repetitionRows(const QJsonObject& metrics, int* skipped, double origin) {
  std::vector<RepetitionRow> rows;
  int bad = 0;
  const QJsonObject reps = metrics["repetitions"].toObject();
  const QString primary = reps["primary_angle"].toString();
  const auto number = [](const QJsonValue& v) -> std::optional<double> {
    return v.isDouble() && std::isfinite(v.toDouble()) ? std::optional(v.toDouble()) : std::nullopt;
  };
  for (const QJsonValue& v : reps["list"].toArray()) {
    const QJsonObject r = v.toObject();
    const auto start = number(r["start_s"]), end = number(r["end_s"]);
    const auto excursion = number(r["excursion_deg"]);
    if (!start || !end || !excursion || *end < *start) {
      ++bad;
      continue;
    }
    RepetitionRow row;
    row.startS = recordingTime(*start, origin);
    row.endS = recordingTime(*end, origin);
    row.peakS = recordingTime(number(r["peak_s"]).value_or(*start), origin);
    row.excursionDeg = *excursion;
    row.partial = r["partial"].toBool();
    const QJsonObject angle = r["angles"].toObject()[primary].toObject();
    row.romDeg = number(angle["rom_deg"]);
    row.peakVelocityDegS = number(angle["peak_velocity_deg_s"]);
    row.sparc = number(r["sparc"]);
    row.ldlj = number(r["ldlj"]);
    const QJsonObject trunk = r["trunk"].toObject();
    row.trunkFlexionDeg = number(trunk["max_flexion_deg"]);
    row.trunkLateralDeg = number(trunk["max_lateral_deg"]);
    row.trunkRotationDeg = number(trunk["max_rotation_deg"]);
    row.shoulderCm = number(trunk["max_shoulder_displacement_cm"]);
    if (trunk["compensated"].isBool()) row.compensated = trunk["compensated"].toBool();
    rows.push_back(row);
  }
  if (skipped) *skipped = bad;
  return rows;
}

std::size_t rowAt(const std::vector<double>& times, double t) {
  if (times.empty()) return 0;
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  return it == times.begin() ? 0 : static_cast<std::size_t>(it - times.begin() - 1);
}

}  // namespace armtrack::gui
