#include "core/estimation/ArmFilter.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <unsupported/Eigen/AutoDiff>
#include <utility>

#include "core/Strings.h"
#include "core/camera/PinholeCamera.h"
#include "core/estimation/BlockUpdate.h"
#include "core/estimation/Heading.h"
#include "core/estimation/Initializer.h"
#include "core/estimation/MeasurementJacobian.h"
#include "core/estimation/Transition.h"
#include "core/estimation/WindowFit.h"

namespace armtrack {

MeasurementModel parseMethod(const std::string& name) {
  const std::string s = asciiLower(name);
  if (s == "a") return MeasurementModel::AccelGyro;
  if (s == "b") return MeasurementModel::AugmentedBodyAccel;
  if (s == "c") return MeasurementModel::InclinometerGyro;
  if (s == "inclinometer") return MeasurementModel::Inclinometer;
  throw std::invalid_argument("unknown method \"" + name + "\": expected A, B, C or inclinometer");
}

std::string methodName(MeasurementModel m) {
  switch (m) {
    case MeasurementModel::AccelGyro:
      return "A";
    case MeasurementModel::AugmentedBodyAccel:
      return "B";
    case MeasurementModel::InclinometerGyro:
      return "C";
    case MeasurementModel::Inclinometer:
      return "inclinometer";
  }
  return "?";
}

MeasurementModel startupModel(const EstimatorParams& p) {
  const bool kinematic = (p.model == MeasurementModel::InclinometerGyro ||
                          p.model == MeasurementModel::AugmentedBodyAccel) &&
                         p.kinematicStartup;
  return kinematic ? MeasurementModel::AccelGyro : p.model;
}

namespace {

constexpr int kBase = 15;
constexpr int kModelRows = 18;            // the six 3-row blocks of eq. 16
constexpr int kMaxRows = kModelRows + 4;  // plus two 2-row marker pixels
using Vec15 = Eigen::Matrix<double, kBase, 1>;
using AD = Eigen::AutoDiffScalar<Vec15>;

// Measurement blocks in the order of eq. 16 (gyros and accelerometers per IMU, then optics),
// then the webcam's marker pixels.
enum Block { kUaGyr = 0, kUaAcc, kFaGyr, kFaAcc, kElbow, kWrist, kCamWrist, kCamElbow, kNumBlocks };

constexpr bool isCamera(int b) {
  return b == kCamWrist || b == kCamElbow;
}
constexpr bool isOptical(int b) {
  return b == kElbow || b == kWrist || isCamera(b);
}

// The blocks present in one update: 3 rows for IMU and Kinect blocks, 2 for marker pixels.
struct BlockList {
  std::array<int, kNumBlocks> block{};
  std::array<int, kNumBlocks> offset{};
  std::array<int, kNumBlocks> size{};
  int count = 0;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1> z;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1> variance;  // diagonal of R
  int rows() const { return static_cast<int>(z.size()); }
  template <int M>
  void add(int b, const Eigen::Matrix<double, M, 1>& value, double var) {
    const auto n = z.size();
    block[count] = b;
    offset[count] = static_cast<int>(n);
    size[count++] = M;
    z.conservativeResize(n + M);
    variance.conservativeResize(n + M);
    z.template segment<M>(n) = value;
    variance.template segment<M>(n).setConstant(var);
  }
  bool has(int b) const {
    for (int i = 0; i < count; ++i)
      if (block[i] == b) return true;
    return false;
  }
  bool anyOptical() const {
    for (int i = 0; i < count; ++i)
      if (isOptical(block[i])) return true;
    return false;
  }
  // A copy without block i.
  BlockList without(int i) const {
    BlockList out;
    for (int k = 0; k < count; ++k) {
      if (k == i) continue;
      if (size[k] == 3)
        out.add<3>(block[k], z.segment<3>(offset[k]), variance(offset[k]));
      else
        out.add<2>(block[k], z.segment<2>(offset[k]), variance(offset[k]));
    }
    return out;
  }
};

// A marker's pixel from its predicted position p (right-arm frame) and dp/dx: the camera sees the
// real arm, which for a left arm is the mirror image of the one the filter works on.
bool markerPixel(const PinholeCamera& camera, bool left, const Eigen::Vector3d& p,
                 const Eigen::Matrix<double, 3, kBase>* dp, Eigen::Vector2d& pixel,
                 Eigen::Matrix<double, 2, kBase>* jac) {
  const Eigen::Vector3d real = left ? mirrorPoint(p) : p;
  if (!jac) return camera.project(real, pixel);
  Eigen::Matrix<double, 2, 3> dPixel;
  if (!camera.project(real, pixel, dPixel)) return false;
  if (left) dPixel.col(2) = -dPixel.col(2);
  *jac = dPixel * *dp;
  return true;
}

// Predicted readings of all six blocks for the 15-state base, templated for AutoDiff.
template <typename T>
void predictBase(const EstimatorParams& p, const Eigen::Matrix<T, kBase, 1>& x,
                 Eigen::Matrix<T, kModelRows, 1>& out) {
  const Eigen::Matrix<T, 5, 1> thdd = x.template segment<5>(0);
  const Eigen::Matrix<T, 5, 1> thd = x.template segment<5>(5);
  const Eigen::Matrix<T, 5, 1> th = x.template segment<5>(10);
  const ArmKinematics<T> k = armKinematics<T>(p.geometry, th, thd, thdd, p.gUp);
  const bool bodyAccel = p.model == MeasurementModel::AccelGyro;
  out.template segment<3>(0) = k.upperImu.omega;
  out.template segment<3>(3) =
      bodyAccel ? Eigen::Matrix<T, 3, 1>(k.upperImu.up + k.upperImu.accel) : k.upperImu.up;
  out.template segment<3>(6) = k.forearmImu.omega;
  out.template segment<3>(9) =
      bodyAccel ? Eigen::Matrix<T, 3, 1>(k.forearmImu.up + k.forearmImu.accel) : k.forearmImu.up;
  out.template segment<3>(12) = k.elbow;
  out.template segment<3>(15) = k.wrist;
}

void predictBaseWithJacobian(const EstimatorParams& p, const Vec15& x,
                             Eigen::Matrix<double, kModelRows, 1>& h,
                             Eigen::Matrix<double, kModelRows, kBase>& jac) {
  Eigen::Matrix<AD, kBase, 1> xa;
  for (int i = 0; i < kBase; ++i) xa(i) = AD(x(i), kBase, i);
  Eigen::Matrix<AD, kModelRows, 1> out;
  predictBase<AD>(p, xa, out);
  for (int i = 0; i < kModelRows; ++i) {
    h(i) = out(i).value();
    jac.row(i) = out(i).derivatives().transpose();
  }
}

template <int N>
class ArmFilter final : public JointEstimator {
 public:
  using Vec = Eigen::Matrix<double, N, 1>;
  using Mat = Eigen::Matrix<double, N, N>;
  using MeasVec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1>;
  using MeasMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, kMaxRows>;
  using Jac = Eigen::Matrix<double, Eigen::Dynamic, N, 0, kMaxRows, N>;
  using Gain = Eigen::Matrix<double, N, Eigen::Dynamic, 0, N, kMaxRows>;
  static constexpr bool kAugmented = N > kBase;

  explicit ArmFilter(const EstimatorParams& p)
      : m_p(mirrored(p)), m_model(p.model), m_up(m_p.gUp.normalized()), m_gate(gateLimits(m_p)) {
    if (m_p.camera && m_p.useCamera) m_camera.emplace(*m_p.camera);  // throws on a bad camera
    reset();
  }

  static PlausibilityLimits gateLimits(const EstimatorParams& p) {
    PlausibilityLimits l = p.plausibility;
    l.maxReach = std::min(l.maxReach,
                          PlausibilityLimits::forGeometry(p.geometry.l3, p.geometry.l6).maxReach);
    return l;
  }

  // Everything below works on a right arm: a left arm's gravity direction is mirrored once here,
  // its samples on arrival.
  static EstimatorParams mirrored(EstimatorParams p) {
    if (p.side == Side::Left) p.gUp = mirrorPoint(p.gUp);
    return p;
  }

  void reset() override {
    m_x.setZero();
    m_P.setIdentity();
    m_initialised = false;
    m_t = m_t0 = 0.0;
    m_lastSeenT = -std::numeric_limits<double>::infinity();
    m_lastOpticalT = -std::numeric_limits<double>::infinity();
    m_pendingOptical.reset();
    m_gatedInARow = {0, 0, 0, 0};
    m_gate.reset();
    m_matchedQ.setZero();
    m_jerkSquared = 0.0;
    m_jerkFrom.reset();
    m_headingMatch = m_turnSquared = m_turnNoise = 0.0;
    m_lastMatchT = -std::numeric_limits<double>::infinity();
    m_recent.clear();
    m_recentStates.clear();
    m_badSince.reset();
    m_opticalDisagrees = false;
    m_fitAt.reset();
    m_counters = {};
  }

