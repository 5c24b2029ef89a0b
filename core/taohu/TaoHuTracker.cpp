#include "core/taohu/TaoHuTracker.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <unsupported/Eigen/LevenbergMarquardt>

#include "core/metrics/Accuracy.h"

namespace armtrack {

namespace {

constexpr int kS = 0;    // sensor position, 3 states
constexpr int kV = 3;    // velocity, 3 states
constexpr int kPsi = 6;  // heading offset
constexpr double kDegToRad = std::numbers::pi / 180.0;

bool finite(const Eigen::Ref<const Eigen::VectorXd>& v) {
  return v.allFinite();
}

// The LM problem of one camera frame (eqs. 13.4-13.5, extended): unknowns x = [s (3), psi], the
// forearm IMU position and the heading offset. Marker points are s + Rot(psi) Rfw c. Residuals,
// each divided by its std: marker pixels, the elbow sphere (|e|^2 - l3^2) / (2 l3), and a
// Gaussian prior L (x - mu).
struct FrameProblem : Eigen::DenseFunctor<double> {
  const PinholeCamera* camera = nullptr;
  bool left = false;
  Eigen::Vector3d up;     // rotation axis of psi
  Eigen::Matrix3d align;  // filter world -> shoulder at psi = 0
  Eigen::Matrix3d Rfw;    // sensor -> filter world
  double l3 = 0, sphereStd = 0, pixelStd = 0;
  std::optional<Eigen::Vector2d> wristPx, elbowPx;
  Eigen::Vector3d offWrist, offElbow;
  bool hasPrior = false;
  Eigen::Vector4d mu;
  Eigen::Matrix4d L;  // inverse Cholesky factor of the prior covariance

  FrameProblem(int values) : Eigen::DenseFunctor<double>(4, values) {}

  static int countValues(bool wrist, bool elbow, bool prior) {
    return 2 * wrist + 2 * elbow + 1 + (prior ? 4 : 0);
  }

  Eigen::Matrix3d rotation(double psi) const {
    return Eigen::AngleAxisd(psi, up).toRotationMatrix() * align * Rfw;
  }

  // Point and its 3x4 Jacobian.
  void point(const InputType& x, const Eigen::Vector3d& off, Eigen::Vector3d& p,
             Eigen::Matrix<double, 3, 4>& dp) const {
    const Eigen::Vector3d r = rotation(x(3)) * off;
    p = x.head<3>() + r;
    dp.leftCols<3>().setIdentity();
    dp.col(3) = up.cross(r);
  }

  bool pixel(const Eigen::Vector3d& p, const Eigen::Matrix<double, 3, 4>& dp, Eigen::Vector2d& px,
             Eigen::Matrix<double, 2, 4>& J) const {
    Eigen::Matrix<double, 2, 3> jc;
    if (!camera->project(left ? mirrorPoint(p) : p, px, jc)) return false;
    if (left) jc.col(2) = -jc.col(2);
    J = jc * dp;
    return true;
  }

