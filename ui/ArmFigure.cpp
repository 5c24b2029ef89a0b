#include "ui/ArmFigure.h"

namespace armtrack::ui {

namespace {
Eigen::Isometry3d toIsometry(const Eigen::Matrix4d& m) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = m.topLeftCorner<3, 3>();
  t.translation() = m.topRightCorner<3, 1>();
  return t;
}

Eigen::Vector3d alongSegment(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                             double distance, double length) {
  if (length <= 0.0) return from;
  return from + (to - from) * (distance / length);
}
}  // namespace

Eigen::Vector3d medialDirection(Side side) {
  return Eigen::Vector3d(0.0, 0.0, side == Side::Left ? 1.0 : -1.0);
}

ArmFigure transformed(const ArmFigure& f, const Eigen::Isometry3d& motion) {
  ArmFigure out = f;
  for (Eigen::Vector3d* p :
       {&out.shoulder, &out.elbow, &out.wrist, &out.upperStrap, &out.forearmStrap})
    *p = motion * *p;
  for (Eigen::Isometry3d* t : {&out.upperImu, &out.forearmImu}) *t = motion * *t;
  out.hand = motion.linear() * out.hand;
  return out;
}

ArmFigure armFigure(const ArmGeometry& geometry, const JointVector& th, Side side) {
  const ArmPose pose = forwardKinematics(geometry, th);
  ArmFigure f;
  f.elbow = pose.elbow;
  f.wrist = pose.wrist;
  f.upperImu = toIsometry(pose.upperImu);
  f.forearmImu = toIsometry(pose.forearmImu);
  f.upperStrap = alongSegment(f.shoulder, f.elbow, geometry.lu3, geometry.l3);
  f.forearmStrap = alongSegment(f.elbow, f.wrist, geometry.lf6, geometry.l6);
  // The hand turns with the forearm (th5): the forearm IMU's frame before its strap angle is
  // frame 6 of the model; at zero pose its z lies along z0, the palm's normal.
  const Eigen::Matrix4d frame6 = chainTransform(wristTable(geometry), th);
  Eigen::Vector3d along = f.wrist - f.elbow;
  along = along.norm() > 1e-9 ? Eigen::Vector3d(along.normalized())
                              : Eigen::Vector3d(frame6.block<3, 1>(0, 2));
  // y6: perpendicular to the forearm, along z0 (the palm's normal) at zero pose.
  Eigen::Vector3d across = frame6.block<3, 1>(0, 1);
  across = (across - across.dot(along) * along);
  across = across.norm() > 1e-9 ? Eigen::Vector3d(across.normalized()) : along.unitOrthogonal();
  f.hand.col(0) = along;
  f.hand.col(2) = across;
  f.hand.col(1) = across.cross(along);
  if (side == Side::Left) {
    const Eigen::DiagonalMatrix<double, 3> s(1.0, 1.0, -1.0);
    for (Eigen::Vector3d* p : {&f.elbow, &f.wrist, &f.upperStrap, &f.forearmStrap}) *p = s * *p;
    for (Eigen::Isometry3d* t : {&f.upperImu, &f.forearmImu}) {
      t->translation() = s * t->translation();
      t->linear() = s * t->linear() * s;
    }
    f.hand = s * f.hand * s;
  }
  return f;
}

}  // namespace armtrack::ui