  bool initialised() const override { return m_initialised; }
  const EstimatorCounters& counters() const override { return m_counters; }
  Eigen::MatrixXd covariance() const override { return m_P; }

  bool headingFromStartPoseOnly() const override {
    constexpr double kHeadingMemory = 5.0;  // s an optical fix is taken to hold the heading
    return !(m_t - m_lastOpticalT <= kHeadingMemory);
  }

  JointEstimate estimate() const override {
    JointEstimate e;
    e.t = m_t;
    e.thdd = m_x.template segment<5>(0);
    e.thd = m_x.template segment<5>(5);
    e.th = m_x.template segment<5>(10);
    const Vec u = headingAngles(m_x);
    const JointVector hu = u.template segment<5>(10);
    const double shortfall = headingShortfall(u);
    JointVector var = m_P.diagonal().template segment<5>(10) + shortfall * hu.cwiseAbs2();
    addHeadingCurvature(e.th, headingVariance(u) + shortfall, hu, var);
    e.thStd = var.cwiseMax(0.0).cwiseSqrt();
    return e;
  }

  UpdateResult update(const ArmSample& s) override {
    ++m_counters.samples;
    if (!std::isfinite(s.t) || s.t < m_lastSeenT) {
      ++m_counters.rejectedTime;
      return UpdateResult::Rejected;
    }
    m_lastSeenT = s.t;

    ArmSample clean = sanitise(m_p.side == Side::Left ? mirrorSample(s) : s);
    const bool hasImu = clean.upperArm || clean.forearm;
    const bool hasOptical = clean.elbow || clean.wrist || clean.camWrist || clean.camElbow;
    if (!hasImu && !hasOptical) {
      // Readings refused at the door: coast through a short stretch, so the row still gets an
      // estimate (its standard deviation grows with the prediction).
      if (m_initialised && m_gate.lastRefused() && s.t - m_lastDataT <= m_p.maxCoastSeconds) {
        predict(s.t - m_t);
        m_t = s.t;
        finishUpdate();
        ++m_counters.coasted;
        return UpdateResult::Predicted;
      }
      return UpdateResult::Rejected;
    }

    if (m_initialised && s.t - m_lastDataT > m_p.maxGap) {
      ++m_counters.restarts;
      m_initialised = false;
    }
    if (!m_initialised) {
      if (!hasImu) {
        m_pendingOptical = clean;
        return UpdateResult::Waiting;
      }
      initialise(clean);
      remember(clean);
      return UpdateResult::Initialised;
    }

    if (m_p.model != m_model && s.t - m_t0 >= m_p.startupSeconds) handOver();
    const Vec xPrior = m_x;
    const Mat pPrior = m_P;
    const double tPrior = m_t, floorPrior = m_headingFloor;
    predict(s.t - m_t);
    m_t = s.t;
    m_prior.reset();
    BlockList blocks = gather(clean);
    const Vec xBefore = m_x;
    const Mat pBefore = m_P;
    const bool optical = blocks.anyOptical();
    if (optical) beforeOpticalUpdate();
    const int offered = blocks.count;
    const bool gated = gateOptical(blocks);
    if (!gated || blocks.count == 0) {
      // Nothing left to fuse (e.g. a single mis-detected marker), or the gate could not be
      // evaluated: the sample changes nothing.
      if (!gated) ++m_counters.skippedUpdates;
      m_x = xPrior;
      m_P = pPrior;
      m_t = tPrior;
      m_headingFloor = floorPrior;
      return UpdateResult::Rejected;
    }
    // The gate saw the heading variance restored; when it dropped every optical block, this is
    // an IMU-only update and P goes back to what it was.
    const bool fuseOptical = blocks.anyOptical();
    if (optical && !fuseOptical) m_P = pBefore;
    // Heading matching reads only frames whose optical rows all passed the gate: a mis-detected
    // marker must not open the heading up, nor its partner in the same frame. Nothing is gated
    // during start-up, so there it reads Kinect positions only, not marker pixels, whose
    // detector mis-detects far more often (5 % of frames in test_camera_fusion).
    const bool startup = m_t - m_t0 < m_p.startupSeconds;
    if (fuseOptical && blocks.count == offered) {
      if (!matchOpticalHeading(blocks, startup)) m_headingMatch = 0.0;
      beforeOpticalUpdate();
    }
    // Both filters start with the iterated EKF update: a UKF's sigma points spread over the
    // start-up uncertainty (tens of degrees) wrap around and lose the arm.
    bool ok = false;
    if (m_p.filter == FilterKind::Ekf || startup) {
      ok = ekfUpdate(blocks);
    } else {
      bool sigmaOutOfView = false;
      ok = ukfUpdate(blocks, sigmaOutOfView);
      // A sigma point the camera cannot see has no pixel: linearise instead for this sample.
      if (!ok && sigmaOutOfView) {
        m_x = xBefore;
        m_P = pBefore;
        if (fuseOptical) beforeOpticalUpdate();
        ok = ekfUpdate(blocks);
      }
    }
    if (!ok || !m_x.allFinite() || !m_P.allFinite()) {
      m_x = xBefore;
      m_P = pBefore;
      ++m_counters.skippedUpdates;
      // Updates that keep failing are a lost filter too, not something to skip for ever.
      if (!m_badSince) m_badSince = s.t;
      if (s.t - *m_badSince >= m_p.lostAfterSeconds) return recover(clean);
      return UpdateResult::Rejected;
    }
    if (fuseOptical) {
      m_lastOpticalT = s.t;
      for (int i = 0; i < blocks.count; ++i) {
        if (isCamera(blocks.block[i]))
          ++m_counters.cameraUpdates;
        else if (isOptical(blocks.block[i]))
          ++m_counters.opticalUpdates;
      }
    }
    m_lastDataT = s.t;
    afterUpdate(fuseOptical);
    matchProcessNoise(xBefore, s.t - tPrior);
    if (blocks.has(kUaAcc) || blocks.has(kFaAcc)) trackJerk();
    finishUpdate();
    remember(clean);
    if (m_fitAt && m_t >= *m_fitAt) {
      m_fitAt.reset();
      if (refitFromWindow(m_t - m_p.fitWindowSeconds)) return UpdateResult::Recovered;
      // Not taken: the window may have held the tail of a fault, or the motion was too fast for
      // the seeds. Try the next window while start-up lasts.
      if (m_t + m_p.fitWindowSeconds - m_t0 < m_p.startupSeconds)
        m_fitAt = m_t + m_p.fitWindowSeconds;
    }
    if (lost()) return recover(clean);
    return UpdateResult::Accepted;
  }

 private:
  // The blocks this filter uses, each checked at the door: implausible ones are dropped and
  // counted (SampleGate), so no reading a sensor cannot produce reaches the update.
  ArmSample sanitise(const ArmSample& s) {
    ArmSample c = s;
    if (!m_p.useOptical) c.elbow.reset(), c.wrist.reset();
    if (!m_camera) c.camWrist.reset(), c.camElbow.reset();
    c = m_gate.check(c);
    if (m_gate.lastRefused()) {
      m_counters.implausible = m_gate.counters();
      m_counters.rejectedNonFinite = m_counters.implausible.byReason(Implausible::NonFinite);
    }
    return c;
  }

  BlockList gather(const ArmSample& s) const {
    BlockList b;
    const bool gyro = m_p.model != MeasurementModel::Inclinometer;
    // After start-up, Method A's accelerometers also carry the model error of a lagging joint
    // acceleration, which grows with the squared jerk (accelJerkVariance).
    const bool jerkModelled =
        m_p.model == MeasurementModel::AccelGyro && m_t - m_t0 >= m_p.startupSeconds;
    const double accelVar =
        m_p.accelVariance *
            (gyro && m_t - m_t0 < m_p.gyroFirstSeconds ? m_p.gyroFirstAccelGain : 1.0) +
        (jerkModelled ? m_p.accelJerkVariance * m_jerkSquared : 0.0);
    if (s.upperArm) {
      if (gyro) b.add(kUaGyr, s.upperArm->gyr, m_p.gyroVariance);
      b.add(kUaAcc, s.upperArm->acc, accelVar);
    }
    if (s.forearm) {
      if (gyro) b.add(kFaGyr, s.forearm->gyr, m_p.gyroVariance);
      b.add(kFaAcc, s.forearm->acc, accelVar);
    }
    if (s.elbow) b.add(kElbow, *s.elbow, m_p.positionVariance);
    if (s.wrist) b.add(kWrist, *s.wrist, m_p.positionVariance);
    if (s.camWrist) b.add(kCamWrist, *s.camWrist, m_p.pixelVariance);
    if (s.camElbow) b.add(kCamElbow, *s.camElbow, m_p.pixelVariance);
    return b;
  }

