// The movements of a home session, as the virtual arm plays them: the sensor check and one
// exercise repeated (Trajectory.h).
#include <cmath>
#include <stdexcept>

#include "core/kinematics/ClinicalAngles.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {

namespace {

JointVector posture(const ClinicalAngles& c) {
  return fromClinical(c);
}

double& field(ClinicalAngles& c, int angle) {
  switch (angle) {
    case 0:
      return c.shoulderFlexion;
    case 1:
      return c.shoulderAbduction;
    case 2:
      return c.shoulderInternalRotation;
    case 3:
      return c.elbowFlexion;
    default:
      return c.forearmPronation;
  }
}

}  // namespace

SensorCheckTrajectory::SensorCheckTrajectory() {
  const JointVector hanging = JointVector::Zero();
  ClinicalAngles bent;
  bent.elbowFlexion = bendDeg();
  m_path.add(0.0, hanging);
  m_path.add(restSeconds(), hanging);
  for (int i = 0; i < bends(); ++i) {
    const double t0 = restSeconds() + i * bendSeconds();
    m_path.add(t0 + 0.5 * bendSeconds(), posture(bent));
    m_path.add(t0 + bendSeconds(), hanging);
  }
  m_path.add(duration(), hanging);
}

JointMotion SensorCheckTrajectory::at(double t) const {
  return m_path.at(t);
}

int ExerciseTrajectory::compensatingAngle(int exerciseAngle) {
  // A shoulder exercise done by bending the elbow; an elbow or forearm one by lifting the arm.
  return exerciseAngle <= 2 ? 3 : 0;
}

ExerciseTrajectory::ExerciseTrajectory(const ExerciseMotion& motion) : m_motion(motion) {
  const ExerciseMotion& m = motion;
  if (m.angle < 0 || m.angle > 4)
    throw std::invalid_argument("exercise: the angle must be a clinical angle index 0-4");
  if (!std::isfinite(m.fromDeg) || !std::isfinite(m.toDeg) || !std::isfinite(m.compensationDeg) ||
      !std::isfinite(m.periodSeconds) || !std::isfinite(m.pauseSeconds) ||
      !std::isfinite(m.startSeconds))
    throw std::invalid_argument("exercise: every value must be finite");
  if (!(m.periodSeconds > 0)) throw std::invalid_argument("exercise: the period must be > 0 s");
  if (m.pauseSeconds < 0 || m.startSeconds < 0)
    throw std::invalid_argument("exercise: the pause and the start must be >= 0 s");
  // The posture the other angles hold: forearm rotation with the elbow at a right angle, the
  // rest with the elbow almost straight.
  ClinicalAngles rest;
  rest.elbowFlexion = m.angle == 4 ? 90.0 : 5.0;
  field(rest, m.angle) = m.fromDeg;
  ClinicalAngles top = rest;
  field(top, m.angle) = m.toDeg;
  field(top, compensatingAngle(m.angle)) += m.compensationDeg;
  m_cycle.add(0.0, posture(rest));
  m_cycle.add(0.5 * m.periodSeconds, posture(top));
  m_cycle.add(m.periodSeconds, posture(rest));
  m_cycle.add(m.periodSeconds + m.pauseSeconds, posture(rest));
  m_cycleSeconds = m.periodSeconds + m.pauseSeconds;
}

JointMotion ExerciseTrajectory::at(double t) const {
  if (!(t > m_motion.startSeconds)) return m_cycle.at(0.0);
  return m_cycle.at(std::fmod(t - m_motion.startSeconds, m_cycleSeconds));
}

}  // namespace armtrack