  int evaluate(const InputType& x, ValueType* f, JacobianType* jac) const {
    int row = 0;
    Eigen::Vector3d p;
    Eigen::Matrix<double, 3, 4> dp;
    Eigen::Vector2d px;
    Eigen::Matrix<double, 2, 4> J;
    for (const auto& [z, off] : {std::pair{&wristPx, &offWrist}, std::pair{&elbowPx, &offElbow}}) {
      if (!*z) continue;
      point(x, *off, p, dp);
      if (!pixel(p, dp, px, J)) return -1;
      if (f) f->segment<2>(row) = (px - **z) / pixelStd;
      if (jac) jac->block<2, 4>(row, 0) = J / pixelStd;
      row += 2;
    }
    point(x, offElbow, p, dp);
    const double scale = 1.0 / (2.0 * l3 * sphereStd);
    if (f) (*f)(row) = (p.squaredNorm() - l3 * l3) * scale;
    if (jac) jac->row(row) = 2.0 * scale * p.transpose() * dp;
    ++row;
    if (hasPrior) {
      if (f) f->segment<4>(row) = L * (x - mu);
      if (jac) jac->block<4, 4>(row, 0) = L;
    }
    return 0;
  }
  int operator()(const InputType& x, ValueType& f) const { return evaluate(x, &f, nullptr); }
  int df(const InputType& x, JacobianType& jac) const { return evaluate(x, nullptr, &jac); }
};

FrameProblem makeFrameProblem(const PinholeCamera& camera, const TaoHuParams& p,
                              const Eigen::Vector3d& up, const Eigen::Matrix3d& align,
                              const Eigen::Matrix3d& Rfw, const Eigen::Vector3d& offWrist,
                              const Eigen::Vector3d& offElbow, std::optional<Eigen::Vector2d> wrist,
                              std::optional<Eigen::Vector2d> elbow, bool prior) {
  FrameProblem problem(FrameProblem::countValues(wrist.has_value(), elbow.has_value(), prior));
  problem.camera = &camera;
  problem.left = p.side == Side::Left;
  problem.up = up;
  problem.align = align;
  problem.Rfw = Rfw;
  problem.l3 = p.geometry.l3;
  problem.sphereStd = p.sphereStdLm;
  problem.pixelStd = p.pixelStd;
  problem.wristPx = wrist;
  problem.elbowPx = elbow;
  problem.offWrist = offWrist;
  problem.offElbow = offElbow;
  problem.hasPrior = prior;
  return problem;
}

// Runs the LM; returns whether it converged, with x the solution and cost the final 0.5 |f|^2.
bool solve(FrameProblem& problem, Eigen::VectorXd& x, double& cost) {
  Eigen::LevenbergMarquardt<FrameProblem> lm(problem);
  lm.setXtol(1e-12);
  lm.setFtol(1e-12);
  lm.setMaxfev(100);
  const Eigen::LevenbergMarquardtSpace::Status status = lm.minimize(x);
  using namespace Eigen::LevenbergMarquardtSpace;
  const bool ok = status == RelativeReductionTooSmall || status == RelativeErrorTooSmall ||
                  status == RelativeErrorAndReductionTooSmall || status == CosinusTooSmall ||
                  status == FtolTooSmall || status == XtolTooSmall || status == GtolTooSmall;
  cost = 0.5 * lm.fnorm() * lm.fnorm();
  return ok && x.allFinite();
}

}  // namespace

TaoHuParams taoHuParams(const RecordingMeta& meta) {
  if (!meta.camera)
    throw std::invalid_argument("the recording has no camera block (webcam marker pixels)");
  TaoHuParams p;
  p.geometry = meta.geometry;
  p.up = meta.up;
  p.g = meta.g;
  p.side = meta.side;
  p.camera = *meta.camera;
  return p;
}

TaoHuTracker::TaoHuTracker(const TaoHuParams& params)
    : m_p(params), m_camera(params.camera), m_orient(params.orientation) {
  if (!(m_p.pixelStd > 0) || !(m_p.accelNoiseDensity > 0) || !(m_p.headingNoiseDensity >= 0) ||
      !(m_p.sphereStdEkf >= 0) || !(m_p.sphereStdLm > 0) || !(m_p.gateChi2 > 0) ||
      !(m_p.up.norm() > 0.5) || !std::isfinite(m_p.g) || !(m_p.geometry.l3 > 0))
    throw std::invalid_argument(
        "TaoHuTracker: noise parameters must be positive, up a unit vector");
  const Eigen::Vector3d up = m_p.up.normalized();
  m_up = m_p.side == Side::Left ? mirrorPoint(up) : up;
  m_align = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), m_up).toRotationMatrix();
  // Wrist and elbow lie on the forearm's axis, so their positions in the IMU frame do not depend
  // on the joint angles; take them at the zero pose.
  const ArmPose pose = forwardKinematics(m_p.geometry, JointVector::Zero());
  const Eigen::Matrix3d R9 = pose.forearmImu.topLeftCorner<3, 3>();
  const Eigen::Vector3d p9 = pose.forearmImu.topRightCorner<3, 1>();
  m_offWrist = R9.transpose() * (pose.wrist - p9);
  m_offElbow = R9.transpose() * (pose.elbow - p9);
  reset();
}

void TaoHuTracker::reset() {
  m_s = TaoHuState{};
  m_orient.reset();
  m_Rfw.setIdentity();
  m_frame = TaoHuFrame{};
}

Eigen::Matrix3d TaoHuTracker::headingRotation(double psi) const {
  return Eigen::AngleAxisd(psi, m_up).toRotationMatrix() * m_align;
}

Eigen::Matrix3d TaoHuTracker::forearmRotation() const {
  return headingRotation(m_s.x(kPsi)) * m_Rfw;
}