  // Innovation gating of the optical measurements at the predicted state: a mis-detected marker
  // (in the webcam image, or in the Kinect's colour image before depth is added) lands far from
  // where the arm can be. Gated and unseeable measurements are removed from b and counted.
  // Start-up is not gated: the first pose may be far off and the optics are what corrects it.
  // Returns false when the state could not be linearised.
  bool gateOptical(BlockList& b) {
    const bool anyCamera = m_camera && (b.has(kCamWrist) || b.has(kCamElbow));
    const bool anyPosition = m_p.positionGate > 0.0 && (b.has(kElbow) || b.has(kWrist));
    if (!anyCamera && !anyPosition) return true;
    const bool startup = m_t - m_t0 < m_p.startupSeconds;
    const Eigen::Matrix<double, kModelRows, 1>& all = priorPrediction().readings;
    const Eigen::Matrix<double, kModelRows, kBase>& allJac = priorPrediction().jacobian;
    for (int i = b.count - 1; i >= 0; --i) {
      const int blk = b.block[i];
      if (blk == kElbow || blk == kWrist) {
        if (!anyPosition) continue;
        int& inARow = m_gatedInARow[blk == kWrist ? 2 : 3];
        if (startup || inARow >= m_p.positionGateResetFrames) {
          if (!startup) m_opticalDisagrees = true;
          inARow = 0;
          continue;
        }
        const Eigen::Vector3d r = b.z.template segment<3>(b.offset[i]) - all.segment<3>(3 * blk);
        // Positions read the angles only (columns 10-14 of the Jacobian).
        const Eigen::Matrix<double, 3, kNumJoints> jac = allJac.block<3, kNumJoints>(3 * blk, 10);
        Eigen::Matrix3d sm = jac.lazyProduct(m_P.template block<kNumJoints, kNumJoints>(10, 10))
                                 .lazyProduct(jac.transpose());
        sm.diagonal().array() += m_p.positionVariance;
        const Eigen::LLT<Eigen::Matrix3d> llt(sm);
        if (llt.info() != Eigen::Success) return false;
        // Both far in metres and improbable: a small stated variance alone must not turn a
        // model error's systematic innovation into an "outlier".
        if (r.norm() > m_p.positionGateMinDistance && r.dot(llt.solve(r)) > m_p.positionGate) {
          ++m_counters.rejectedOutliers;
          ++m_counters.gatedPositions;
          ++inARow;
          b = b.without(i);
        } else {
          inARow = 0;
        }
        continue;
      }
      if (!isCamera(blk) || !anyCamera) continue;
      Eigen::Vector2d px;
      Eigen::Matrix<double, 2, kBase> jac;
      const int posBlock = blk == kCamWrist ? kWrist : kElbow;
      const Eigen::Matrix<double, 3, kBase> dp = allJac.middleRows<3>(3 * posBlock);
      if (!markerPixel(*m_camera, m_p.side == Side::Left, all.segment<3>(3 * posBlock), &dp, px,
                       &jac)) {
        ++m_counters.cameraNotVisible;
        b = b.without(i);
        continue;
      }
      int& inARow = m_gatedInARow[blk == kCamWrist ? 0 : 1];
      if (startup || inARow >= m_p.pixelGateResetFrames) {
        if (!startup) m_opticalDisagrees = true;
        inARow = 0;
        continue;
      }
      const Eigen::Vector2d r = b.z.template segment<2>(b.offset[i]) - px;
      const Eigen::Matrix<double, 2, kNumJoints> ja = jac.rightCols<kNumJoints>();  // angles only
      Eigen::Matrix2d sm = ja.lazyProduct(m_P.template block<kNumJoints, kNumJoints>(10, 10))
                               .lazyProduct(ja.transpose());
      sm.diagonal().array() += m_p.pixelVariance;
      const Eigen::LLT<Eigen::Matrix2d> llt(sm);
      if (llt.info() != Eigen::Success) return false;
      const double d2 = r.dot(llt.solve(r));
      if (d2 > m_p.pixelGate) {
        ++m_counters.rejectedOutliers;
        ++inARow;
        b = b.without(i);
      } else {
        inARow = 0;
      }
    }
    return true;
  }

  void initialise(const ArmSample& s) {
    ArmSample first = s;
    constexpr double kOpticalWindow = 0.1;  // s an earlier optical sample may lag the first IMU
    if (m_pendingOptical && s.t - m_pendingOptical->t <= kOpticalWindow) {
      if (!first.elbow) first.elbow = m_pendingOptical->elbow;
      if (!first.wrist) first.wrist = m_pendingOptical->wrist;
      if (!first.camWrist) first.camWrist = m_pendingOptical->camWrist;
      if (!first.camElbow) first.camElbow = m_pendingOptical->camElbow;
    }
    m_pendingOptical.reset();
    m_p.model = m_model;  // every (re)start begins on the start-up model, until handOver()
    m_p.model = startupModel(m_p);
    const InitialPose pose = initialPose(m_p, first);
    m_x.setZero();
    m_x.template segment<5>(5) = pose.thd;
    m_x.template segment<5>(10) = pose.th;
    // Two marker pixels pin the arm like two positions do (up to the depth along each ray, which
    // the arm's lengths fix); one pixel alone does not.
    const bool optical = (first.elbow || first.wrist) || (first.camWrist && first.camElbow);
    startCovariance(optical);
    m_t = m_t0 = m_lastDataT = s.t;
    m_recent.clear();
    m_recentStates.clear();
    m_badSince.reset();
    m_opticalDisagrees = false;
    m_matchedQ.setZero();
    m_jerkSquared = 0.0;
    m_jerkFrom.reset();
    m_headingMatch = m_turnSquared = m_turnNoise = 0.0;
    m_lastMatchT = -std::numeric_limits<double>::infinity();
    m_fitAt = m_p.fitWindowSeconds > 0.0 ? std::optional<double>(s.t + m_p.fitWindowSeconds)
                                         : std::nullopt;
    m_lastOpticalT = optical ? s.t : -std::numeric_limits<double>::infinity();
    m_headingFloor = headingAngles(m_x).dot(m_P * headingAngles(m_x));
    m_initialised = true;
    freezeInactive();
    keepInAnatomicalRange();
  }

  // The start-up covariance around the present state.
  void startCovariance(bool optical) {
    m_P.setZero();
    const double angleStd = optical ? m_p.initialAngleStdOptical : m_p.initialAngleStd;
    for (int j = 0; j < kNumJoints; ++j) {
      m_P(j, j) = m_p.initialAccelStd * m_p.initialAccelStd;
      m_P(5 + j, 5 + j) = m_p.initialRateStd * m_p.initialRateStd;
      m_P(10 + j, 10 + j) = angleStd * angleStd;
    }
    // A start pose without optical data has its heading from the prior alone: say so in P.
    if (!optical) {
      const Vec15 v = headingSymmetry(m_x.template head<kBase>(), m_up);
      m_P.template topLeftCorner<kBase, kBase>() +=
          m_p.initialHeadingStd * m_p.initialHeadingStd * v * v.transpose();
    }
    if constexpr (kAugmented) {
      for (int i = kBase; i < N; ++i) m_P(i, i) = m_p.bodyAccelVariance;
    }
    m_headingFloor = headingAngles(m_x).dot(m_P * headingAngles(m_x));
  }

  // x <- F x, P <- F P F^T + Q for step dt (eqs. 3-4 with the time step taken from the data).
  void predict(double dt) {
    if (dt <= 0.0) return;
    const double phi = std::isfinite(m_p.jointAccelCorrelationTime)
                           ? std::exp(-dt / m_p.jointAccelCorrelationTime)
                           : 1.0;
    const double phiB = kAugmented ? std::exp(-dt / m_p.bodyAccelCorrelationTime) : 0.0;
    transitionRows(m_x, dt, phi, phiB);
    for (int j = 0; j < kNumJoints; ++j) m_x(10 + j) = wrapAngle(m_x(10 + j));
    transitionCovariance(m_P, dt, phi, phiB);

    const double var = m_t - m_t0 < m_p.startupSeconds
                           ? std::max(m_p.jointAccelVariance, m_p.startupJointAccelVariance)
                           : m_p.jointAccelVariance;
    for (int j = 0; j < kNumJoints; ++j)
      if (m_p.activeJoints[j]) m_P(j, j) += std::max(var, m_matchedQ(j)) * dt / m_p.referenceStep;
    // Method A's lag turns the upper arm about every axis (shoulderPathVarianceRate; the turn
    // about the vertical is the heading's walk below).
    if (m_p.model == MeasurementModel::AccelGyro && m_t - m_t0 >= m_p.startupSeconds) {
      const double lagWalk = m_p.shoulderPathVarianceRate * m_x.template segment<3>(5).norm() * dt;
      for (int j = 0; j < 3; ++j)
        if (m_p.activeJoints[j]) m_P(10 + j, 10 + j) += lagWalk;
    }
    // The heading random walk is a turn of the whole arm about the vertical: in joint space its
    // variance grows with the squared joint-space length of a unit turn, which is large near the
    // shoulder's gimbal lock (abduction 90 deg), where a small turn moves flexion and rotation far.
    const Vec15 v = headingSymmetryAtState();
    const double turnRate = (headingTurnRate() + headingSpeedTurnRate()) *
                            generatorAt(m_x.template segment<5>(10)).squaredNorm();
    m_P.template topLeftCorner<kBase, kBase>() += turnRate * dt * v * v.transpose();
    m_headingFloor += turnRate * dt;
    if constexpr (kAugmented) {
      const double qb = m_p.bodyAccelVariance * (1.0 - phiB * phiB);
      for (int i = kBase; i < N; ++i) m_P(i, i) += qb;
    }
  }

