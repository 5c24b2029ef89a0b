#include "app/gui/services/HomeRecords.h"

#include <QJsonDocument>
#include <algorithm>

#include "app/gui/services/AngleKeys.h"

namespace armtrack::gui {

namespace {

constexpr auto kFormat = "armtrack-home-v1";

QJsonValue optionalNumber(const std::optional<double>& v) {
  return v ? QJsonValue(*v) : QJsonValue();
}

}  // namespace

QJsonObject HomeExerciseResult::toJson() const {
  return QJsonObject{{"format", kFormat},
                     {"exercise", exercise},
                     {"angle", angleKey(angle)},
                     {"position", position},
                     {"sets_planned", setsPlanned},
                     {"sets_done", setsDone},
                     {"repetitions_planned", repetitionsPlanned},
                     {"repetitions", repetitions},
                     {"partial", partial},
                     {"target_min_deg", targetMinDeg},
                     {"target_max_deg", targetMaxDeg},
                     {"range_min_deg", optionalNumber(rangeMinDeg)},
                     {"range_max_deg", optionalNumber(rangeMaxDeg)},
                     {"target_reached", targetReached},
                     {"too_fast", tooFast},
                     {"range_not_reached", rangeNotReached},
                     {"compensation", compensation},
                     {"trunk_limit_deg", optionalNumber(trunkLimitDeg)},
                     {"trunk_compensation", trunkCompensation},
                     {"measured", measured},
                     {"stopped_early", stoppedEarly}};
}

std::optional<HomeExerciseResult> HomeExerciseResult::fromJson(const QJsonObject& o) {
  if (o.value("format").toString() != QLatin1String(kFormat)) return std::nullopt;
  HomeExerciseResult r;
  r.exercise = o.value("exercise").toString();
  r.angle = angleIndex(o.value("angle").toString());
  if (r.angle < 0) return std::nullopt;
  r.position = o.value("position").toInt();
  r.setsPlanned = o.value("sets_planned").toInt();
  r.setsDone = o.value("sets_done").toInt();
  r.repetitionsPlanned = o.value("repetitions_planned").toInt();
  r.repetitions = o.value("repetitions").toInt();
  r.partial = o.value("partial").toInt();
  r.targetMinDeg = o.value("target_min_deg").toDouble();
  r.targetMaxDeg = o.value("target_max_deg").toDouble();
  if (o.value("range_min_deg").isDouble()) r.rangeMinDeg = o.value("range_min_deg").toDouble();
  if (o.value("range_max_deg").isDouble()) r.rangeMaxDeg = o.value("range_max_deg").toDouble();
  r.targetReached = o.value("target_reached").toInt();
  r.tooFast = o.value("too_fast").toInt();
  r.rangeNotReached = o.value("range_not_reached").toInt();
  r.compensation = o.value("compensation").toInt();
  if (o.value("trunk_limit_deg").isDouble())
    r.trunkLimitDeg = o.value("trunk_limit_deg").toDouble();
  r.trunkCompensation = o.value("trunk_compensation").toInt();
  r.measured = o.value("measured").toBool(true);
  r.stoppedEarly = o.value("stopped_early").toBool();
  return r;
}

HomePlan loadHomePlan(storage::ClinicalStore& store, const QString& patientCode) {
  HomePlan plan;
  plan.patient = store.patient(patientCode);
  for (const storage::ProgrammeItem& item : store.programme(patientCode)) {
    HomeExercise e;
    e.item = item;
    e.protocol = store.protocol(item.protocolName);
    e.angle = angleIndex(e.protocol.angleKey);
    if (e.angle < 0) continue;
    e.repetitions = std::max(1, storage::effectiveRepetitions(item, e.protocol));
    std::tie(e.targetMinDeg, e.targetMaxDeg) = storage::effectiveTarget(item, e.protocol);
    e.trunkLimitDeg = storage::effectiveTrunkLimit(item, e.protocol);
    plan.exercises.push_back(e);
  }
  plan.history.resize(plan.exercises.size());
  // listSessions gives them oldest first.
  for (const storage::SessionInfo& s : store.listSessions(patientCode)) {
    if (s.setting != QLatin1String(storage::kSettingHome)) continue;
    const auto r =
        HomeExerciseResult::fromJson(QJsonDocument::fromJson(s.homeSummaryJson.toUtf8()).object());
    if (!r) continue;
    for (std::size_t i = 0; i < plan.exercises.size(); ++i) {
      if (plan.exercises[i].protocol.name != r->exercise) continue;
      auto& h = plan.history[i];
      h.push_back({s.startedAt, *r});
      if (h.size() > static_cast<std::size_t>(HomePlan::kHistory)) h.erase(h.begin());
    }
  }
  return plan;
}

void saveHomeOutcomes(storage::ClinicalStore& store, const std::vector<HomeExerciseResult>& results,
                      std::optional<int> painScore, const QString& comment) {
  for (const HomeExerciseResult& r : results) {
    if (r.sessionId == 0) continue;
    store.saveHomeOutcome(
        r.sessionId, painScore, comment,
        QString::fromUtf8(QJsonDocument(r.toJson()).toJson(QJsonDocument::Compact)));
  }
}

}  // namespace armtrack::gui