TaoHuStatus TaoHuTracker::update(const ArmSample& sample) {
  TaoHuCounters& c = m_s.counters;
  ++c.samples;
  const bool bad =
      !std::isfinite(sample.t) ||
      (sample.forearm && (!finite(sample.forearm->gyr) || !finite(sample.forearm->acc))) ||
      (sample.camWrist && !finite(*sample.camWrist)) ||
      (sample.camElbow && !finite(*sample.camElbow));
  if (bad) {
    ++c.rejectedNonFinite;
    return TaoHuStatus::Rejected;
  }
  if (m_s.seen && sample.t < m_s.tLast) {
    ++c.rejectedTime;
    return TaoHuStatus::Rejected;
  }
  m_s.seen = true;
  m_s.tLast = sample.t;
  const double t = sample.t;

  if (sample.forearm) {
    const ImuReading r = m_p.side == Side::Left ? mirrorImu(*sample.forearm) : *sample.forearm;
    const bool gap = m_s.imuSeen && t - m_s.tLastImu > m_p.maxImuGapSeconds;
    if (gap) {
      // The orientation is lost over a long gap too: start again, warm-up included.
      if (m_s.initialised) restart();
      m_orient.reset();
    }
    if (!m_s.imuSeen || gap) {
      m_s.imuSeen = true;
      m_s.tFirstImu = m_s.tLastImu = t;
      ++c.imuSamples;
    } else if (t > m_s.tLastImu) {
      const double dt = t - m_s.tLastImu;
      m_orient.update(r.gyr, r.acc, dt);
      m_Rfw = m_orient.orientation().toRotationMatrix();
      if (m_s.initialised) predictTo(t);  // with the previous sample's acceleration
      m_s.accWorld = m_Rfw * r.acc;
      m_s.tLastImu = t;
      ++c.imuSamples;
    } else {
      ++c.rejectedTime;  // a second forearm reading at the same instant
    }
  }

  if (!sample.camWrist && !sample.camElbow)
    return m_s.initialised ? TaoHuStatus::Tracking : TaoHuStatus::Waiting;
  ++c.cameraFrames;
  if (!m_s.initialised) {
    if (!m_s.imuSeen || t - m_s.tFirstImu < m_p.warmupSeconds) return TaoHuStatus::Waiting;
    return initialise(sample) ? TaoHuStatus::Frame : TaoHuStatus::Waiting;
  }
  predictTo(t);
  cameraUpdate(sample);
  return TaoHuStatus::Frame;
}

void TaoHuTracker::restart() {
  m_s.initialised = false;
  m_s.gatedInARow = 0;
  ++m_s.counters.restarts;
}

void TaoHuTracker::predictTo(double t) {
  const double dt = t - m_s.tEkf;
  if (!(dt > 0)) return;
  predict(m_s.x, m_s.P, dt);
  m_s.tEkf = t;
}

void TaoHuTracker::predict(TaoHuState::Vec7& x, TaoHuState::Mat7& P, double dt) const {
  using Mat7 = TaoHuState::Mat7;
  const Eigen::Vector3d aRot = headingRotation(x(kPsi)) * m_s.accWorld;
  const Eigen::Vector3d a = aRot - m_p.g * m_up;  // eq. 13.2's a = q a^B q' - g
  x.segment<3>(kS) += x.segment<3>(kV) * dt + 0.5 * a * dt * dt;
  x.segment<3>(kV) += a * dt;
  const Eigen::Vector3d da = m_up.cross(aRot);  // d a / d psi
  Mat7 F = Mat7::Identity();
  F.block<3, 3>(kS, kV).diagonal().setConstant(dt);
  F.block<3, 1>(kS, kPsi) = 0.5 * dt * dt * da;
  F.block<3, 1>(kV, kPsi) = dt * da;
  Mat7 Q = Mat7::Zero();
  const double q = m_p.accelNoiseDensity;
  Q.block<3, 3>(kS, kS).diagonal().setConstant(q * dt * dt * dt / 3.0);
  Q.block<3, 3>(kS, kV).diagonal().setConstant(q * dt * dt / 2.0);
  Q.block<3, 3>(kV, kS).diagonal().setConstant(q * dt * dt / 2.0);
  Q.block<3, 3>(kV, kV).diagonal().setConstant(q * dt);
  Q(kPsi, kPsi) = m_p.headingNoiseDensity * dt;
  P = F * P * F.transpose() + Q;
}