  // Predicted measurement (and Jacobian) for the present blocks at state x. Returns false when a
  // marker is out of the camera's view at x.
  bool measure(const Vec& x, const BlockList& b, MeasVec& h, Jac* jac) const {
    Eigen::Matrix<double, kModelRows, 1> own;
    Eigen::Matrix<double, kModelRows, kBase> ownJac;
    const Eigen::Matrix<double, kModelRows, 1>* readings = &own;
    const Eigen::Matrix<double, kModelRows, kBase>* derivatives = &ownJac;
    const Vec15 base = x.template head<kBase>();
    if (jac && m_prior && m_prior->at == base) {
      readings = &m_prior->readings;  // the first iteration linearises where the gate did
      derivatives = &m_prior->jacobian;
    } else if (jac) {
      // Optical rows (positions, and marker pixels through them) read the position rows.
      predictReadings(m_p.geometry, m_p.gUp, m_p.model == MeasurementModel::AccelGyro, base, own,
                      &ownJac, b.anyOptical());
    } else {
      predictBase<double>(m_p, base, own);
    }
    const Eigen::Matrix<double, kModelRows, 1>& all = *readings;
    const Eigen::Matrix<double, kModelRows, kBase>& allJac = *derivatives;
    h.resize(b.rows());
    if (jac) {
      jac->resize(b.rows(), N);
      // Every block below writes its rows' first 15 columns; only Method B's are wider.
      if constexpr (kAugmented) jac->setZero();
    }
    for (int i = 0; i < b.count; ++i) {
      const int blk = b.block[i];
      const int row = b.offset[i];
      if (isCamera(blk)) {
        const int posBlock = blk == kCamWrist ? kWrist : kElbow;
        Eigen::Vector2d px;
        Eigen::Matrix<double, 2, kBase> pxJac;
        Eigen::Matrix<double, 3, kBase> dp;
        if (jac) dp = allJac.template middleRows<3>(3 * posBlock);
        if (!markerPixel(*m_camera, m_p.side == Side::Left, all.template segment<3>(3 * posBlock),
                         jac ? &dp : nullptr, px, jac ? &pxJac : nullptr))
          return false;
        h.template segment<2>(row) = px;
        if (jac) jac->template block<2, kBase>(row, 0) = pxJac;
        continue;
      }
      h.template segment<3>(row) = all.template segment<3>(3 * blk);
      if (jac) jac->template block<3, kBase>(row, 0) = allJac.template middleRows<3>(3 * blk);
      if constexpr (kAugmented) {
        // Method B: the accelerometer also reads the augmented body-acceleration state.
        if ((blk == kUaAcc || blk == kFaAcc) && m_p.model == MeasurementModel::AugmentedBodyAccel) {
          const int off = kBase + (blk == kUaAcc ? 0 : 3);
          h.template segment<3>(row) += x.template segment<3>(off);
          if (jac) jac->template block<3, 3>(row, off).setIdentity();
        }
      }
    }
    return true;
  }

  // The Kalman update for a given linearisation, one block at a time. R is block-diagonal, so
  // this equals the batch update exactly, at a third of the cost: per block an MxM Cholesky
  // factor L of S = H P H^T + R, the gain applied to the innovation left by the blocks before,
  // and the symmetric rank-M downdate P -= V^T V with V = L^-1 H P, which keeps P symmetric.
  // Returns false when some S is not positive definite.
  bool sequentialUpdate(const Jac& jac, const MeasVec& innov, const BlockList& b, Mat& p, Vec& dx) {
    dx.setZero();
    m_updateNis = 0.0;
    m_updateDof = 0;
    for (int i = 0; i < b.count; ++i) {
      const bool ok = b.size[i] == 3 ? blockUpdate<3>(jac, innov, b, i, p, dx)
                                     : blockUpdate<2>(jac, innov, b, i, p, dx);
      if (!ok) return false;
    }
    return true;
  }

  template <int M>
  bool blockUpdate(const Jac& jac, const MeasVec& innov, const BlockList& b, int i, Mat& p,
                   Vec& dx) {
    const int row = b.offset[i];
    // Optical rows (positions, marker pixels) read the angles only: their Jacobian is zero left
    // of column 10 and right of 15, and the products skip those columns.
    if (isOptical(b.block[i]))
      return updateBlock<M, kNumJoints>(jac.template block<M, kNumJoints>(row, 10), 10, innov, b, i,
                                        p, dx);
    return updateBlock<M, N>(jac.template middleRows<M>(row), 0, innov, b, i, p, dx);
  }

  // The update for block i whose Jacobian rows are zero outside columns [col, col + K), given as
  // hj (M x K); the arithmetic is fuseBlock's (BlockUpdate.h).
  template <int M, int K>
  bool updateBlock(const Eigen::Matrix<double, M, K>& hj, int col, const MeasVec& innov,
                   const BlockList& b, int i, Mat& p, Vec& dx) {
    const int row = b.offset[i];
    // Heading-blind IMU update (a Schmidt, or "consider", update along one direction): IMU rows
    // say nothing about the turn of the arm about the vertical, so their gain must not move the
    // state along it. The optimal gain would, through P's correlations, whenever the motion
    // outruns the process model (at the start and end of a fast reach the joint accelerations
    // jump), and every such step stays, because nothing but optics can undo it. The gain has
    // its heading component removed, and P follows that gain exactly.
    const BlindDirection<N> heading{m_headingBlind.v, m_headingBlind.u};
    const bool blind = m_headingBlind.active && !isOptical(b.block[i]);
    double nis = 0.0;
    if (!fuseBlock<M, K, N>(hj, col, innov.template segment<M>(row),
                            b.variance.template segment<M>(row), blind ? &heading : nullptr, p, dx,
                            nis))
      return false;
    if (watched(b.block[i])) m_updateNis += nis, m_updateDof += M;
    return true;
  }

  // The heading is a symmetry of the IMU readings only when the whole arm can turn about the
  // vertical: all three shoulder joints free (the paper's one-segment studies hold two fixed).
  bool headingIsFree() const {
    return m_p.activeJoints[0] && m_p.activeJoints[1] && m_p.activeJoints[2];
  }

  double headingTurnRate() const {
    if (!headingIsFree()) return 0.0;
    return m_p.model == MeasurementModel::AccelGyro ? m_p.headingVarianceRate
                                                    : m_p.inclinometerHeadingVarianceRate;
  }

  // The heading's walk from the lag of the angles behind the motion (Method A): grows with the
  // shoulder joints' speed, so with the path they travel.
  double headingSpeedTurnRate() const {
    if (!headingIsFree() || m_p.model != MeasurementModel::AccelGyro) return 0.0;
    return m_p.headingPathVarianceRate * m_x.template segment<3>(5).norm();
  }

  // Whether IMU updates are heading-blind now, and the directions they use: v the full-state
  // heading symmetry, u the covector that reads the turn about the vertical (u . v = 1). From
  // the start, so that without optics the heading stays the start pose's, as documented,
  // instead of taking a random turn while start-up settles. Only for Method A: B and C leave
  // body acceleration out of their model, so their IMU innovations carry model error whose
  // correlations with the heading the filter needs to bleed off.
  bool headingBlind() const {
    return m_p.headingBlindImuUpdates && headingIsFree() &&
           m_p.model == MeasurementModel::AccelGyro;
  }

  // headingSymmetry at x, remembered for the last state asked: predict(), the heading-blind
  // update and the projection of the first iteration all ask at the same predicted state.
  const Vec15& headingSymmetryAt(const Vec15& x) {
    if (!m_heading || m_heading->first != x)
      m_heading.emplace(x, headingSymmetry(x, m_up, generatorAt(x.template segment<5>(10))));
    return m_heading->second;
  }
  const Vec15& headingSymmetryAtState() { return headingSymmetryAt(m_x.template head<kBase>()); }

  void prepareHeadingBlind() {
    m_headingBlind.active = headingBlind();
    if (!m_headingBlind.active) return;
    m_headingBlind.v.setZero();
    m_headingBlind.v.template head<kBase>() = headingSymmetryAtState();
    // What stays put is the arm's turn about the vertical, read by the covector w (up . J_s dth),
    // not the angles' Euclidean component along the heading direction: a correction that only
    // tilts the arm (w . dx = 0) may still have such a component when the shoulder axes are not
    // orthogonal, and reading that as heading made every tilt correction turn the arm a little.
    const JointVector w = headingCovector(m_x.template segment<5>(10), m_up);
    m_headingBlind.u.setZero();
    m_headingBlind.u.template segment<5>(10) = w / w.dot(m_headingBlind.v.template segment<5>(10));
  }

