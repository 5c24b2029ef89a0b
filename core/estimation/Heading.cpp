#include "core/estimation/Heading.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace armtrack {

namespace {
// Cosines and sines of the two angles the shoulder axes depend on.
struct ShoulderTrig {
  double c0, s0, c1, s1;
  explicit ShoulderTrig(const JointVector& th)
      : c0(std::cos(th(0))), s0(std::sin(th(0))), c1(std::cos(th(1))), s1(std::sin(th(1))) {}
};

// The shoulder axes in frame 0 (columns z0, z1, z2): the spatial angular velocity of the upper
// arm is J_s th'.head<3>().
Eigen::Matrix3d shoulderAxes(const ShoulderTrig& t) {
  // Rows 1-2 of the tables give z1 = Rz(th0) Rx(pi/2) z and z2 = z1's frame turned by th1 + pi/2.
  Eigen::Matrix3d j;
  j.col(0) = Eigen::Vector3d::UnitZ();
  j.col(1) = Eigen::Vector3d(t.s0, -t.c0, 0.0);
  j.col(2) = Eigen::Vector3d(t.c1 * t.c0, t.c1 * t.s0, t.s1);
  return j;
}
Eigen::Matrix3d shoulderAxes(const JointVector& th) {
  return shoulderAxes(ShoulderTrig(th));
}

// The upper arm's orientation in frame 0 up to a constant rotation on the right (which a turn
// on the left leaves alone): the shoulder rows' Rz(th0) Rx(pi/2) Rz(th1 + pi/2) Rx(pi/2) Rz(th2).
// Its spatial angular velocity is shoulderAxes(th) th'.
Eigen::Matrix3d shoulderRotation(const JointVector& th) {
  using Eigen::AngleAxisd;
  using Eigen::Vector3d;
  constexpr double kHalfPi = std::numbers::pi / 2;
  return (AngleAxisd(th(0), Vector3d::UnitZ()) * AngleAxisd(kHalfPi, Vector3d::UnitX()) *
          AngleAxisd(th(1) + kHalfPi, Vector3d::UnitZ()) * AngleAxisd(kHalfPi, Vector3d::UnitX()) *
          AngleAxisd(th(2), Vector3d::UnitZ()))
      .toRotationMatrix();
}

// Inverse of shoulderRotation: the angle triple of orientation r nearest `near` (wrapped
// distance). z2 = r z = (c1 c0, c1 s0, s1) gives th1 and th0 on each branch; th2 is what turns
// the rest of the chain onto r.
Eigen::Vector3d shoulderAnglesNear(const Eigen::Matrix3d& r, const Eigen::Vector3d& near) {
  const Eigen::Vector3d z2 = r.col(2);
  const double s1 = std::clamp(z2(2), -1.0, 1.0);
  const double a1 = std::asin(s1);
  const double horizontal = std::hypot(z2(0), z2(1));
  Eigen::Vector3d best = near;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (const double th1 : {a1, wrapAngle(std::numbers::pi - a1)}) {
    const double c1 = std::cos(th1);
    // At the gimbal lock th0 is free: keep the one the arm had.
    const double th0 = horizontal > 1e-9 ? std::atan2(z2(1) / c1, z2(0) / c1) : near(0);
    const Eigen::Matrix3d m =
        shoulderRotation(JointVector(th0, th1, 0.0, 0.0, 0.0)).transpose() * r;
    const double th2 = std::atan2(m(1, 0), m(0, 0));
    const Eigen::Vector3d cand(wrapAngle(th0), wrapAngle(th1), wrapAngle(th2));
    double d = 0.0;
    for (int j = 0; j < 3; ++j) d += std::abs(wrapAngle(cand(j) - near(j)));
    if (d < bestDistance) {
      bestDistance = d;
      best = cand;
    }
  }
  return best;
}

// up . (J_s dth) as a row over the five angles: J_s^T up in the shoulder's entries.
JointVector covectorOf(const Eigen::Matrix3d& axes, const Eigen::Vector3d& up) {
  JointVector w = JointVector::Zero();
  w.head<3>() = axes.transpose() * up;
  return w;
}

// (J J^T + eps I)^-1, the damped least-squares normal matrix's inverse, by cofactors (Eigen's
// 3x3 inverse): a sixth of an LDLT factorisation and its solve, and as accurate here.
Eigen::Matrix3d dampedInverse(const Eigen::Matrix3d& j) {
  return (j * j.transpose() + 1e-12 * Eigen::Matrix3d::Identity()).inverse();
}
}  // namespace