TaoHuTracker::Fuse TaoHuTracker::fuseMarker(TaoHuState::Vec7& x, TaoHuState::Mat7& P,
                                            const Eigen::Vector2d& z,
                                            const Eigen::Vector3d& offset) const {
  const Eigen::Vector3d r = headingRotation(x(kPsi)) * m_Rfw * offset;
  const Eigen::Vector3d p = x.segment<3>(kS) + r;
  const bool left = m_p.side == Side::Left;
  Eigen::Vector2d h;
  Eigen::Matrix<double, 2, 3> jc;
  if (!m_camera.project(left ? mirrorPoint(p) : p, h, jc)) return Fuse::NotVisible;
  if (left) jc.col(2) = -jc.col(2);
  Eigen::Matrix<double, 2, 7> H = Eigen::Matrix<double, 2, 7>::Zero();
  H.block<2, 3>(0, kS) = jc;
  H.col(kPsi) = jc * m_up.cross(r);
  const Eigen::Vector2d y = z - h;
  const Eigen::Matrix2d S =
      H * P * H.transpose() + Eigen::Matrix2d::Identity() * (m_p.pixelStd * m_p.pixelStd);
  const Eigen::Matrix2d Sinv = S.inverse();
  if (!(y.dot(Sinv * y) <= m_p.gateChi2)) return Fuse::Gated;
  const Eigen::Matrix<double, 7, 2> K = P * H.transpose() * Sinv;
  x += K * y;
  const TaoHuState::Mat7 IKH = TaoHuState::Mat7::Identity() - K * H;
  P = IKH * P * IKH.transpose() + K * K.transpose() * (m_p.pixelStd * m_p.pixelStd);  // Joseph form
  return Fuse::Fused;
}

void TaoHuTracker::fuseSphere(TaoHuState::Vec7& x, TaoHuState::Mat7& P) const {
  const Eigen::Vector3d r = headingRotation(x(kPsi)) * m_Rfw * m_offElbow;
  const Eigen::Vector3d e = x.segment<3>(kS) + r;
  const double n = e.norm();
  if (!(n > 1e-6)) return;
  Eigen::Matrix<double, 1, 7> H = Eigen::Matrix<double, 1, 7>::Zero();
  H.block<1, 3>(0, kS) = e.transpose() / n;
  H(kPsi) = e.dot(m_up.cross(r)) / n;
  const double R = m_p.sphereStdEkf * m_p.sphereStdEkf;
  const double S = (H * P * H.transpose())(0) + R;
  const Eigen::Matrix<double, 7, 1> K = P * H.transpose() / S;
  x += K * (m_p.geometry.l3 - n);
  const TaoHuState::Mat7 IKH = TaoHuState::Mat7::Identity() - K * H;
  P = IKH * P * IKH.transpose() + K * K.transpose() * R;
}

