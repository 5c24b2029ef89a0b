// The estimator behind makeEstimator(): one class template over the state size (15, or 21 with
// Method B's body-acceleration states). Private to the estimator. Its members are defined in
//   ArmFilter.cpp          the update of one sample: prediction, measurement
//   ArmFilterEkf.cpp       the EKF update, one block at a time
//   ArmFilterOptical.cpp   the optical rows' gate, heading matching
//   ArmFilterHeading.cpp   the heading the IMUs cannot see: symmetry, heading-blind update, floor
//   ArmFilterUkf.cpp       the unscented update
//   ArmFilterRecovery.cpp  start, window fits, the consistency watch and recovery, limits
//   ArmFilterTrunk.cpp     a moving trunk: frame 0's motion, optical data into frame 0
// each instantiated there for both state sizes. docs/estimator.md explains the method.
#pragma once

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <array>
#include <deque>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "core/camera/PinholeCamera.h"
#include "core/estimation/ArmFilter.h"
#include "core/estimation/BlockUpdate.h"
#include "core/estimation/Heading.h"
#include "core/estimation/MeasurementBlocks.h"
#include "core/estimation/SampleGate.h"
#include "core/estimation/TrunkTracker.h"
#include "core/estimation/WindowFit.h"

namespace armtrack::detail {

// Whether every entry of m is finite, in SIMD packets: m - m is zero where an entry is finite and
// NaN where it is not, so the sum of the differences is zero exactly when all are finite.
// (Eigen's allFinite tests entry by entry with a branch each: 225 of them for P, every step.)
template <typename Derived>
bool allFiniteFast(const Eigen::MatrixBase<Derived>& m) {
  return (m.array() - m.array()).sum() == 0.0;
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
      : m_p(mirrored(p)),
        m_model(p.model),
        m_up(m_p.gUp.normalized()),
        m_gate(gateLimits(m_p)),
        m_restBias{RestBias(m_p.restBias), RestBias(m_p.restBias)} {
    if (m_p.camera && m_p.useCamera) m_camera.emplace(*m_p.camera);  // throws on a bad camera
    m_base.up = m_p.gUp;
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
    if (p.side == Side::Left) {
      p.gUp = mirrorPoint(p.gUp);
      if (p.trunk) p.trunk = mirrorMount(*p.trunk);
    }
    return p;
  }

  void reset() override;

  bool initialised() const override { return m_initialised; }
  const EstimatorCounters& counters() const override { return m_counters; }
  Eigen::MatrixXd covariance() const override { return m_P; }

  bool headingFromStartPoseOnly() const override {
    constexpr double kHeadingMemory = 5.0;  // s an optical fix is taken to hold the heading
    return !(m_t - m_lastOpticalT <= kHeadingMemory);
  }

  JointEstimate estimate() const override;
  std::optional<TrunkEstimate> trunk() const override;

  UpdateResult update(const ArmSample& s) override;

 private:
  // The six blocks' predicted readings and their Jacobian at the predicted state, which the
  // optical gate and heading matching both read before the update: computed once per sample.
  struct Prediction {
    Vec15 at;  // the state they were computed at
    Eigen::Matrix<double, kModelRows, 1> readings;
    Eigen::Matrix<double, kModelRows, kBase> jacobian;
  };

  // ArmFilter.cpp: one sample's update
  ArmSample sanitise(const ArmSample& s);
  BlockList gather(const ArmSample& s) const;
  void predict(double dt);
  bool measure(const Vec& x, const BlockList& b, MeasVec& h, Jac* jac) const;
  void trackJerk();
  void finishUpdate();
  static void symmetrise(Mat& p);
  static void mirrorLower(Mat& p);

  // ArmFilterEkf.cpp: the EKF update
  bool sequentialUpdate(const Jac& jac, const MeasVec& innov, const BlockList& b, Mat& p, Vec& dx);
  template <int M>
  bool blockUpdate(const Jac& jac, const MeasVec& innov, const BlockList& b, int i,
                   PaddedCovariance<N>& p, Vec& dx);
  template <int M, int K>
  bool updateBlock(const Eigen::Matrix<double, M, K>& hj, int col, const MeasVec& innov,
                   const BlockList& b, int i, PaddedCovariance<N>& p, Vec& dx);
  bool ekfUpdate(const BlockList& b);

  // ArmFilterTiming.cpp: readings of sensors slower than the rows (held between new samples)
  void trackSampleTiming(const ArmSample& clean, double rowStep);
  double timingVariance(int block) const;
  double sampleDelay(const ArmSample& clean) const;

  // ArmFilterTrunk.cpp: a moving trunk
  void applyTrunk(ArmSample& s);
  double trunkPositionVariance(const Eigen::Vector3d& p) const;
  // The variance the arm's angles relative to the thorax take from the trunk's uncertain pose
  // (its rotation and the hip it turns about), added to var (rad^2).
  void addTrunkVariance(const JointVector& th, JointVector& var) const;
  // Without an optical shoulder: the hip pivot from the arm's optical points (world frame).
  void fitHipFromArm(const ArmSample& s);
  // Whether the EKF carries the state's sensitivity to the trunk's pose (m_trunkSens) through its
  // updates: with a sternum IMU, after start-up (whose iterated updates it does not follow).
  bool tracksTrunkSensitivity() const {
    return m_trunk && m_trunk->state().haveImu && m_p.filter == FilterKind::Ekf &&
           m_t - m_t0 >= m_p.startupSeconds;
  }
  // D of each optical block of the present update: how an error of the trunk's pose moves what
  // the block measures (m_trunkRows, rows of a camera block: its first two).
  void trunkMeasurementRows(const Vec& x, const BlockList& b);

  // ArmFilterOptical.cpp: the optical rows' gate and heading matching
  bool gateOptical(BlockList& b);
  const Prediction& priorPrediction();
  bool matchOpticalHeading(const BlockList& b, bool positionsOnly);

  // ArmFilterHeading.cpp: the heading the IMUs cannot see
  const Vec15& headingSymmetryAt(const Vec15& x);
  void prepareHeadingBlind();
  bool projectHeading(const Vec& x, const BlockList& b, Jac& jac);
  Vec headingAngles(const Vec& x) const;
  const JointVector& generatorAt(const JointVector& th) const;
  const HeadingGeometry& geometryAt(const JointVector& th) const;
  void addHeadingCurvature(const JointVector& th, double headingVar, const JointVector& hu,
                           JointVector& var) const;
  double headingShortfall(const Vec& u) const;
  void beforeOpticalUpdate();

  // ArmFilterUkf.cpp: the unscented update
  bool ukfUpdate(const BlockList& b, bool& outOfView);
  void watchInnovation(const BlockList& b, const MeasVec& nu, const MeasMat& s);

  // ArmFilterRecovery.cpp: start, window fits, watch and recovery, limits
  void initialise(const ArmSample& s);
  void startCovariance(bool optical);
  void remember(const ArmSample& clean);
  std::vector<ArmSample> recentSince(double t, std::vector<Vec15>* states = nullptr,
                                     std::vector<WindowFrame>* frames = nullptr) const;
  EstimatorParams paramsInFrame() const;
  static bool anyOptical(const std::vector<ArmSample>& w);
  std::vector<Vec15> fitSeeds(const ArmSample& last, const std::vector<ArmSample>& w) const;
  bool refitFromWindow(double since);
  void takeFit(const WindowFitResult& fit, const std::vector<ArmSample>& w);
  bool lost();
  UpdateResult recover(const ArmSample& last);
  void matchProcessNoise(const Vec& xPredicted, double dt);
  bool inAnatomicalRange(const Vec15& x) const;
  void keepInAnatomicalRange();
  void repairCovariance();
  void freezeInactive();
  void reopenAngles();
  // Methods B and C on real sensors (docs/estimator.md, "Methods B and C on realistic
  // sensors"): the optics' disagreement opens the angles up instead of a re-initialisation.
  // It belongs with the kinematic start-up: off with it, as the paper studies run the paper's
  // filters.
  bool inclinometerRealSensors() const {
    return (m_p.model == MeasurementModel::InclinometerGyro ||
            m_p.model == MeasurementModel::AugmentedBodyAccel) &&
           m_p.kinematicStartup;
  }
  void handOver();

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
  // instead of taking a random turn while start-up settles. Method A always. B and C leave body
  // acceleration out of their model, so their IMU innovations carry model error whose
  // correlations with the heading the filter needs to bleed off without optics (heading-blind,
  // IMUs only, they peaked at 53-131 deg); with optics seen in the last second (and the
  // kinematic start-up on, as inclinometerRealSensors) they are heading-blind too: otherwise a
  // fast reach turned them about the vertical by 30-50 deg at 1 deg of standard deviation, and
  // the gate then refused the markers that would have taken it back (docs/estimator.md,
  // "Methods B and C on realistic sensors").
  bool headingBlind() const {
    return m_p.headingBlindImuUpdates && headingIsFree() &&
           (m_p.model == MeasurementModel::AccelGyro ||
            (inclinometerRealSensors() && m_t - m_lastOpticalT < 1.0));
  }
  // A trunk that turns makes the heading visible to the arm's IMUs: its rate, angular
  // acceleration and the shoulder's acceleration reach each arm IMU through the arm's pose,
  // heading included, so turning the arm about the vertical no longer leaves their readings
  // alone. Projecting the heading out of their rows (projectHeading) then throws that away and
  // makes the filter explain what the heading would have by moving the other angles: on leaning
  // recordings with a Kinect, shoulder errors of 3-8 deg with under 60 % inside two sd; with
  // IMUs only, the humerus 2-3 deg off the vertical on fast reaches. So while frame 0 turns
  // faster than kTrunkTurningRate (the sternum IMU's rate noise is about 0.2 deg/s) the IMU rows
  // keep their heading part; the heading-blind gain still keeps IMU rows from moving the heading
  // (docs/estimator.md, "Trunk").
  static constexpr double kTrunkTurningRate = 2.0 * kDeg;  // rad/s
  bool trunkTurning() const {
    return m_trunk && m_trunk->state().haveImu && m_base.omega.norm() > kTrunkTurningRate;
  }

  const Vec15& headingSymmetryAtState() { return headingSymmetryAt(m_x.template head<kBase>()); }

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

  // Rows the consistency watch reads: the gyroscopes, which every model predicts exactly, and
  // the accelerometers only where the model includes body acceleration (Method A); Methods B
  // and C leave it out on purpose, so their accelerometer innovations are large in any motion.
  bool watched(int block) const {
    if (block == kUaGyr || block == kFaGyr) return true;
    return (block == kUaAcc || block == kFaAcc) && m_p.model == MeasurementModel::AccelGyro;
  }

  EstimatorParams m_p;
  MeasurementModel m_model;  // the model asked for; m_p.model may differ during start-up
  Eigen::Vector3d m_up;      // unit up vector, frame 0
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
  static constexpr double kGoodFitRms = 3.0;     // whitened residual RMS of a fit worth taking
  std::deque<Vec15> m_recentStates;              // the filter's state after each of m_recent
  bool m_opticalDisagrees = false;               // an optical point was gated many frames in a row
  JointVector m_matchedQ = JointVector::Zero();  // matched joint-acceleration noise, (rad/s^2)^2
  double m_jerkSquared = 0.0;  // the joints' squared jerk, (rad/s^3)^2 (trackJerk)
  // The last accelerometer update: its time and joint accelerations (trackJerk).
  std::optional<std::pair<double, JointVector>> m_jerkFrom;
  std::deque<ArmSample> m_recent;  // fused samples of the last fitWindowSeconds
  // Frame 0 at each of m_recent while a trunk IMU moves it (empty for a still trunk): window fits
  // predict each sample from the trunk's motion and the camera as they were then.
  std::deque<WindowFrame> m_recentFrames;
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
  mutable std::optional<std::pair<JointVector, HeadingGeometry>> m_geometry;  // th, its geometry
  std::optional<ArmSample> m_pendingOptical;
  std::optional<PinholeCamera> m_camera;      // when params carry a camera and useCamera is set
  std::optional<CameraParams> m_frameCamera;  // the camera as frame 0 sees it, with a trunk IMU
  // Consecutive gated frames: wrist marker, elbow marker, wrist position, elbow position.
  std::array<int, 4> m_gatedInARow{0, 0, 0, 0};
  SampleGate m_gate;
  // Per IMU channel (the blocks kUaGyr..kFaAcc): when it was last held, its last new value and
  // the squared rate at which its new values change (trackSampleTiming).
  struct ChannelTiming {
    double heldT = -std::numeric_limits<double>::infinity();
    double lastT = -std::numeric_limits<double>::infinity();
    Eigen::Vector3d last = Eigen::Vector3d::Zero();
    double changeSquared = 0.0;  // |d value / dt|^2
  };
  std::array<ChannelTiming, 4> m_timing;
  double m_rowStep = 0.0;  // s from the previous row to the present one
  std::array<RestBias, 2> m_restBias;
  EstimatorCounters m_counters;
  // Frame 0's motion for the predicted readings: still ({0, 0, 0, gUp}) until a trunk IMU speaks.
  FrameState<double> m_base;
  std::optional<TrunkTracker> m_trunk;  // from the first trunk IMU reading or optical shoulder
  // The state's error per unit error of the trunk's pose, [e0, dh]: the trunk's rotation error
  // in frame 0 (rad) and the hip pivot's (world, m). A consider (Schmidt) sensitivity: carried
  // through F and every EKF block's gain, never fed back (addTrunkVariance reads it).
  using TrunkSensitivity = Eigen::Matrix<double, N, 6, Eigen::RowMajor>;
  TrunkSensitivity m_trunkSens = TrunkSensitivity::Zero();
  std::array<Eigen::Matrix<double, 3, 6, Eigen::RowMajor>, kNumBlocks> m_trunkRows{};
  bool m_sensInUpdate = false;  // the present EKF update carries m_trunkSens
};

}  // namespace armtrack::detail