// J_s h = up, where J_s's columns are the three shoulder axes in frame 0 (z0, z1, z2). The damping
// only guards the gimbal lock; it is small enough that h stays the exact rotation elsewhere.
JointVector headingGenerator(const JointVector& th, const Eigen::Vector3d& up) {
  return headingGeometry(th, up).generator;
}

HeadingGeometry headingGeometry(const JointVector& th, const Eigen::Vector3d& up) {
  const ShoulderTrig t(th);
  HeadingGeometry g;
  g.c0 = t.c0, g.s0 = t.s0, g.c1 = t.c1, g.s1 = t.s1;
  g.axes = shoulderAxes(t);
  g.normalInverse = dampedInverse(g.axes);
  g.generator.setZero();
  g.generator.head<3>() = g.axes.transpose() * (g.normalInverse * up);
  return g;
}

JointVector headingCovector(const HeadingGeometry& g, const Eigen::Vector3d& up) {
  return covectorOf(g.axes, up);
}

JointVector headingCovector(const JointVector& th, const Eigen::Vector3d& up) {
  return covectorOf(shoulderAxes(th), up);
}

JointVector headingDirection(const JointVector& th, const Eigen::Vector3d& up) {
  const JointVector d = headingGenerator(th, up);
  const double n = d.norm();
  return n > 0 ? JointVector(d / n) : d;
}

Eigen::Matrix<double, 15, 1> headingSymmetry(const Eigen::Matrix<double, 15, 1>& x,
                                             const Eigen::Vector3d& up) {
  return headingSymmetry(x, up, headingGeometry(x.segment<5>(10), up));
}

Eigen::Matrix<double, 15, 1> headingSymmetry(const Eigen::Matrix<double, 15, 1>& x,
                                             const Eigen::Vector3d& up, const HeadingGeometry& g) {
  // Turning a whole motion th(t) about the vertical maps it to phi(th(t)); differentiating with
  // respect to the turn angle gives th -> h, th' -> Dh th', th'' -> Dh th'' + D2h[th', th'].
  // h = J^T y with A y = up, A = J J^T + eps I (dampedInverse), and J depends on th0 and th1 only;
  // differentiating A y = up along a direction d gives y' = -A^-1 A' y and
  // y'' = -A^-1 (A'' y + 2 A' y'), so h' = J'^T y + J^T y' and
  // h'' = J''^T y + 2 J'^T y' + J^T y'': exact derivatives, with A inverted once.
  const JointVector thd = x.segment<5>(5), thdd = x.segment<5>(0);
  const JointVector& h = g.generator;
  const double c0 = g.c0, s0 = g.s0, c1 = g.c1, s1 = g.s1;
  const Eigen::Matrix3d& j = g.axes;
  const Eigen::Matrix3d& aInv = g.normalInverse;
  const Eigen::Vector3d y = aInv * up;
  // Along d: J' (z0 is constant, z1 turns with th0, z2 with th0 and th1), A', y' and h'.
  struct First {
    Eigen::Matrix3d dj, da;
    Eigen::Vector3d dy;
    JointVector dh = JointVector::Zero();
  };
  auto first = [&](const JointVector& d) {
    First f;
    f.dj.col(0).setZero();
    f.dj.col(1) = d(0) * Eigen::Vector3d(c0, s0, 0.0);
    f.dj.col(2) = d(0) * Eigen::Vector3d(-c1 * s0, c1 * c0, 0.0) +
                  d(1) * Eigen::Vector3d(-s1 * c0, -s1 * s0, c1);
    f.da = f.dj * j.transpose() + j * f.dj.transpose();
    f.dy = -(aInv * (f.da * y));
    f.dh.head<3>() = f.dj.transpose() * y + j.transpose() * f.dy;
    return f;
  };
  const First rate = first(thd);
  const JointVector dhThdd = first(thdd).dh;
  // J'' along th', then A'', y'' and h''.
  const double d0 = thd(0), d1 = thd(1);
  Eigen::Matrix3d d2j;
  d2j.col(0).setZero();
  d2j.col(1) = d0 * d0 * Eigen::Vector3d(-s0, c0, 0.0);
  d2j.col(2) = d0 * d0 * Eigen::Vector3d(-c1 * c0, -c1 * s0, 0.0) +
               2.0 * d0 * d1 * Eigen::Vector3d(s1 * s0, -s1 * c0, 0.0) +
               d1 * d1 * Eigen::Vector3d(-c1 * c0, -c1 * s0, -s1);
  const Eigen::Matrix3d d2a =
      d2j * j.transpose() + 2.0 * rate.dj * rate.dj.transpose() + j * d2j.transpose();
  const Eigen::Vector3d d2y = -(aInv * (d2a * y + 2.0 * rate.da * rate.dy));
  JointVector d2hThd = JointVector::Zero();
  d2hThd.head<3>() =
      d2j.transpose() * y + 2.0 * rate.dj.transpose() * rate.dy + j.transpose() * d2y;
  const JointVector& dhThd = rate.dh;
  Eigen::Matrix<double, 15, 1> v;
  v.segment<5>(0) = dhThdd + d2hThd;
  v.segment<5>(5) = dhThd;
  v.segment<5>(10) = h;
  const double n = h.norm();
  return n > 0 ? Eigen::Matrix<double, 15, 1>(v / n) : v;
}