bool TaoHuTracker::initialise(const ArmSample& s) {
  TaoHuCounters& c = m_s.counters;
  if (!s.camWrist || !s.camElbow) return false;  // the alignment needs both markers
  const bool left = m_p.side == Side::Left;
  Eigen::Vector3d origin, dir;
  m_camera.ray(*s.camElbow, origin, dir);
  if (left) {
    origin = mirrorPoint(origin);
    dir = mirrorPoint(dir);
  }
  // The elbow ray meets the sphere |e| = l3 twice: a near and a far depth branch (or, missing
  // it, comes closest once).
  const double l3 = m_p.geometry.l3;
  const double b = origin.dot(dir);
  const double disc = b * b - origin.squaredNorm() + l3 * l3;
  const double root = std::sqrt(std::max(disc, 0.0));
  const std::array<Eigen::Vector3d, 2> elbow0{origin + (-b - root) * dir,
                                              origin + (-b + root) * dir};

  FrameProblem problem = makeFrameProblem(m_camera, m_p, m_up, m_align, m_Rfw, m_offWrist,
                                          m_offElbow, *s.camWrist, *s.camElbow, false);
  // The heading is unknown: 12 starts 30 deg apart on each branch. Keep the fits that explain the
  // pixels, one per distinct solution.
  std::vector<std::pair<double, Eigen::Vector4d>> fits;
  for (const Eigen::Vector3d& e0 : elbow0) {
    for (int k = 0; k < 12; ++k) {
      const double psi = wrapAngle(k * 30.0 * kDegToRad);
      Eigen::VectorXd x(4);
      x.head<3>() = e0 - headingRotation(psi) * m_Rfw * m_offElbow;
      x(3) = psi;
      double cost = 0;
      if (!solve(problem, x, cost)) continue;
      // 0.5 (squared pixel residuals in std units + sphere term), over 4 pixel values.
      const double rmsPx = std::sqrt(2.0 * cost / 4.0) * m_p.pixelStd;
      if (!(rmsPx <= m_p.initMaxRmsPx)) continue;
      x(3) = wrapAngle(x(3));
      const bool known = std::any_of(fits.begin(), fits.end(), [&](const auto& f) {
        return (f.second.template head<3>() - x.head<3>()).norm() < 0.005;
      });
      if (!known) fits.emplace_back(cost, x);
    }
  }
  if (fits.empty()) {
    ++c.initFailures;
    return false;
  }
  std::sort(fits.begin(), fits.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  // One frame fixes depth and heading only loosely: a camera 2 m away sees an almost orthographic
  // image, so the two depth branches often fit about equally well. When the runner-up fits within
  // the chi-square spread of the best, start between them with a covariance that spans both and
  // let the motion decide; else start at the best.
  Eigen::Vector4d mean = fits[0].second;
  Eigen::Matrix4d spread = Eigen::Matrix4d::Zero();
  if (fits.size() > 1 && fits[1].first - fits[0].first < 0.5 * m_p.initBranchChi2) {
    const Eigen::Vector4d half = 0.5 * (fits[1].second - fits[0].second);
    mean += half;
    spread = half * half.transpose();
    ++c.ambiguousStarts;
  }
  m_s.x.setZero();
  m_s.x.segment<3>(kS) = mean.head<3>();
  m_s.x(kPsi) = wrapAngle(mean(3));
  m_s.P.setZero();
  m_s.P.block<3, 3>(kS, kS).diagonal().setConstant(0.02 * 0.02);
  m_s.P.block<3, 3>(kV, kV).diagonal().setConstant(0.5 * 0.5);
  m_s.P(kPsi, kPsi) = std::pow(5.0 * kDegToRad, 2);
  const std::array<int, 4> idx{kS, kS + 1, kS + 2, kPsi};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m_s.P(idx[i], idx[j]) += spread(i, j);
  m_s.tEkf = s.t;
  m_s.initialised = true;
  m_s.gatedInARow = 0;
  ++c.initialisations;
  makeFrame(s.t, true);
  return true;
}

void TaoHuTracker::cameraUpdate(const ArmSample& s) {
  TaoHuCounters& c = m_s.counters;
  const TaoHuState::Vec7 xPred = m_s.x;
  const TaoHuState::Mat7 PPred = m_s.P;

  bool wristOk = false, elbowOk = false;
  const auto count = [&](Fuse f, std::size_t& fused, std::size_t& gated) {
    if (f == Fuse::Fused) ++fused;
    if (f == Fuse::Gated) ++gated;
    if (f == Fuse::NotVisible) ++c.notVisible;
    return f == Fuse::Fused;
  };
  const bool useElbow = s.camElbow && m_p.useElbowPixels;
  if (s.camWrist)
    wristOk =
        count(fuseMarker(m_s.x, m_s.P, *s.camWrist, m_offWrist), c.wristUpdates, c.wristGated);
  if (useElbow)
    elbowOk =
        count(fuseMarker(m_s.x, m_s.P, *s.camElbow, m_offElbow), c.elbowUpdates, c.elbowGated);
  if (m_p.sphereStdEkf > 0) fuseSphere(m_s.x, m_s.P);
  m_s.x(kPsi) = wrapAngle(m_s.x(kPsi));

  if (!wristOk && !elbowOk) {
    makeFrame(s.t, false);
    if (++m_s.gatedInARow >= m_p.maxGatedFrames) restart();
    return;
  }
  m_s.gatedInARow = 0;

  // LM refinement: the accepted pixels, the sphere, and the EKF prediction as a prior; started
  // from the EKF's corrected state.
  const std::array<int, 4> idx{kS, kS + 1, kS + 2, kPsi};
  FrameProblem problem = makeFrameProblem(m_camera, m_p, m_up, m_align, m_Rfw, m_offWrist,
                                          m_offElbow, wristOk ? s.camWrist : std::nullopt,
                                          elbowOk ? s.camElbow : std::nullopt, true);
  Eigen::Matrix4d C;
  Eigen::VectorXd x(4);
  for (int i = 0; i < 4; ++i) {
    problem.mu(i) = xPred(idx[i]);
    x(i) = m_s.x(idx[i]);
    for (int j = 0; j < 4; ++j) C(i, j) = PPred(idx[i], idx[j]);
  }
  problem.mu(3) = x(3) + wrapAngle(problem.mu(3) - x(3));
  const Eigen::LLT<Eigen::Matrix4d> llt(C);
  bool refined = false;
  if (llt.info() == Eigen::Success) {
    problem.L = llt.matrixL().solve(Eigen::Matrix4d::Identity());
    ++c.lmRuns;
    double cost = 0;
    if (solve(problem, x, cost)) {
      refined = true;
    } else {
      ++c.lmFailures;
    }
  } else {
    ++c.lmFailures;
  }
  if (refined && m_p.feedbackLm) {
    // Move the whole state to the LM solution, conditioned through the EKF covariance: the
    // solved states take their new values, the velocity follows its correlation with them.
    Eigen::Vector4d delta;
    Eigen::Matrix<double, 7, 4> Pxs;
    Eigen::Matrix4d Pss;
    for (int i = 0; i < 4; ++i) {
      delta(i) = i == 3 ? wrapAngle(x(3) - m_s.x(kPsi)) : x(i) - m_s.x(idx[i]);
      Pxs.col(i) = m_s.P.col(idx[i]);
      for (int j = 0; j < 4; ++j) Pss(i, j) = m_s.P(idx[i], idx[j]);
    }
    m_s.x += Pxs * Pss.ldlt().solve(delta);
    for (int i = 0; i < 4; ++i) m_s.x(idx[i]) = x(i);  // exactly, despite rounding
    m_s.x(kPsi) = wrapAngle(m_s.x(kPsi));
    makeFrame(s.t, true);
    return;
  }
  if (refined) {
    // Report the LM solution but keep the EKF as it is.
    const TaoHuState::Vec7 keep = m_s.x;
    for (int i = 0; i < 4; ++i) m_s.x(idx[i]) = x(i);
    makeFrame(s.t, true);
    m_s.x = keep;
    return;
  }
  makeFrame(s.t, false);
}

void TaoHuTracker::makeFrame(double t, bool refined) {
  const Eigen::Matrix3d R = forearmRotation();
  const Eigen::Vector3d s = m_s.x.segment<3>(kS);
  const Eigen::Vector3d w = s + R * m_offWrist;
  const Eigen::Vector3d e = s + R * m_offElbow;
  const bool left = m_p.side == Side::Left;
  m_frame.t = t;
  m_frame.wrist = left ? mirrorPoint(w) : w;
  m_frame.elbow = left ? mirrorPoint(e) : e;
  m_frame.th = anglesFromPoints(m_p.geometry, e, w, R);
  m_frame.heading = m_s.x(kPsi);
  m_frame.refined = refined;
  m_frame.trueAngles.reset();
}

JointVector TaoHuTracker::anglesFromPoints(const ArmGeometry& geo, const Eigen::Vector3d& elbow,
                                           const Eigen::Vector3d& wrist,
                                           const Eigen::Matrix3d& forearmImuRotation) {
  JointVector th = JointVector::Zero();
  // Elbow direction u = (c0 c1, s0 c1, s1).
  const Eigen::Vector3d u = elbow.normalized();
  th(1) = std::asin(std::clamp(u.z(), -1.0, 1.0));
  th(0) = std::atan2(u.y(), u.x());
  // Forearm direction in frame 2: (-s2 s4, c2 s4, c4), with s4 <= 0.
  const Eigen::Matrix3d R02 =
      (dhTransform<double>(th(0), 0.0, std::numbers::pi / 2, 0.0) *
       dhTransform<double>(th(1) + std::numbers::pi / 2, 0.0, std::numbers::pi / 2, 0.0))
          .topLeftCorner<3, 3>();
  const Eigen::Vector3d f = R02.transpose() * (wrist - elbow).normalized();
  th(3) = std::atan2(-std::hypot(f.x(), f.y()), f.z());
  th(2) = std::atan2(f.x(), -f.y());
  // Pronation: forearm IMU = R05(th0..th4) Rz(th5) Rfix, Rfix the constant rows after th5.
  const std::array<DhRow, 9> rows = forearmImuTable(geo);
  const Eigen::Matrix3d R05 = chainTransform(elbowTable(geo), th).topLeftCorner<3, 3>();
  Eigen::Matrix4d fix = Eigen::Matrix4d::Identity();
  for (std::size_t i = 6; i < rows.size(); ++i)
    fix =
        fix * dhTransform<double>(rows[i].gammaOffset, rows[i].lambda, rows[i].beta, rows[i].delta);
  const Eigen::Matrix3d M =
      R05.transpose() * forearmImuRotation * fix.topLeftCorner<3, 3>().transpose();
  th(4) = std::atan2(M(1, 0) - M(0, 1), M(0, 0) + M(1, 1));  // best rotation about z
  return th;
}

// ---------------------------------------------------------------------------------------------

TaoHuResult runTaoHu(const Recording& recording, const TaoHuParams& params) {
  if (!recording.meta.camera)
    throw std::invalid_argument("the recording has no camera block (webcam marker pixels)");
  const bool anyForearm = std::any_of(recording.samples.begin(), recording.samples.end(),
                                      [](const ArmSample& s) { return s.forearm.has_value(); });
  if (!anyForearm) throw std::invalid_argument("the recording has no forearm IMU samples");

  // Truth rows, for interpolation to the camera frames.
  std::vector<std::pair<double, JointVector>> truth;
  for (const ArmSample& s : recording.samples) {
    if (s.trueAngles && std::isfinite(s.t) && (truth.empty() || s.t > truth.back().first))
      truth.emplace_back(s.t, *s.trueAngles);
  }
  const auto truthAt = [&](double t) -> std::optional<JointVector> {
    const auto it = std::lower_bound(truth.begin(), truth.end(), t,
                                     [](const auto& a, double v) { return a.first < v; });
    if (it != truth.end() && it->first == t) return it->second;
    if (it == truth.begin() || it == truth.end()) return std::nullopt;
    const auto& [t0, a] = *(it - 1);
    const auto& [t1, b] = *it;
    if (t1 - t0 > 0.1) return std::nullopt;
    const double w = (t - t0) / (t1 - t0);
    JointVector th;
    for (int j = 0; j < kNumJoints; ++j) th(j) = wrapAngle(a(j) + w * wrapAngle(b(j) - a(j)));
    return th;
  };

  TaoHuTracker tracker(params);
  TaoHuResult result;
  for (const ArmSample& s : recording.samples) {
    if (tracker.update(s) != TaoHuStatus::Frame) continue;
    TaoHuFrame f = tracker.frame();
    if (!truth.empty()) f.trueAngles = truthAt(f.t);
    result.frames.push_back(f);
  }
  result.counters = tracker.counters();
  return result;
}

TaoHuErrors taoHuErrors(const TaoHuResult& result, const ArmGeometry& geometry, Side side,
                        double skipSeconds) {
  TaoHuErrors e;
  if (result.frames.empty()) return e;
  const double from = result.frames.front().t + skipSeconds;
  ErrorAccumulator angles;
  double wristSq = 0, elbowSq = 0;
  for (const TaoHuFrame& f : result.frames) {
    if (!f.trueAngles || f.t < from) continue;
    const ArmPose pose = forwardKinematics(geometry, *f.trueAngles);
    const bool left = side == Side::Left;
    const Eigen::Vector3d wt = left ? mirrorPoint(pose.wrist) : pose.wrist;
    const Eigen::Vector3d et = left ? mirrorPoint(pose.elbow) : pose.elbow;
    const Eigen::Vector3d dw = f.wrist - wt;
    const double ew = dw.norm(), ee = (f.elbow - et).norm();
    wristSq += ew * ew;
    elbowSq += ee * ee;
    e.wristPeakCm = std::max(e.wristPeakCm, 100.0 * ew);
    e.elbowPeakCm = std::max(e.elbowPeakCm, 100.0 * ee);
    e.wristAxisPeakCm = std::max(e.wristAxisPeakCm, 100.0 * dw.cwiseAbs().maxCoeff());
    angles.add(f.th, *f.trueAngles);
  }
  e.count = angles.count();
  if (e.count == 0) return e;
  e.rmseDeg = angles.rmse() / kDegToRad;
  e.peakDeg = angles.peak() / kDegToRad;
  e.wristRmseCm = 100.0 * std::sqrt(wristSq / static_cast<double>(e.count));
  e.elbowRmseCm = 100.0 * std::sqrt(elbowSq / static_cast<double>(e.count));
  return e;
}

}  // namespace armtrack