  bool ekfUpdate(const BlockList& b) {
    const int iterations = m_t - m_t0 < m_p.startupSeconds ? std::max(1, m_p.startupIterations) : 1;
    prepareHeadingBlind();
    const Vec x0 = m_x;
    Vec xi = m_x, dx;
    MeasVec h;
    Jac jac;
    // The iterations start from the prior P each time; a single one updates m_P in place (on
    // failure the caller restores m_P).
    Mat p;
    Mat& updated = iterations > 1 ? p : m_P;
    for (int it = 0; it < iterations; ++it) {
      if (!measure(xi, b, h, &jac)) return false;
      projectHeading(xi, b, jac);
      // Gauss-Newton step of the iterated EKF, from the prior each time; one iteration is the
      // plain EKF.
      // At the first iteration xi = x0 and the Jacobian term is zero.
      const MeasVec innov = it == 0 ? MeasVec(b.z - h) : MeasVec(b.z - h - jac * (x0 - xi));
      if (iterations > 1) p = m_P;
      if (!sequentialUpdate(jac, innov, b, updated, dx)) return false;
      const Vec next = x0 + dx;
      const double change = (next - xi).norm();
      xi = next;
      if (change < 1e-9) break;
    }
    m_x = xi;
    if (iterations > 1) m_P = p;
    return true;
  }

  bool ukfUpdate(const BlockList& b, bool& outOfView) {
    // Scaled unscented transform, alpha = 1, beta = 2, kappa = 0: positive weights 1/(2N).
    constexpr int kPoints = 2 * N + 1;
    prepareHeadingBlind();
    // A heading-blind IMU-only update spreads its sigma points without the heading: the state is
    // split as x = d + a v (a = u . x the heading, d the rest, u . d = 0), the readings depend on
    // d alone, and the sigma points follow d's covariance Pi P Pi^T with Pi = I - v u^T. Spread
    // along a straight line in joint space by the tens of degrees an arm without optics has in
    // heading, they would only measure how that line leaves the curved symmetry.
    const bool conditioned = m_headingBlind.active && !b.anyOptical();
    Mat spread = m_P;
    Mat pi = Mat::Identity();
    if (conditioned) {
      pi -= m_headingBlind.v * m_headingBlind.u.transpose();
      spread = pi * m_P * pi.transpose();
      spread.diagonal().array() += 1e-12;
    }
    Eigen::LLT<Mat> llt(static_cast<double>(N) * spread);
    if (llt.info() != Eigen::Success) {
      if (conditioned) return false;
      repairCovariance();
      llt.compute(static_cast<double>(N) * m_P);
      if (llt.info() != Eigen::Success) return false;
    }
    const Mat l = llt.matrixL();
    const int m = b.rows();
    Eigen::Matrix<double, Eigen::Dynamic, kPoints, 0, kMaxRows, kPoints> z(m, kPoints);
    MeasVec h;
    outOfView = false;
    auto sigma = [&](const Vec& x, int col) {
      if (!measure(x, b, h, nullptr)) return false;
      z.col(col) = h;
      return true;
    };
    bool seen = sigma(m_x, 0);
    for (int i = 0; i < N && seen; ++i)
      seen = sigma(m_x + l.col(i), 1 + i) && sigma(m_x - l.col(i), 1 + N + i);
    if (!seen) {
      outOfView = true;
      return false;
    }
    const double w = 1.0 / (2.0 * N);
    const double w0c = 2.0;
    const MeasVec zMean = z.rightCols(2 * N).rowwise().sum() * w;
    MeasMat pzz = w0c * (z.col(0) - zMean) * (z.col(0) - zMean).transpose();
    Gain pxz = Gain::Zero(N, m);
    for (int i = 0; i < N; ++i) {
      const MeasVec dp = z.col(1 + i) - zMean;
      const MeasVec dm = z.col(1 + N + i) - zMean;
      pzz += w * (dp * dp.transpose() + dm * dm.transpose());
      pxz += w * l.col(i) * (dp - dm).transpose();
    }
    // The unscented transform's equivalent linearisation H = Pxz^T P^-1 gets the same heading
    // projection as the EKF's Jacobian; the rest of Pzz (nonlinearity) is kept. (Sigma points
    // conditioned on the heading already see none of it.)
    if (!conditioned) {
      const Eigen::LLT<Mat> pl(m_P);
      if (pl.info() != Eigen::Success) return false;
      Jac hs = pl.solve(pxz).transpose();
      const MeasMat linearPart = hs * m_P * hs.transpose();
      if (projectHeading(m_x, b, hs)) {
        pzz += hs * m_P * hs.transpose() - linearPart;
        pxz = m_P * hs.transpose();
      }
    }
    pzz.diagonal() += b.variance;
    const Eigen::LLT<MeasMat> sl(pzz);
    if (sl.info() != Eigen::Success) return false;
    watchInnovation(b, b.z - zMean, pzz);
    if (conditioned) {
      // pxz is d's cross-covariance; the whole state's follows from the linearisation it implies,
      // H^T = cov(d)^-1 pxz on d, that is P Pi^T H^T. The gain is then d's: the heading stays.
      const Eigen::LLT<Mat> dl(spread);
      if (dl.info() != Eigen::Success) return false;
      const Gain full = m_P * pi.transpose() * dl.solve(pxz);
      const Gain k = sl.solve(pxz.transpose()).transpose();
      m_x += k * (b.z - zMean);
      m_P += k * pzz * k.transpose() - k * full.transpose() - full * k.transpose();
      symmetrise(m_P);
      return true;
    }
    Gain k = sl.solve(pxz.transpose()).transpose();
    if (m_headingBlind.active) {
      // The IMU rows' gain leaves the heading alone (see blockUpdate); P follows the gain used.
      for (int i = 0; i < b.count; ++i) {
        if (isOptical(b.block[i])) continue;
        auto cols = k.middleCols(b.offset[i], b.size[i]);
        cols -= m_headingBlind.v * (m_headingBlind.u.transpose() * cols);
      }
      m_x += k * (b.z - zMean);
      m_P += k * pzz * k.transpose() - k * pxz.transpose() - pxz * k.transpose();
      symmetrise(m_P);
      return true;
    }
    m_x += k * (b.z - zMean);
    m_P -= k * pzz * k.transpose();
    return true;
  }

  // Observability constraint: IMU rows must not see the heading (turning the whole arm about the
  // vertical changes no IMU reading). Linearisation at a moving state would otherwise make the
  // heading look observable and its variance collapse. Returns whether any row was changed.
  bool projectHeading(const Vec& x, const BlockList& b, Jac& jac) {
    Vec v = Vec::Zero();
    v.template head<kBase>() = headingSymmetryAt(x.template head<kBase>());
    const double vv = v.squaredNorm();
    if (vv <= 0.0) return false;
    bool changed = false;
    for (int i = 0; i < b.count; ++i) {
      if (isOptical(b.block[i])) continue;
      auto rows = jac.template middleRows<3>(b.offset[i]);
      const Eigen::Vector3d hv = rows * v;
      rows -= hv * v.transpose() / vv;
      changed = true;
    }
    return changed;
  }

  // Unit heading direction among the angles at x: the rotation of the whole arm about the
  // vertical, rates and accelerations held (zero elsewhere).
  Vec headingAngles(const Vec& x) const {
    Vec u = Vec::Zero();
    const JointVector& d = generatorAt(x.template segment<5>(10));  // headingDirection, cached
    const double n = d.norm();
    u.template segment<5>(10) = n > 0 ? JointVector(d / n) : d;
    return u;
  }

  // headingGenerator at th, remembered for the last angles asked: a step asks at the predicted
  // angles (process noise, heading symmetry, heading matching, the optical and heading-blind
  // updates) and then at the updated ones (heading floor, estimate()) up to eight times.
  const JointVector& generatorAt(const JointVector& th) const {
    if (!m_generator || m_generator->first != th)
      m_generator.emplace(th, headingGenerator(th, m_up));
    return m_generator->second;
  }

  // P holds the heading's variance to first order: a turn of the whole arm about the vertical
  // moves the shoulder angles along hu. Far from small, the turn bends through joint space (near
  // the gimbal lock a 40 deg turn can move flexion 14 deg where the first-order step says 1), so
  // when the heading is uncertain by more than a degree the reported variance takes the joints'
  // mean squared excursion under the exact turn, over the heading's distribution, in place of the
  // first-order part. (Half the excursion at two standard deviations each way, used before,
  // overstated it: IMU-only abduction had 99.8-100 % of its errors inside two sd.)
  void addHeadingCurvature(const JointVector& th, double headingVar, const JointVector& hu,
                           JointVector& var) const {
    const double rate = generatorAt(th).norm();  // joint rad per rad of turn
    if (!(rate > 0.0) || !(headingVar > 0.0)) return;
    const double turnStd = std::sqrt(headingVar) / rate;
    constexpr double kFirstOrderEnough = 1.0 * kDeg;
    if (turnStd < kFirstOrderEnough) return;
    const JointVector moment = turnSecondMoment(th, turnStd, m_up);
    for (int j = 0; j < 3; ++j) var(j) += std::max(0.0, moment(j) - headingVar * hu(j) * hu(j));
  }

