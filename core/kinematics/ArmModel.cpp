#include "core/kinematics/ArmModel.h"

namespace armtrack {
namespace {
constexpr double kHalfPi = std::numbers::pi / 2;
// Rows 1-3, the shoulder, common to all four tables.
constexpr DhRow kShoulder1{0, 0.0, 0.0, kHalfPi, 0.0};
constexpr DhRow kShoulder2{1, kHalfPi, 0.0, kHalfPi, 0.0};
constexpr DhRow kShoulder3{2, 0.0, 0.0, 0.0, 0.0};
}  // namespace

std::array<DhRow, 6> upperImuTable(const ArmGeometry& geo) {
  return {kShoulder1,
          kShoulder2,
          kShoulder3,
          DhRow{-1, 0.0, geo.lu3, 0.0, 0.0},
          DhRow{-1, geo.thu4, 0.0, kHalfPi, 0.0},
          DhRow{-1, 0.0, geo.lu5, 0.0, 0.0}};
}

std::array<DhRow, 5> elbowTable(const ArmGeometry& geo) {
  return {kShoulder1, kShoulder2, kShoulder3, DhRow{-1, kHalfPi, geo.l3, -kHalfPi, 0.0},
          DhRow{3, 0.0, 0.0, kHalfPi, 0.0}};
}

std::array<DhRow, 9> forearmImuTable(const ArmGeometry& geo) {
  const auto e = elbowTable(geo);
  return {e[0],
          e[1],
          e[2],
          e[3],
          e[4],
          DhRow{4, 0.0, 0.0, 0.0, 0.0},
          DhRow{-1, 0.0, geo.lf6, 0.0, 0.0},
          DhRow{-1, geo.thf7 + kHalfPi, 0.0, kHalfPi, 0.0},
          DhRow{-1, 0.0, geo.lf8, 0.0, 0.0}};
}

std::array<DhRow, 7> wristTable(const ArmGeometry& geo) {
  const auto e = elbowTable(geo);
  return {
      e[0], e[1], e[2], e[3], e[4], DhRow{4, 0.0, 0.0, 0.0, 0.0}, DhRow{-1, 0.0, geo.l6, 0.0, 0.0}};
}

ArmPose forwardKinematics(const ArmGeometry& geo, const JointVector& th) {
  ArmPose pose;
  pose.upperImu = chainTransform(upperImuTable(geo), th);
  pose.forearmImu = chainTransform(forearmImuTable(geo), th);
  pose.elbow = chainTransform(elbowTable(geo), th).topRightCorner<3, 1>();
  pose.wrist = chainTransform(wristTable(geo), th).topRightCorner<3, 1>();
  return pose;
}

ArmPrediction predictSensors(const ArmGeometry& geo, const JointVector& th, const JointVector& thd,
                             const JointVector& thdd, const Eigen::Vector3d& gUp) {
  const ArmKinematics<double> k = armKinematics<double>(geo, th, thd, thdd, gUp);
  ArmPrediction p;
  p.upper = {k.upperImu.omega, k.upperImu.up + k.upperImu.accel};
  p.forearm = {k.forearmImu.omega, k.forearmImu.up + k.forearmImu.accel};
  p.elbow = k.elbow;
  p.wrist = k.wrist;
  return p;
}

}  // namespace armtrack
