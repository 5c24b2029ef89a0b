#include "app/gui/services/HomeExerciseRules.h"

#include <algorithm>

namespace armtrack::gui {

HeadingTrust::HeadingTrust(int angle, double blindLimitS) : m_angle(angle), m_limit(blindLimitS) {}

void HeadingTrust::add(const session::EstimateRow& row) {
  if (!angleNeedsOptics(m_angle)) return;
  if (!row.headingFromStartPoseOnly)
    m_blindSince = -1;
  else if (m_blindSince < 0)
    m_blindSince = row.t;
}

bool HeadingTrust::blind(double t) const {
  return angleNeedsOptics(m_angle) && m_blindSince >= 0 && t - m_blindSince > m_limit;
}

bool HeadingTrust::shown(const session::EstimateRow& row) const {
  return angleTrustworthy(m_angle, row.thStd(m_angle), blind(row.t));
}

HomeExerciseResult plannedResult(const HomeExercise& exercise, bool measured) {
  HomeExerciseResult r;
  r.exercise = exercise.protocol.name;
  r.angle = exercise.angle;
  r.position = exercise.item.position;
  r.setsPlanned = exercise.item.sets;
  r.repetitionsPlanned = exercise.item.sets * exercise.repetitions;
  r.targetMinDeg = exercise.targetMinDeg;
  r.targetMaxDeg = exercise.targetMaxDeg;
  r.trunkLimitDeg = exercise.trunkLimitDeg;
  r.measured = measured;
  return r;
}

void addSet(HomeExerciseResult& result, const ExerciseFeedback& f, bool measured) {
  result.repetitions += static_cast<int>(f.repetitions());
  result.partial += static_cast<int>(f.partial());
  result.targetReached += static_cast<int>(f.targetReached());
  result.tooFast += static_cast<int>(f.tooFast());
  result.rangeNotReached += static_cast<int>(f.rangeNotReached());
  result.compensation += static_cast<int>(f.compensations());
  if (measured && f.repetitions() > 0) {
    const double lo = f.rangeMinRad() / kDegToRad, hi = f.rangeMaxRad() / kDegToRad;
    result.rangeMinDeg = std::min(result.rangeMinDeg.value_or(lo), lo);
    result.rangeMaxDeg = std::max(result.rangeMaxDeg.value_or(hi), hi);
  }
  ++result.setsDone;
}

}  // namespace armtrack::gui