  // Heading honesty. The projection of the IMU rows keeps IMU-only updates from moving the
  // heading, but information still leaks in (through correlations, and because the linearisation
  // point moves with the noisy joint accelerations), so P's heading variance shrinks below what
  // is known. The filter therefore tracks a floor beside P: the heading variance start-up (or the
  // last optical fix) left, plus the heading random walk since. The reported angle uncertainty
  // includes it, and the first optical update after IMU-only data gets it back into P, so the
  // optical heading correction is taken at once. Changing P during IMU-only updates instead makes
  // the filter unstable.
  double headingShortfall(const Vec& u) const {
    // Heading-blind IMU updates keep P's heading variance honest by themselves; the floor is for
    // Methods B and C, whose IMU updates leak information into it.
    const double floor = headingBlind() ? 0.0 : m_headingFloor;
    return std::max(0.0, std::max(floor, m_headingMatch) - headingVariance(u));
  }

  // u^T P u for a heading direction u from headingAngles, which is zero outside the angles: the
  // angle block alone (a 5x5 product instead of a 15x15 one, two or three times a step).
  double headingVariance(const Vec& u) const {
    const JointVector hu = u.template segment<5>(10);
    return hu.dot(m_P.template block<5, 5>(10, 10) * hu);
  }

  void afterUpdate(bool optical) {
    if (optical) {
      m_headingFloor = headingVariance(headingAngles(m_x));
    }
  }

  void beforeOpticalUpdate() {
    m_headingFloor = std::max(m_headingFloor, m_headingMatch);
    const Vec u = headingAngles(m_x);
    // u is zero outside the angles: only P's angle block changes, and only by a shortfall.
    const double shortfall = headingShortfall(u);
    if (shortfall == 0.0) return;
    const JointVector hu = u.template segment<5>(10);
    m_P.template block<5, 5>(10, 10) += shortfall * hu * hu.transpose();
  }

  // The six blocks' predicted readings and their Jacobian at the predicted state, which the
  // optical gate and heading matching both read before the update: computed once per sample.
  struct Prediction {
    Vec15 at;  // the state they were computed at
    Eigen::Matrix<double, kModelRows, 1> readings;
    Eigen::Matrix<double, kModelRows, kBase> jacobian;
  };
  const Prediction& priorPrediction() {
    if (!m_prior) {
      m_prior.emplace();
      m_prior->at = m_x.template head<kBase>();
      predictReadings(m_p.geometry, m_p.gUp, m_p.model == MeasurementModel::AccelGyro, m_prior->at,
                      m_prior->readings, &m_prior->jacobian);
    }
    return *m_prior;
  }

  // Heading matching (covariance matching along the one direction the IMUs cannot see): the
  // turn about the vertical that the optical rows ask for at the predicted state, by weighted
  // least squares, less what their noise alone would give, averaged over headingMatchTime, is
  // the heading variance the filter should have. After a fast movement has turned the estimate
  // about the vertical, P's heading variance is far smaller than the error, the optics pull at a
  // few percent per frame and the angles stay off for seconds; with the matched variance the
  // next frames correct it, and the reported standard deviation says the heading was uncertain.
  // Returns false when the optical rows could not be evaluated.
  bool matchOpticalHeading(const BlockList& b, bool positionsOnly) {
    if (!(m_p.headingMatchTime > 0.0)) return true;
    const Vec u = headingAngles(m_x);
    const Vec15 u15 = u.template head<kBase>();
    const Eigen::Matrix<double, kModelRows, 1>& all = priorPrediction().readings;
    const Eigen::Matrix<double, kModelRows, kBase>& allJac = priorPrediction().jacobian;
    double info = 0.0, score = 0.0;
    for (int i = 0; i < b.count; ++i) {
      const int blk = b.block[i];
      if (blk == kElbow || blk == kWrist) {
        const Eigen::Vector3d r = b.z.template segment<3>(b.offset[i]) - all.segment<3>(3 * blk);
        const Eigen::Vector3d jh = allJac.middleRows<3>(3 * blk) * u15;
        info += jh.squaredNorm() / m_p.positionVariance;
        score += jh.dot(r) / m_p.positionVariance;
      } else if (isCamera(blk) && m_camera && !positionsOnly) {
        const int posBlock = blk == kCamWrist ? kWrist : kElbow;
        const Eigen::Matrix<double, 3, kBase> dp = allJac.middleRows<3>(3 * posBlock);
        Eigen::Vector2d px;
        Eigen::Matrix<double, 2, kBase> jac;
        if (!markerPixel(*m_camera, m_p.side == Side::Left, all.segment<3>(3 * posBlock), &dp, px,
                         &jac))
          continue;
        const Eigen::Vector2d r = b.z.template segment<2>(b.offset[i]) - px;
        const Eigen::Vector2d jh = jac * u15;
        info += jh.squaredNorm() / m_p.pixelVariance;
        score += jh.dot(r) / m_p.pixelVariance;
      }
    }
    if (!std::isfinite(info) || !std::isfinite(score)) return false;
    if (!(info > 0.0)) return true;
    const double turn = score / info;  // rad about the vertical
    const double since = std::isfinite(m_lastMatchT) ? m_t - m_lastMatchT : m_p.headingMatchTime;
    m_lastMatchT = m_t;
    const double w = std::clamp(since / m_p.headingMatchTime, 0.0, 1.0);
    m_turnSquared += w * (turn * turn - m_turnSquared);
    m_turnNoise += w * (1.0 / info - m_turnNoise);
    // Only a turn well beyond what the optical noise gives (2 sigma) counts: below that the
    // filter's own heading variance is the better judge, and matching the noise would make the
    // estimate follow it.
    m_headingMatch = std::clamp(m_turnSquared - 4.0 * m_turnNoise, 0.0, kMaxHeadingMatch);
    return true;
  }

  // Rows the consistency watch reads: the gyroscopes, which every model predicts exactly, and
  // the accelerometers only where the model includes body acceleration (Method A); Methods B
  // and C leave it out on purpose, so their accelerometer innovations are large in any motion.
  bool watched(int block) const {
    if (block == kUaGyr || block == kFaGyr) return true;
    return (block == kUaAcc || block == kFaAcc) && m_p.model == MeasurementModel::AccelGyro;
  }

  // The UKF's consistency watch: the normalised innovation squared of the watched rows alone, as
  // the EKF's block updates count it. With every row, Method C's and B's accelerometers (body
  // acceleration left out of their model) read as a lost arm within 0.15 s of any fast motion,
  // and the UKF restarted again and again.
  void watchInnovation(const BlockList& b, const MeasVec& nu, const MeasMat& s) {
    std::array<int, kMaxRows> rows{};
    int n = 0;
    for (int i = 0; i < b.count; ++i)
      if (watched(b.block[i]))
        for (int r = 0; r < b.size[i]; ++r) rows[n++] = b.offset[i] + r;
    MeasMat sw(n, n);
    MeasVec nw(n);
    for (int i = 0; i < n; ++i) {
      nw(i) = nu(rows[i]);
      for (int j = 0; j < n; ++j) sw(i, j) = s(rows[i], rows[j]);
    }
    const Eigen::LLT<MeasMat> llt(sw);
    m_updateNis = n > 0 && llt.info() == Eigen::Success ? nw.dot(llt.solve(nw)) : 0.0;
    m_updateDof = llt.info() == Eigen::Success ? n : 0;
  }

  // The recent past, for the window fit: fused readings only, in the right-arm frame.
  void remember(const ArmSample& clean) {
    ArmSample kept = clean;
    kept.trueAngles.reset();
    kept.estimate.reset();
    m_recent.push_back(std::move(kept));
    m_recentStates.push_back(m_x.template head<kBase>());
    while (!m_recent.empty() && m_recent.front().t < m_t - m_p.fitWindowSeconds) {
      m_recent.pop_front();
      m_recentStates.pop_front();
    }
  }

  std::vector<ArmSample> recentSince(double t, std::vector<Vec15>* states = nullptr) const {
    std::vector<ArmSample> w;
    for (std::size_t i = 0; i < m_recent.size(); ++i) {
      if (m_recent[i].t < t) continue;
      w.push_back(m_recent[i]);
      if (states) states->push_back(m_recentStates[i]);
    }
    return w;
  }

