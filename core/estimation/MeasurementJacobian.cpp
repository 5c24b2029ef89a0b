#include "core/estimation/MeasurementJacobian.h"

#include <cmath>

namespace armtrack {

namespace {

constexpr double kHalfPi = detail::kHalfPi;

// A 3-vector and its derivatives with respect to the accelerations (dA), rates (dR) and angles
// (dT) of the first J joints: the joints after a frame do not move it.
template <int J>
struct Tangent {
  using Block = Eigen::Matrix<double, 3, J>;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  Block dA = Block::Zero(), dR = Block::Zero(), dT = Block::Zero();
};

// FrameState (ArmModel.h) with derivatives.
template <int J>
struct Frame {
  Tangent<J> w, wd, acc, up;
};

template <int J>
Tangent<J + 1> widen(const Tangent<J>& t) {
  Tangent<J + 1> out;
  out.v = t.v;
  out.dA.template leftCols<J>() = t.dA;
  out.dR.template leftCols<J>() = t.dR;
  out.dT.template leftCols<J>() = t.dT;
  return out;
}

// The frame with room for one more joint, which does not move it.
template <int J>
Frame<J + 1> widen(const Frame<J>& f) {
  return {widen(f.w), widen(f.wd), widen(f.acc), widen(f.up)};
}

// Row i of every derivative block of out = a * row ia of p + b * row ib of q.
template <int J>
void combineRow(Tangent<J>& out, int i, double a, const Tangent<J>& p, int ia, double b,
                const Tangent<J>& q, int ib) {
  out.dA.row(i) = a * p.dA.row(ia) + b * q.dA.row(ib);
  out.dR.row(i) = a * p.dR.row(ia) + b * q.dR.row(ib);
  out.dT.row(i) = a * p.dT.row(ia) + b * q.dT.row(ib);
}

// Row i of every derivative block of out = row k of p, negated when negate.
template <int J>
void copyRow(Tangent<J>& out, int i, const Tangent<J>& p, int k, bool negate) {
  if (negate) {
    out.dA.row(i) = -p.dA.row(k);
    out.dR.row(i) = -p.dR.row(k);
    out.dT.row(i) = -p.dT.row(k);
  } else {
    out.dA.row(i) = p.dA.row(k);
    out.dR.row(i) = p.dR.row(k);
    out.dT.row(i) = p.dT.row(k);
  }
}

// detail::toChild with derivatives: Rx(-beta) Rz(-gamma) v, with c, s the cosine and sine of
// gamma. joint >= 0 when gamma is that joint's angle (plus a constant): then dc = -s dth and
// ds = c dth.
template <int J>
Tangent<J> toChild(const Tangent<J>& t, double c, double s, double beta, int joint) {
  Tangent<J> r;  // rows: x, y, z before the Rx turn
  const double x = c * t.v(0) + s * t.v(1);
  const double y = c * t.v(1) - s * t.v(0);
  combineRow(r, 0, c, t, 0, s, t, 1);
  combineRow(r, 1, c, t, 1, -s, t, 0);
  if (joint >= 0) {
    r.dT(0, joint) += y;
    r.dT(1, joint) -= x;
  }
  r.v = Eigen::Vector3d(x, y, t.v(2));
  copyRow(r, 2, t, 2, false);
  if (beta == 0.0) return r;
  Tangent<J> out;
  out.v(0) = r.v(0);
  copyRow(out, 0, r, 0, false);
  if (beta == kHalfPi) {  // (x, z, -y)
    out.v(1) = r.v(2);
    out.v(2) = -r.v(1);
    copyRow(out, 1, r, 2, false);
    copyRow(out, 2, r, 1, true);
  } else if (beta == -kHalfPi) {  // (x, -z, y)
    out.v(1) = -r.v(2);
    out.v(2) = r.v(1);
    copyRow(out, 1, r, 2, true);
    copyRow(out, 2, r, 1, false);
  } else {
    const double cb = std::cos(beta), sb = std::sin(beta);
    out.v(1) = cb * r.v(1) + sb * r.v(2);
    out.v(2) = cb * r.v(2) - sb * r.v(1);
    combineRow(out, 1, cb, r, 1, sb, r, 2);
    combineRow(out, 2, cb, r, 2, -sb, r, 1);
  }
  return out;
}

// The lever term of propagate() for a translation lambda along the parent's z, added to acc:
// w.' x lambda k + w' x (w' x lambda k), from the parent's w' and w.'.
template <int J>
void addLever(Tangent<J>& acc, const Tangent<J>& w0, const Tangent<J>& wd0, double lambda) {
  const Eigen::Vector3d& w = w0.v;
  acc.v(0) += lambda * (wd0.v(1) + w(0) * w(2));
  acc.v(1) += lambda * (w(1) * w(2) - wd0.v(0));
  acc.v(2) -= lambda * (w(0) * w(0) + w(1) * w(1));
  using Block = typename Tangent<J>::Block;
  const auto lever = [&](Block Tangent<J>::*block) {
    const auto& dw = w0.*block;
    const auto& dwd = wd0.*block;
    auto& da = acc.*block;
    da.row(0) += lambda * (dwd.row(1) + w(0) * dw.row(2) + w(2) * dw.row(0));
    da.row(1) += lambda * (w(1) * dw.row(2) + w(2) * dw.row(1) - dwd.row(0));
    da.row(2) -= (2.0 * lambda) * (w(0) * dw.row(0) + w(1) * dw.row(1));
  };
  lever(&Tangent<J>::dA);
  lever(&Tangent<J>::dR);
  lever(&Tangent<J>::dT);
}

// propagate() (ArmModel.h) for a row whose rotation is joint j's angle, with its rate rate and
// acceleration accel; no Tx offset (every row of the tables has delta = 0).
template <int J>
Frame<J> jointRow(const Frame<J>& p, int j, double c, double s, double rate, double accel,
                  double lambda, double beta) {
  Tangent<J> w = p.w;
  w.v(2) += rate;
  w.dR(2, j) += 1.0;
  Tangent<J> wd;
  wd.v =
      Eigen::Vector3d(p.wd.v(0) + p.w.v(1) * rate, p.wd.v(1) - p.w.v(0) * rate, p.wd.v(2) + accel);
  combineRow(wd, 0, 1.0, p.wd, 0, rate, p.w, 1);
  combineRow(wd, 1, 1.0, p.wd, 1, -rate, p.w, 0);
  copyRow(wd, 2, p.wd, 2, false);
  wd.dR(0, j) += p.w.v(1);
  wd.dR(1, j) -= p.w.v(0);
  wd.dA(2, j) += 1.0;
  Tangent<J> acc = p.acc;
  if (lambda != 0.0) addLever(acc, p.w, p.wd, lambda);
  return {toChild(w, c, s, beta, j), toChild(wd, c, s, beta, j), toChild(acc, c, s, beta, j),
          toChild(p.up, c, s, beta, j)};
}

// propagateFixed(): a row with a constant rotation gamma.
template <int J>
Frame<J> fixedRow(const Frame<J>& p, double gamma, double lambda, double beta) {
  Tangent<J> acc = p.acc;
  if (lambda != 0.0) addLever(acc, p.w, p.wd, lambda);
  if (gamma == 0.0 && beta == 0.0) return {p.w, p.wd, acc, p.up};
  const double c = std::cos(gamma), s = std::sin(gamma);
  return {toChild(p.w, c, s, beta, -1), toChild(p.wd, c, s, beta, -1), toChild(acc, c, s, beta, -1),
          toChild(p.up, c, s, beta, -1)};
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

// One IMU's gyroscope and accelerometer rows of h and jac, from its frame.
template <int J>
void imuRows(const Frame<J>& f, bool bodyAccel, int row, ModelReadings& h, ModelJacobian* jac) {
  h.segment<3>(row) = f.w.v;
  h.segment<3>(row + 3) = bodyAccel ? Eigen::Vector3d(f.up.v + f.acc.v) : f.up.v;
  if (!jac) return;
  auto gyr = jac->middleRows<3>(row);
  gyr.setZero();
  gyr.leftCols<J>() = f.w.dA;
  gyr.middleCols<J>(kNumJoints) = f.w.dR;
  gyr.middleCols<J>(2 * kNumJoints) = f.w.dT;
  auto acc = jac->middleRows<3>(row + 3);
  acc.setZero();
  acc.middleCols<J>(2 * kNumJoints) = f.up.dT;
  if (!bodyAccel) return;
  acc.leftCols<J>() = f.acc.dA;
  acc.middleCols<J>(kNumJoints) = f.acc.dR;
  acc.middleCols<J>(2 * kNumJoints) += f.acc.dT;
}

}  // namespace

void predictReadings(const ArmGeometry& geo, const Eigen::Vector3d& gUp, bool bodyAccel,
                     const Eigen::Matrix<double, kMeasurementStates, 1>& x, ModelReadings& h,
                     ModelJacobian* jac) {
  const auto thdd = x.segment<5>(0);
  const auto thd = x.segment<5>(5);
  const auto th = x.segment<5>(10);
  // The rows of armKinematics(), in its order and with its arithmetic.
  const double c1 = std::cos(th(0)), s1 = std::sin(th(0));
  const double c2 = -std::sin(th(1)), s2 = std::cos(th(1));  // of th1 + pi/2
  const double c3 = std::cos(th(2)), s3 = std::sin(th(2));
  const double c5 = std::cos(th(3)), s5 = std::sin(th(3));
  const double c6 = std::cos(th(4)), s6 = std::sin(th(4));

  Frame<1> f0;
  f0.up.v = gUp;
  const Frame<1> f1 = jointRow(f0, 0, c1, s1, thd(0), thdd(0), 0.0, kHalfPi);
  const Frame<2> f2 = jointRow(widen(f1), 1, c2, s2, thd(1), thdd(1), 0.0, kHalfPi);
  const Frame<3> f3 = jointRow(widen(f2), 2, c3, s3, thd(2), thdd(2), 0.0, 0.0);

  // Upper-arm IMU, Table 1 rows 4-6.
  {
    const Frame<3> u4 = fixedRow(f3, 0.0, geo.lu3, 0.0);
    const Frame<3> u5 = fixedRow(u4, geo.thu4, 0.0, kHalfPi);
    imuRows(fixedRow(u5, 0.0, geo.lu5, 0.0), bodyAccel, 0, h, jac);
  }
  // Forearm IMU, Table 3 rows 4-9.
  {
    const Frame<3> e4 = fixedRow(f3, kHalfPi, geo.l3, -kHalfPi);
    const Frame<4> e5 = jointRow(widen(e4), 3, c5, s5, thd(3), thdd(3), 0.0, kHalfPi);
    const Frame<5> e6 = jointRow(widen(e5), 4, c6, s6, thd(4), thdd(4), 0.0, 0.0);
    const Frame<5> f7 = fixedRow(e6, 0.0, geo.lf6, 0.0);
    const Frame<5> f8 = fixedRow(f7, geo.thf7 + kHalfPi, 0.0, kHalfPi);
    imuRows(fixedRow(f8, 0.0, geo.lf8, 0.0), bodyAccel, 6, h, jac);
  }
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