JointVector turnAboutVertical(const JointVector& th, double angle, const Eigen::Vector3d& up) {
  // Each shoulder orientation has two angle triples (th1 and pi - th1, with th0 and th2 turned by
  // pi) and, at the gimbal lock, a line of them. Turning in steps of at most 15 deg and taking at
  // each step the triple nearest the last one follows the branch a continuous turn reaches.
  const Eigen::Vector3d axis = up.normalized();
  const Eigen::Matrix3d start = shoulderRotation(th);
  constexpr double kStep = 15.0 * std::numbers::pi / 180.0;
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(angle) / kStep)));
  JointVector t = th;
  for (int k = 1; k <= steps; ++k) {
    const Eigen::Matrix3d goal = Eigen::AngleAxisd(angle * k / steps, axis) * start;
    t.head<3>() = shoulderAnglesNear(goal, t.head<3>());
  }
  return t;
}

JointVector turnSecondMoment(const JointVector& th, double turnStd, const Eigen::Vector3d& up) {
  // A sum over turns spaced at most half a standard deviation (and 15 deg) apart out to 4
  // standard deviations (at most half a circle) each way, weighted by the normal density. Each
  // side is turned outward in steps from th, so every point costs one step of turnAboutVertical
  // and follows the same continuous branch. The joints' change is far from smooth in the turn
  // when the arm passes near the gimbal lock, where a 5-point Gauss-Hermite rule was far off.
  JointVector m = JointVector::Zero();
  if (!(turnStd > 0.0)) return m;
  const Eigen::Vector3d axis = up.normalized();
  const Eigen::Matrix3d start = shoulderRotation(th);
  const double reach = std::min(4.0 * turnStd, std::numbers::pi);
  constexpr double kMaxStep = 15.0 * std::numbers::pi / 180.0;
  const int steps = static_cast<int>(std::ceil(reach / std::min(0.5 * turnStd, kMaxStep)));
  const double step = reach / steps;
  double weights = 1.0;  // the centre: no change
  for (const double sign : {-1.0, 1.0}) {
    Eigen::Vector3d t = th.head<3>();
    for (int k = 1; k <= steps; ++k) {
      const double turn = sign * k * step;
      t = shoulderAnglesNear(Eigen::AngleAxisd(turn, axis) * start, t);
      const double z = turn / turnStd;
      const double w = std::exp(-0.5 * z * z);
      for (int j = 0; j < 3; ++j) m(j) += w * std::pow(wrapAngle(t(j) - th(j)), 2);
      weights += w;
    }
  }
  return m / weights;
}

}  // namespace armtrack