  // Seeds for a window fit at the latest sample: the running state, and the single-sample
  // start pose there (rates from the gyroscopes). When the window holds no optical data but an
  // optical fix set the heading, only the running state: the fit cannot see the heading, and
  // the single-sample pose would bring the start-up prior's heading back.
  static bool anyOptical(const std::vector<ArmSample>& w) {
    for (const ArmSample& r : w)
      if (r.elbow || r.wrist || r.camWrist || r.camElbow) return true;
    return false;
  }

  std::vector<Vec15> fitSeeds(const ArmSample& last, const std::vector<ArmSample>& w) const {
    std::vector<Vec15> seeds{m_x.template head<kBase>()};
    if (!anyOptical(w) && std::isfinite(m_lastOpticalT)) return seeds;
    const InitialPose pose = initialPose(m_p, last);
    Vec15 x = Vec15::Zero();
    x.template segment<5>(5) = pose.thd;
    x.template segment<5>(10) = pose.th;
    seeds.push_back(x);
    // The pose at the window's latest optical frame, with the IMU readings just before it, carried
    // to the window's end at its gyroscope rates: optical positions pin the upper arm and the
    // elbow where a single IMU sample in fast motion (gravity hidden in body acceleration) cannot.
    for (auto it = w.rbegin(); it != w.rend(); ++it) {
      if (!(it->elbow || it->wrist || it->camWrist || it->camElbow)) continue;
      ArmSample merged = *it;
      for (auto imu = it; imu != w.rend(); ++imu) {
        if (!imu->hasImu()) continue;
        merged.upperArm = imu->upperArm;
        merged.forearm = imu->forearm;
        break;
      }
      if (!merged.hasImu()) break;
      const InitialPose at = initialPose(m_p, merged);
      Vec15 y = Vec15::Zero();
      y.template segment<5>(5) = at.thd;
      y.template segment<5>(10) = at.th + at.thd * (last.t - it->t);
      seeds.push_back(y);
      break;
    }
    return seeds;
  }

  // Start-up in mid-motion: once fitWindowSeconds of data are in, a batch fit of one smooth
  // motion to all of them replaces the running state when it explains the data clearly better.
  bool refitFromWindow(double since) {
    std::vector<Vec15> states;
    const std::vector<ArmSample> w = recentSince(since, &states);
    if (w.size() < 2) return false;
    // A window without optical data: the fit cannot see the heading, so it holds the running
    // state's (an optical fix's, or the start pose's), and the heading keeps the variance it had.
    // Left free, it would take whichever heading its seed had.
    std::optional<JointVector> anchor;
    if (!anyOptical(w)) anchor = m_x.template segment<5>(10);
    const WindowFitResult fit = fitWindow(m_p, w, fitSeeds(w.back(), w), anchor);
    if (!fit.explains(kGoodFitRms) || !inAnatomicalRange(fit.x)) return false;
    if (!(fit.rms < kRefitGain * trajectoryRms(m_p, w, states))) return false;
    const Vec u = headingAngles(m_x);
    const double headingVar = u.dot(m_P * u) + headingShortfall(u);
    takeFit(fit, w);
    if (anchor) {
      // The start covariance without optics spreads the heading over the start-up prior's 30 deg;
      // the anchored fit kept the fix's heading, so P keeps the fix's heading variance instead.
      startCovariance(true);
      Vec v = Vec::Zero();
      v.template head<kBase>() = headingSymmetry(m_x.template head<kBase>(), m_up);
      m_P += headingVar * v * v.transpose();
      m_headingFloor = headingVar;
      finishUpdate();
    }
    ++m_counters.startupRefits;
    return true;
  }

  // A fitted state replaces the running one with the start-up covariance: the fit is good to a
  // few degrees, and the filter must stay ready to take the next corrections.
  void takeFit(const WindowFitResult& fit, const std::vector<ArmSample>& w) {
    m_x.template head<kBase>() = fit.x;
    bool optical = false;
    for (const ArmSample& r : w)
      optical = optical || r.elbow || r.wrist || (r.camWrist && r.camElbow);
    startCovariance(optical);
    finishUpdate();
  }

  // Consistency watch: IMU innovations far beyond their covariance for lostAfterSeconds in a
  // row, or a state no arm can be in, mean the filter has lost the arm.
  bool lost() {
    if (!m_x.allFinite() ||
        m_x.template segment<5>(5).cwiseAbs().maxCoeff() > m_p.plausibility.gyroRange)
      return true;
    if (m_t - m_t0 < m_p.startupSeconds) return false;
    // The optics kept contradicting the state (a gated point, frame after frame): the IMUs alone
    // cannot fix a wrong heading or branch, so start again from the window.
    if (m_opticalDisagrees) {
      m_opticalDisagrees = false;
      return true;
    }
    if (m_updateDof == 0) return false;
    if (m_updateNis / m_updateDof <= m_p.lostNis) {
      m_badSince.reset();
      return false;
    }
    if (!m_badSince) m_badSince = m_t;
    return m_t - *m_badSince >= m_p.lostAfterSeconds;
  }

  // Re-initialises from the recent window (or, when that fails, from the sample alone), counts it
  // and reports it: the estimate jumps here without the arm having moved.
  UpdateResult recover(const ArmSample& last) {
    ++m_counters.recoveries;
    m_badSince.reset();
    const std::vector<ArmSample> w = recentSince(m_t - m_p.fitWindowSeconds);
    const std::vector<Vec15> seeds = fitSeeds(last, w);
    initialise(last);  // fresh covariance, start-up noise and iterations, a new start-up fit
    if (w.size() >= 2) {
      const WindowFitResult fit = fitWindow(m_p, w, seeds);
      if (fit.explains(kGoodFitRms) && inAnatomicalRange(fit.x)) takeFit(fit, w);
    }
    remember(last);
    return UpdateResult::Recovered;
  }

  // Covariance matching: the squared correction an update makes to each joint acceleration,
  // per reference step and averaged over adaptationTime, is the process noise the motion needs.
  void matchProcessNoise(const Vec& xPredicted, double dt) {
    if (!m_p.adaptiveProcessNoise || m_p.model != MeasurementModel::AccelGyro || !(dt > 0.0) ||
        !(m_p.adaptationTime > 0.0))
      return;
    const double w = std::min(1.0, dt / m_p.adaptationTime);
    for (int j = 0; j < kNumJoints; ++j) {
      const double d = m_x(j) - xPredicted(j);
      m_matchedQ(j) += w * (d * d * m_p.referenceStep / dt - m_matchedQ(j));
      m_matchedQ(j) = std::min(m_matchedQ(j), m_p.maxJointAccelVariance);
    }
  }

  // The joints' squared jerk, summed over the joints: the estimate's joint accelerations
  // change from one accelerometer update to the next (optical rows between two IMU rows are part
  // of the step, so its length is the IMU's sampling however the rows interleave), squared and
  // averaged over adaptationTime, after start-up only (its corrections are convergence, not
  // motion). It sets the accelerometers' model error (accelJerkVariance). Each change holds the
  // update's noise-driven correction as well as the motion: at rest between fast reaches it
  // reads about 30 times the true squared jerk, and widens the accelerometers by 2-9 times their
  // noise variance. A smoothed jerk (the accelerations less their running
  // mean) that reads the motion alone left the shoulder less honest (docs/estimator.md).
  void trackJerk() {
    const JointVector thdd = m_x.template head<5>();
    if (m_t - m_t0 >= m_p.startupSeconds && m_jerkFrom && m_p.adaptationTime > 0.0) {
      const double dt = m_t - m_jerkFrom->first;
      if (dt > 0.0) {
        const double w = std::min(1.0, dt / m_p.adaptationTime);
        const double j2 = (thdd - m_jerkFrom->second).squaredNorm() / (dt * dt);
        m_jerkSquared += w * (j2 - m_jerkSquared);
      }
    }
    m_jerkFrom.emplace(m_t, thdd);
  }

  void finishUpdate() {
    for (int j = 0; j < kNumJoints; ++j) m_x(10 + j) = wrapAngle(m_x(10 + j));
    symmetrise(m_P);
    keepInAnatomicalRange();
    freezeInactive();
    // A negative or vanishing variance means round-off has eaten positive definiteness.
    if ((m_P.diagonal().array() <= 0.0).any()) repairCovariance();
  }

  // P = (P + P^T) / 2 in place, pair by pair: each entry gets the 0.5 (a + b) of the whole
  // expression (the diagonal is unchanged), without its 15x15 temporary.
  static void symmetrise(Mat& p) {
    for (int c = 0; c < N; ++c)
      for (int r = c + 1; r < N; ++r) p(r, c) = p(c, r) = 0.5 * (p(r, c) + p(c, r));
  }

  // A window fit that ends outside the anatomical range has found the other Euler branch (the
  // same arm, which the sensors cannot tell apart) or a wrong minimum: not taken.
  bool inAnatomicalRange(const Vec15& x) const {
    for (int j = 0; j < kNumJoints; ++j) {
      const double th = wrapAngle(x(10 + j));
      if (m_p.activeJoints[j] && (th < m_p.jointLower(j) || th > m_p.jointUpper(j))) return false;
    }
    return true;
  }

