#include "core/estimation/MeasurementJacobian.h"

#include <array>
#include <cmath>
#include <limits>

namespace armtrack {

namespace {

constexpr double kHalfPi = detail::kHalfPi;

// A 3-vector and its derivatives with respect to the state, joint by joint: with C = 3, column
// 3j + k is the derivative with respect to joint j's acceleration (k = 0), rate (1) and angle
// (2); with C = 1 (gravity, which only the angles turn), column j is joint j's angle. A frame
// moves only with the joints before it, so after J joints only the first C J columns can be
// non-zero: the operations below take J as a template argument and touch those columns alone,
// in place, so no frame's derivatives are ever copied or widened.
template <int C>
struct Tangent {
  using Derivatives = Eigen::Matrix<double, 3, C * kNumJoints, Eigen::RowMajor>;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  Derivatives d = Derivatives::Zero();
  static constexpr int angleColumn(int joint) { return C * joint + C - 1; }
};

// FrameState (ArmModel.h) with derivatives. The angular velocity has no derivative with respect
// to the accelerations; it is kept in the same layout as the accelerations it feeds.
struct Frame {
  Tangent<3> w, wd, acc;
  Tangent<1> up;
};

// detail::toChild with derivatives, in place: Rx(-beta) Rz(-gamma) v, with c, s the cosine and
// sine of gamma. joint >= 0 when gamma is that joint's angle (plus a constant): then
// dc = -s dth and ds = c dth.
template <int J, int C>
void toChild(Tangent<C>& t, double c, double s, double beta, int joint) {
  using Row = Eigen::Matrix<double, 1, C * J>;
  auto d = t.d.template leftCols<C * J>();
  const double x = c * t.v(0) + s * t.v(1);
  const double y = c * t.v(1) - s * t.v(0);
  const Row r0 = d.row(0);
  d.row(0) = c * r0 + s * d.row(1);
  d.row(1) = c * d.row(1) - s * r0;
  if (joint >= 0) {
    t.d(0, Tangent<C>::angleColumn(joint)) += y;
    t.d(1, Tangent<C>::angleColumn(joint)) -= x;
  }
  t.v = Eigen::Vector3d(x, y, t.v(2));
  if (beta == 0.0) return;
  const Row r1 = d.row(1);
  const double y1 = t.v(1);
  if (beta == kHalfPi) {  // (x, z, -y)
    t.v(1) = t.v(2);
    t.v(2) = -y1;
    d.row(1) = d.row(2);
    d.row(2) = -r1;
  } else if (beta == -kHalfPi) {  // (x, -z, y)
    t.v(1) = -t.v(2);
    t.v(2) = y1;
    d.row(1) = -d.row(2);
    d.row(2) = r1;
  } else {
    const double cb = std::cos(beta), sb = std::sin(beta);
    t.v(1) = cb * y1 + sb * t.v(2);
    t.v(2) = cb * t.v(2) - sb * y1;
    d.row(1) = cb * r1 + sb * d.row(2);
    d.row(2) = cb * d.row(2) - sb * r1;
  }
}

// All of a frame's vectors to the child frame; the acceleration only when the model reads it.
template <int J>
void frameToChild(Frame& f, double c, double s, double beta, int joint, bool bodyAccel) {
  toChild<J>(f.w, c, s, beta, joint);
  toChild<J>(f.wd, c, s, beta, joint);
  if (bodyAccel) toChild<J>(f.acc, c, s, beta, joint);
  toChild<J>(f.up, c, s, beta, joint);
}

// The lever term of propagate() for a translation lambda along the parent's z, added to acc:
// w.' x lambda k + w' x (w' x lambda k), from the parent's w' and w.'.
template <int J>
void addLever(Tangent<3>& acc, const Tangent<3>& w0, const Tangent<3>& wd0, double lambda) {
  const Eigen::Vector3d& w = w0.v;
  acc.v(0) += lambda * (wd0.v(1) + w(0) * w(2));
  acc.v(1) += lambda * (w(1) * w(2) - wd0.v(0));
  acc.v(2) -= lambda * (w(0) * w(0) + w(1) * w(1));
  const auto dw = w0.d.template leftCols<3 * J>();
  const auto dwd = wd0.d.template leftCols<3 * J>();
  auto da = acc.d.template leftCols<3 * J>();
  da.row(0) += lambda * (dwd.row(1) + w(0) * dw.row(2) + w(2) * dw.row(0));
  da.row(1) += lambda * (w(1) * dw.row(2) + w(2) * dw.row(1) - dwd.row(0));
  da.row(2) -= (2.0 * lambda) * (w(0) * dw.row(0) + w(1) * dw.row(1));
}

// propagate() (ArmModel.h) for a row whose rotation is joint j = J - 1's angle, with its rate
// rate and acceleration accel; no translation (every joint row of the tables has lambda =
// delta = 0).
template <int J>
void jointRow(Frame& f, double c, double s, double rate, double accel, double beta,
              bool bodyAccel) {
  constexpr int j = J - 1;
  // w.' + w' x rate k + accel k; the rate changes only w's z row, which this does not read.
  auto dwd = f.wd.d.template leftCols<3 * J>();
  const auto dw = f.w.d.template leftCols<3 * J>();
  f.wd.v =
      Eigen::Vector3d(f.wd.v(0) + f.w.v(1) * rate, f.wd.v(1) - f.w.v(0) * rate, f.wd.v(2) + accel);
  dwd.row(0) += rate * dw.row(1);
  dwd.row(1) -= rate * dw.row(0);
  f.wd.d(0, 3 * j + 1) += f.w.v(1);
  f.wd.d(1, 3 * j + 1) -= f.w.v(0);
  f.wd.d(2, 3 * j) += 1.0;
  f.w.v(2) += rate;
  f.w.d(2, 3 * j + 1) += 1.0;
  frameToChild<J>(f, c, s, beta, j, bodyAccel);
}

// The cosine and sine of a constant row's rotation, remembered for the last angle: the geometry
// changes with the patient's set-up, not from step to step (three sincos a step otherwise).
struct Turn {
  double gamma = std::numeric_limits<double>::quiet_NaN(), c = 1.0, s = 0.0;
  void at(double g) {
    if (g == gamma) return;
    gamma = g;
    c = std::cos(g);
    s = std::sin(g);
  }
};

// propagateFixed(): a row with a constant rotation gamma; turn is the row's own memory.
template <int J>
void fixedRow(Frame& f, Turn& turn, double gamma, double lambda, double beta, bool bodyAccel) {
  if (bodyAccel && lambda != 0.0) addLever<J>(f.acc, f.w, f.wd, lambda);
  if (gamma == 0.0 && beta == 0.0) return;
  turn.at(gamma);
  frameToChild<J>(f, turn.c, turn.s, beta, -1, bodyAccel);
}

// A position and its derivatives with respect to the five angles.
struct Point {
  Eigen::Vector3d v;
  Eigen::Matrix<double, 3, kNumJoints> d = Eigen::Matrix<double, 3, kNumJoints>::Zero();
};

// detail::toParent with derivatives: Rz(gamma) Rx(beta) p; joint as in toChild.
Point toParent(const Point& p, double c, double s, double beta, int joint) {
  double y = p.v(1), z = p.v(2);
  Eigen::Matrix<double, 1, kNumJoints> dy = p.d.row(1), dz = p.d.row(2);
  if (beta == kHalfPi) {
    y = -p.v(2);
    z = p.v(1);
    dy = -p.d.row(2);
    dz = p.d.row(1);
  } else if (beta == -kHalfPi) {
    y = p.v(2);
    z = -p.v(1);
    dy = p.d.row(2);
    dz = -p.d.row(1);
  } else if (beta != 0.0) {
    const double cb = std::cos(beta), sb = std::sin(beta);
    y = cb * p.v(1) - sb * p.v(2);
    z = sb * p.v(1) + cb * p.v(2);
    dy = cb * p.d.row(1) - sb * p.d.row(2);
    dz = sb * p.d.row(1) + cb * p.d.row(2);
  }
  Point out;
  out.v = Eigen::Vector3d(c * p.v(0) - s * y, s * p.v(0) + c * y, z);
  out.d.row(0) = c * p.d.row(0) - s * dy;
  out.d.row(1) = s * p.d.row(0) + c * dy;
  out.d.row(2) = dz;
  if (joint >= 0) {
    out.d(0, joint) -= out.v(1);
    out.d(1, joint) += out.v(0);
  }
  return out;
}

// One IMU's gyroscope and accelerometer rows of h and jac, from its frame after J joints.
template <int J>
void imuRows(const Frame& f, bool bodyAccel, int row, ModelReadings& h, ModelJacobian* jac) {
  h.segment<3>(row) = f.w.v;
  h.segment<3>(row + 3) = bodyAccel ? Eigen::Vector3d(f.up.v + f.acc.v) : f.up.v;
  if (!jac) return;
  auto gyr = jac->middleRows<3>(row);
  auto acc = jac->middleRows<3>(row + 3);
  gyr.setZero();
  acc.setZero();
  for (int j = 0; j < J; ++j) {
    gyr.col(kNumJoints + j) = f.w.d.col(3 * j + 1);
    gyr.col(2 * kNumJoints + j) = f.w.d.col(3 * j + 2);
    acc.col(2 * kNumJoints + j) = f.up.d.col(j);
    if (!bodyAccel) continue;
    acc.col(j) = f.acc.d.col(3 * j);
    acc.col(kNumJoints + j) = f.acc.d.col(3 * j + 1);
    acc.col(2 * kNumJoints + j) += f.acc.d.col(3 * j + 2);
  }
}

}  // namespace

void predictReadings(const ArmGeometry& geo, const Eigen::Vector3d& gUp, bool bodyAccel,
                     const Eigen::Matrix<double, kMeasurementStates, 1>& x, ModelReadings& h,
                     ModelJacobian* jac, bool positions) {
  FrameState<double> base;
  base.up = gUp;
  predictReadings(geo, base, bodyAccel, x, h, jac, positions);
}

void predictReadings(const ArmGeometry& geo, const FrameState<double>& base, bool bodyAccel,
                     const Eigen::Matrix<double, kMeasurementStates, 1>& x, ModelReadings& h,
                     ModelJacobian* jac, bool positions) {
  const auto thdd = x.segment<5>(0);
  const auto thd = x.segment<5>(5);
  const auto th = x.segment<5>(10);
  // The rows of armKinematics(), in its order and with its arithmetic.
  const double c1 = std::cos(th(0)), s1 = std::sin(th(0));
  const double c2 = -std::sin(th(1)), s2 = std::cos(th(1));  // of th1 + pi/2
  const double c3 = std::cos(th(2)), s3 = std::sin(th(2));
  const double c5 = std::cos(th(3)), s5 = std::sin(th(3));
  const double c6 = std::cos(th(4)), s6 = std::sin(th(4));

  // One frame carried down the chain in place; the forearm's branch starts from a copy at
  // frame 3.
  Frame f;  // frame 0: still, or moving with the trunk (constants: no derivatives)
  f.w.v = base.omega;
  f.wd.v = base.omegaDot;
  f.acc.v = base.accel;
  f.up.v = base.up;
  jointRow<1>(f, c1, s1, thd(0), thdd(0), kHalfPi, bodyAccel);
  jointRow<2>(f, c2, s2, thd(1), thdd(1), kHalfPi, bodyAccel);
  jointRow<3>(f, c3, s3, thd(2), thdd(2), 0.0, bodyAccel);
  Frame fa = f;

  // Upper-arm IMU, Table 1 rows 4-6.
  thread_local std::array<Turn, 7> turns;  // one per fixed row below
  fixedRow<3>(f, turns[0], 0.0, geo.lu3, 0.0, bodyAccel);
  fixedRow<3>(f, turns[1], geo.thu4, 0.0, kHalfPi, bodyAccel);
  fixedRow<3>(f, turns[2], 0.0, geo.lu5, 0.0, bodyAccel);
  imuRows<3>(f, bodyAccel, 0, h, jac);
  // Forearm IMU, Table 3 rows 4-9.
  fixedRow<3>(fa, turns[3], kHalfPi, geo.l3, -kHalfPi, bodyAccel);
  jointRow<4>(fa, c5, s5, thd(3), thdd(3), kHalfPi, bodyAccel);
  jointRow<5>(fa, c6, s6, thd(4), thdd(4), 0.0, bodyAccel);
  fixedRow<5>(fa, turns[4], 0.0, geo.lf6, 0.0, bodyAccel);
  fixedRow<5>(fa, turns[5], geo.thf7 + kHalfPi, 0.0, kHalfPi, bodyAccel);
  fixedRow<5>(fa, turns[6], 0.0, geo.lf8, 0.0, bodyAccel);
  imuRows<5>(fa, bodyAccel, 6, h, jac);
  if (!positions) return;
  // Elbow and wrist (eq. 11), carried back to frame 0 row by row.
  Point v, e;
  v.v = Eigen::Vector3d(0.0, 0.0, geo.l6);
  v = toParent(v, c6, s6, 0.0, 4);
  v = toParent(v, c5, s5, kHalfPi, 3);
  v = toParent(v, 0.0, 1.0, -kHalfPi, -1);  // row 4: gamma = pi/2 ...
  v.v(2) += geo.l3;                         // ... and its translation l3 along z3
  e.v = Eigen::Vector3d(0.0, 0.0, geo.l3);
  v = toParent(v, c3, s3, 0.0, 2);
  e = toParent(e, c3, s3, 0.0, 2);
  v = toParent(v, c2, s2, kHalfPi, 1);
  e = toParent(e, c2, s2, kHalfPi, 1);
  v = toParent(v, c1, s1, kHalfPi, 0);
  e = toParent(e, c1, s1, kHalfPi, 0);
  h.segment<3>(12) = e.v;
  h.segment<3>(15) = v.v;
  if (!jac) return;
  jac->bottomRows<6>().leftCols<2 * kNumJoints>().setZero();
  jac->block<3, kNumJoints>(12, 2 * kNumJoints) = e.d;
  jac->block<3, kNumJoints>(15, 2 * kNumJoints) = v.d;
}

}  // namespace armtrack