  // Estimate projection (Simon & Chia 2002) onto each violated limit in turn: the joint goes to
  // the nearest limit (wrapped), and every state correlated with it moves by the gain P e / P_ii.
  // The covariance is kept: the limit is knowledge about the arm, not a measurement.
  void keepInAnatomicalRange() {
    for (int j = 0; j < kNumJoints; ++j) {
      const int i = 10 + j;
      const double th = m_x(i), lo = m_p.jointLower(j), hi = m_p.jointUpper(j);
      if (!m_p.activeJoints[j] || (th >= lo && th <= hi) || !(m_P(i, i) > 0.0)) continue;
      const double toLo = std::isfinite(lo) ? wrapAngle(lo - th) : kInf;
      const double toHi = std::isfinite(hi) ? wrapAngle(hi - th) : kInf;
      const double step = std::abs(toLo) < std::abs(toHi) ? toLo : toHi;
      if (!std::isfinite(step)) continue;
      m_x += m_P.col(i) * (step / m_P(i, i));
      for (int k = 0; k < kNumJoints; ++k) m_x(10 + k) = wrapAngle(m_x(10 + k));
      ++m_counters.limitedStates;
    }
  }

  void repairCovariance() {
    ++m_counters.covarianceRepairs;
    Eigen::SelfAdjointEigenSolver<Mat> es(0.5 * (m_P + m_P.transpose()));
    Vec ev = es.eigenvalues().cwiseMax(1e-12);
    m_P = es.eigenvectors() * ev.asDiagonal() * es.eigenvectors().transpose();
  }

  // Inactive joints are held at their fixed value with a tiny variance (keeps P positive definite).
  void freezeInactive() {
    for (int j = 0; j < kNumJoints; ++j) {
      if (m_p.activeJoints[j]) continue;
      for (int d = 0; d < 3; ++d) {
        const int i = 5 * d + j;
        m_P.row(i).setZero();
        m_P.col(i).setZero();
        m_P(i, i) = 1e-12;
        m_x(i) = d == 2 ? m_p.fixedAngles(j) : 0.0;
      }
    }
  }

  // The end of a kinematic start-up (startupModel): the state and covariance carry over to the
  // model asked for; Method A's matched process noise does not, nor its heading floor.
  void handOver() {
    m_p.model = m_model;
    m_matchedQ.setZero();
    m_jerkSquared = 0.0;
    m_jerkFrom.reset();
    if constexpr (kAugmented) {
      // Method B's body-acceleration states start from what the kinematics say they are.
      Eigen::Matrix<double, kModelRows, 1> with, without;
      const Vec15 base = m_x.template head<kBase>();
      predictReadings(m_p.geometry, m_p.gUp, true, base, with, nullptr);
      predictReadings(m_p.geometry, m_p.gUp, false, base, without, nullptr);
      m_x.template segment<3>(kBase) = (with - without).template segment<3>(3 * kUaAcc);
      m_x.template segment<3>(kBase + 3) = (with - without).template segment<3>(3 * kFaAcc);
    }
    const Vec u = headingAngles(m_x);
    m_headingFloor = u.dot(m_P * u);
  }

  EstimatorParams m_p;
  MeasurementModel m_model;  // the model asked for; m_p.model may differ during start-up
  Eigen::Vector3d m_up;  // unit up vector, frame 0
  Vec m_x;
  Mat m_P;
  bool m_initialised = false;
  double m_t = 0.0;   // time of the state (s)
  double m_t0 = 0.0;  // time of the last (re)initialisation (s)
  double m_lastSeenT = 0.0;
  double m_lastDataT = 0.0;  // time of the last sample whose readings were fused (s)
  double m_lastOpticalT = 0.0;
  static constexpr double kRefitGain =
      0.7;  // a start-up fit must explain the data this much better
  static constexpr double kGoodFitRms = 3.0;  // whitened residual RMS of a fit worth taking
  std::deque<Vec15> m_recentStates;           // the filter's state after each of m_recent
  bool m_opticalDisagrees = false;            // an optical point was gated many frames in a row
  JointVector m_matchedQ = JointVector::Zero();  // matched joint-acceleration noise, (rad/s^2)^2
  double m_jerkSquared = 0.0;  // the joints' squared jerk, (rad/s^3)^2 (trackJerk)
  // The last accelerometer update: its time and joint accelerations (trackJerk).
  std::optional<std::pair<double, JointVector>> m_jerkFrom;
  std::deque<ArmSample> m_recent;    // fused samples of the last fitWindowSeconds
  std::optional<double> m_fitAt;     // when the start-up window fit is due (s)
  std::optional<double> m_badSince;  // start of a run of inconsistent IMU updates (s)
  double m_updateNis = 0.0;          // normalised innovation squared of the last update (IMU rows)
  int m_updateDof = 0;               // rows m_updateNis sums over
  double m_headingFloor = 0.0;       // least variance along the heading while IMU-only (rad^2)
  double m_headingMatch = 0.0;       // heading variance the optical innovations ask for (rad^2)
  double m_turnSquared = 0.0;        // running mean of the squared turn the optics ask for (rad^2)
  double m_turnNoise = 0.0;          // ... and of its variance from optical noise alone (rad^2)
  double m_lastMatchT = -std::numeric_limits<double>::infinity();
  static constexpr double kMaxHeadingMatch = (60.0 * kDeg) * (60.0 * kDeg);
  struct HeadingBlind {
    bool active = false;
    Vec v = Vec::Zero();              // full-state heading symmetry (its angle part is u)
    Vec u = Vec::Zero();              // reads the turn about the vertical (u . v = 1)
  } m_headingBlind;                   // prepareHeadingBlind() for the present update
  std::optional<Prediction> m_prior;  // priorPrediction() of the present sample
  std::optional<std::pair<Vec15, Vec15>> m_heading;  // a state and its headingSymmetry
  mutable std::optional<std::pair<JointVector, JointVector>> m_generator;  // th, headingGenerator
  std::optional<ArmSample> m_pendingOptical;
  std::optional<PinholeCamera> m_camera;  // when params carry a camera and useCamera is set
  // Consecutive gated frames: wrist marker, elbow marker, wrist position, elbow position.
  std::array<int, 4> m_gatedInARow{0, 0, 0, 0};
  SampleGate m_gate;
  EstimatorCounters m_counters;
};

}  // namespace

std::unique_ptr<JointEstimator> makeEstimator(const EstimatorParams& params) {
  if (params.model == MeasurementModel::AugmentedBodyAccel)
    return std::make_unique<ArmFilter<kBase + 6>>(params);
  return std::make_unique<ArmFilter<kBase>>(params);
}

EstimatorParams recordingParams(const RecordingMeta& meta) {
  EstimatorParams p;
  p.geometry = meta.geometry;
  p.gUp = meta.gUp();
  p.side = meta.side;
  p.camera = meta.camera;
  return p;
}

BatchResult estimateSamples(const std::vector<ArmSample>& samples, const EstimatorParams& params) {
  BatchResult out;
  auto filter = makeEstimator(params);
  out.estimates.reserve(samples.size());
  for (const ArmSample& s : samples) {
    const UpdateResult r = filter->update(s);
    if (hasEstimate(r) && s.hasImu()) out.estimates.push_back(filter->estimate());
  }
  out.counters = filter->counters();
  return out;
}

Eigen::Matrix<double, 18, 1> predictAll(const EstimatorParams& params,
                                        const Eigen::Matrix<double, 15, 1>& x) {
  Eigen::Matrix<double, kModelRows, 1> out;
  predictBase<double>(params, x, out);
  return out;
}

Eigen::Matrix<double, 18, 15> predictAllJacobian(const EstimatorParams& params,
                                                 const Eigen::Matrix<double, 15, 1>& x) {
  Eigen::Matrix<double, kModelRows, 1> h;
  Eigen::Matrix<double, kModelRows, kBase> jac;
  predictBaseWithJacobian(params, x, h, jac);
  return jac;
}

bool predictMarkerPixel(const EstimatorParams& params, const Eigen::Matrix<double, 15, 1>& x,
                        bool wrist, Eigen::Vector2d& pixel, Eigen::Matrix<double, 2, 15>* jac) {
  if (!params.camera) return false;
  const PinholeCamera camera(*params.camera);
  const int block = wrist ? kWrist : kElbow;
  Eigen::Matrix<double, kModelRows, 1> h;
  Eigen::Matrix<double, kModelRows, kBase> all;
  predictBaseWithJacobian(params, x, h, all);
  const Eigen::Matrix<double, 3, kBase> dp = all.middleRows<3>(3 * block);
  return markerPixel(camera, params.side == Side::Left, h.segment<3>(3 * block), &dp, pixel, jac);
}

}  // namespace armtrack
