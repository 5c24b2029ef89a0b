// Joint-angle estimators of Alizadegan & Behzadipour (2016): an EKF and a UKF over the state
// [th'' th' th] (eq. 1) with the GM-1 joint-acceleration process model (eqs. 3-4) and a choice of
// IMU measurement models (Methods A, B, C and the inclinometer-only model), optionally fused with
// optical elbow and wrist positions (eq. 16). See docs/estimator.md.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/ArmSample.h"
#include "core/estimation/Heading.h"
#include "core/estimation/RestBias.h"
#include "core/estimation/SampleGate.h"
#include "core/io/Recording.h"
#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"

namespace armtrack {

inline constexpr double kDeg = std::numbers::pi / 180.0;  ///< one degree in rad
inline constexpr double kInf = std::numeric_limits<double>::infinity();

enum class FilterKind { Ekf, Ukf };

/// What the accelerometers are assumed to measure (the gyroscope is used except where noted).
enum class MeasurementModel {
  Inclinometer,        ///< accelerometer = gravity only; no gyroscope (zero-order, Fig. 5)
  InclinometerGyro,    ///< accelerometer = gravity only, plus gyroscope (Method C)
  AccelGyro,           ///< accelerometer = gravity + body acceleration (eq. 17-18), gyro (Method A)
  AugmentedBodyAccel,  ///< gravity + body acceleration as GM-1 states, plus gyro (Method B)
};

/// Parses "A", "B", "C", "inclinometer" (case-insensitive); throws std::invalid_argument.
MeasurementModel parseMethod(const std::string& name);
std::string methodName(MeasurementModel m);

/// Filter parameters. Defaults are the paper's Table 5 and Table 7 in SI units.
struct EstimatorParams {
  FilterKind filter = FilterKind::Ekf;
  MeasurementModel model = MeasurementModel::AccelGyro;
  ArmGeometry geometry;                  ///< the arm and IMU mounting the filter assumes
  Eigen::Vector3d gUp{-9.81, 0.0, 0.0};  ///< g * up in the shoulder frame (m/s^2)
  /// Which arm. Samples and gUp are in that arm's shoulder frame; a left arm is estimated as the
  /// mirror image of a right arm (core/kinematics/Side.h), with the same joint angles.
  Side side = Side::Right;

  /// Joint-acceleration process noise variance per reference step, (rad/s^2)^2. Table 5:
  /// 1 (deg/s^2)^2 at the paper's 1 ms step. For another dt the variance scales with dt / 1 ms.
  double jointAccelVariance = 1.0 * kDeg * kDeg;
  double referenceStep = 1e-3;  ///< s, the step jointAccelVariance refers to
  /// Adaptive joint-acceleration noise (covariance matching, Mohamed & Schwarz 1999): the
  /// corrections the updates make to the joint accelerations, averaged over adaptationTime,
  /// raise the process noise above jointAccelVariance while the arm moves fast, so fast human
  /// movement (600 deg/s, 6,000 deg/s^2) is tracked without tuning, and it falls back to
  /// jointAccelVariance when the arm slows down. Off reproduces the paper's fixed noise.
  /// Method A only: matching assumes the measurement model explains the readings, and the
  /// inclinometer models (B, C) leave body acceleration out of it on purpose, so their large
  /// accelerometer innovations would be taken for process noise and make the state chase them.
  bool adaptiveProcessNoise = true;
  double adaptationTime = 0.05;  ///< s, averaging time of the matched noise
  /// Ceiling of the matched noise, (rad/s^2)^2 per reference step: (1000 deg/s^2)^2, several
  /// times what the fastest minimum-jerk reach of a human arm needs, so readings no arm can
  /// produce cannot blow the covariance up.
  double maxJointAccelVariance = (1000.0 * kDeg) * (1000.0 * kDeg);
  /// GM-1 correlation time of the joint accelerations (s). Infinity gives eq. 3's identity block.
  double jointAccelCorrelationTime = std::numeric_limits<double>::infinity();
  /// Random walk of the arm's heading, as a turn of the whole arm about the vertical (rad^2/s of
  /// turn; in joint space it grows near the shoulder's gimbal lock, where a small turn moves
  /// flexion and rotation far), so the filter stays willing to accept optical heading
  /// corrections (docs/estimator.md, "Heading"). With heading-blind IMU updates (Method A) the
  /// heading only drifts as the gyroscopes' white noise integrates: Table 5's 0.1 (deg/s)^2 at
  /// 1 kHz gives 1e-4 (deg)^2/s. A real sensor's bias and misalignment turn it faster; heading
  /// matching opens the heading up when the optics see that.
  double headingVarianceRate = 1e-4 * kDeg * kDeg;
  /// Method A: the heading's random walk that grows with the motion, per radian the shoulder
  /// joints travel (rad^2 of turn per rad, i.e. rad^2/s per rad/s of the shoulder joints'
  /// speed). The estimate lags smooth motion a little and, as the turn a change of the angles
  /// makes depends on the path, the lagging path turns the arm about the vertical where no IMU
  /// can see it. Measured without optics after a Kinect fix on 24 five-joint runs (seeds 31-38,
  /// 51-58, 71-78; Table 5 noise): 0.6-1.3e-7 beyond the gyroscopes' walk (docs/estimator.md,
  /// "Uncertainty").
  double headingPathVarianceRate = 1e-7;
  /// Method A, after start-up: the same lag turns the upper arm about the horizontal axes too,
  /// where the accelerometers see it, but on fast movement (their variance widened with the jerk,
  /// accelJerkVariance) only slowly: each shoulder joint's variance grows by this, per radian the
  /// shoulder joints travel (rad^2 per rad). The heading's measured rate, applied per joint; it
  /// took the shoulder at 600 deg/s from 71-78 % to 88-96 % inside 2 sd with the heading's share
  /// left out, and changes the five-joint movements' coverage by 1-2 points (docs/estimator.md,
  /// "Uncertainty"). 0 turns it off.
  double shoulderPathVarianceRate = 1e-7;
  /// The same for Methods B and C, whose accelerometer model leaves body acceleration out: the
  /// tilt errors that leaves turn into heading errors as the arm rotates. 1 (deg)^2/s.
  double inclinometerHeadingVarianceRate = 1.0 * kDeg * kDeg;
  /// Heading-blind IMU updates (Method A, all three shoulder joints active, after start-up): the
  /// gyroscopes and accelerometers say nothing about the arm's turn about the vertical, so their
  /// updates leave the state's heading where it is (a Schmidt update along that one direction)
  /// instead of moving it through the covariance's correlations, which at the start and end of
  /// a fast reach turned the arm by several degrees that only optics could take back
  /// (docs/estimator.md, "Heading"). Off reproduces the plain EKF and UKF.
  bool headingBlindImuUpdates = true;
  /// Heading matching (s): the turn about the vertical that the optical data ask for, averaged
  /// over this time, sets the least heading variance before each optical update, so a heading
  /// error left by a fast movement is corrected in a few frames and shows in the standard
  /// deviation (docs/estimator.md, "Heading"). Six Kinect frames at 30 Hz: one noisy frame alone
  /// does not open the heading up. 0 turns it off.
  double headingMatchTime = 0.2;

  double gyroVariance = 0.1 * kDeg * kDeg;  ///< (rad/s)^2, Table 5: 0.1 (deg/s)^2
  double accelVariance = 1e-2;              ///< (m/s^2)^2, Table 5
  double positionVariance = 1e-4;           ///< m^2, Table 5 (Kinect)
  /// Method A, after start-up: the accelerometers' variance grows by this times the squared jerk
  /// of the joints ((rad/s^3)^2, summed over the joints), (m/s^2)^2 per (rad/s^3)^2. The process
  /// model takes the joint accelerations for a random walk, so on smooth fast movement their
  /// estimate lags the true ones by about the jerk times the filter's response time, and the
  /// body acceleration predicted from them misses the readings by that lag times the lever arm:
  /// model error that the filter would otherwise take for information about the angles and
  /// report too small a standard deviation. The jerk is the estimate's own: the change of its
  /// joint accelerations between accelerometer updates (noise-driven corrections included),
  /// squared and averaged over adaptationTime. Measured against simulated truth on fast reaching:
  /// 4-6e-8 per axis (a 0.3 m lever and a lag of about 0.7 ms; docs/estimator.md, "Uncertainty").
  /// 0 turns it off. Methods B and C model body acceleration otherwise (B as states, C not at
  /// all), so it does not apply to them.
  double accelJerkVariance = 4e-8;

  /// Method B: stationary variance (m/s^2)^2 and correlation time (s) of the body-acceleration
  /// GM-1 states (Sabatini 2006). (10 m/s^2)^2: a forearm swung at 1 Hz through 90 deg sees
  /// about 50 m/s^2, a fast reach 30; at 1 (m/s^2)^2 the states cannot follow and a two-IMU arm
  /// lands 15 deg off at the elbow. The one-segment study of the paper's Table 6 uses 1.
  double bodyAccelVariance = 100.0;
  double bodyAccelCorrelationTime = 0.1;

  bool useOptical = true;  ///< fuse Kinect elbow/wrist positions when a sample carries them

  /// The sternum IMU's mounting (the sidecar's trunk block). Samples with a trunk IMU move frame
  /// 0 with the thorax (docs/estimator.md, "Trunk"); without a mounting, trunk IMU readings are
  /// refused and counted (EstimatorCounters::rejectedTrunk).
  std::optional<TrunkMount> trunk;
  /// Where the trunk turns (the hip pivot), in frame 0 at the start for a right arm (m): a
  /// typical place 0.45 m below and 0.15 m medial to the shoulder centre. Refined from an optical
  /// shoulder when one is seen.
  Eigen::Vector3d hipPivot{0.45, 0.0, -0.15};

  /// What the sensors and an arm can produce; implausible blocks are refused before the filter
  /// sees them (core/estimation/SampleGate.h). maxReach is capped at 1.5 x (l3 + l6) + 0.2 m.
  PlausibilityLimits plausibility;

  /// Each arm IMU's gyroscope bias is taken from the moments it is still (RestBias: the mean
  /// rate over a still second, refined at each later rest) and subtracted from its readings.
  /// Off: the readings as given (a calibration file's biases still apply before the filter).
  bool gyroBiasAtRest = true;
  RestBiasParams restBias;

  /// Webcam: the camera that sees the wrist and elbow markers (the recording's `camera` block).
  /// Without it, marker pixels are ignored.
  std::optional<CameraParams> camera;
  bool useCamera = true;       ///< fuse marker pixels when a sample carries them
  double pixelVariance = 1.0;  ///< px^2 per image axis (1 px noise)
  /// Innovation gate for marker pixels: a pixel whose squared Mahalanobis distance exceeds this
  /// (chi-square, 2 degrees of freedom; 13.8 leaves out 0.1 % of good detections) is taken for a
  /// mis-detected marker, dropped and counted. Not applied during start-up.
  double pixelGate = 13.8;
  /// After this many gated frames in a row for one marker the next one is fused ungated: the
  /// filter, not the detector, is then the likelier one to be lost.
  int pixelGateResetFrames = 15;
  /// A gate for Kinect positions, per point (squared Mahalanobis distance, 3 degrees of
  /// freedom): the Kinect plugin finds the markers in the colour image, so a mis-detection gives
  /// a 3D outlier. Wide on purpose (20 standard deviations; the 99.9 % level would be 16.3): a
  /// model error (mounting, start heading) gives systematic innovations the optics must still
  /// correct (docs/estimator.md). 0 turns it off. Not applied during start-up; after
  /// positionGateResetFrames gated samples in a row for one point the next is fused ungated.
  double positionGate = 400.0;
  /// ... and only when the position is also this far (m) from the predicted one.
  double positionGateMinDistance = 0.15;
  int positionGateResetFrames = 15;
  /// Joints the filter estimates; inactive joints stay at fixedAngles (the paper's one-segment
  /// studies estimate th0 only).
  std::array<bool, kNumJoints> activeJoints{true, true, true, true, true};
  JointVector fixedAngles = JointVector::Zero();  ///< rad
  /// Anatomical limits (rad, joint angles th0..th4): beyond what any arm can reach, wider than
  /// the normal ranges of motion (ClinicalAngles) so they never touch a real movement. An estimate
  /// outside is projected back onto the nearest limit with the covariance's correlations (the
  /// joints it is coupled to move with it; the covariance is kept). This rules out the mirrored
  /// Euler branch of the shoulder and an elbow bent backwards, where an inclinometer model under
  /// body acceleration would otherwise settle. Infinite bounds leave a joint free. Defaults, in
  /// clinical terms: abduction from -100 deg (the arm swung across the body), internal rotation
  /// -120 to 110 deg, elbow flexion -20 to 170 deg, pronation -130 to 130 deg; flexion free.
  /// The other Euler branch of a shoulder pose, (th0 + 180, 180 - th1, th2 + 180) deg, then lies
  /// outside unless the internal rotation is beyond about +-60 deg.
  JointVector jointLower = defaultJointLower();
  JointVector jointUpper = defaultJointUpper();
  static JointVector defaultJointLower() {
    JointVector v;
    v << -kInf, -100.0 * kDeg, -110.0 * kDeg, -170.0 * kDeg, -130.0 * kDeg;
    return v;
  }
  static JointVector defaultJointUpper() {
    JointVector v;
    v << kInf, kInf, 120.0 * kDeg, 20.0 * kDeg, 130.0 * kDeg;
    return v;
  }

  /// Start-up: initial standard deviations after the gravity/optical initialisation.
  double initialAngleStd = 45.0 * kDeg;        ///< rad, start pose from gravity alone
  double initialAngleStdOptical = 5.0 * kDeg;  ///< rad, start pose fixed by optical positions
  double initialRateStd = 0.5;                 ///< rad/s
  double initialAccelStd = 10.0;               ///< rad/s^2
  double initialHeadingStd = 30.0 * kDeg;      ///< rad, extra along the heading direction
  /// Methods B and C start on the body-acceleration model: through the start-up second (and after
  /// each restart) their filter reads the accelerometers as Method A does, then hands its state
  /// and covariance over to their own model (Method B's body-acceleration states start from what
  /// the kinematics predict). Their models read the centripetal acceleration of a fast swing (4 g
  /// at a forearm strap swung at 1 Hz through 90 deg) as gravity along the arm, and with the
  /// start-up's wide covariance that threw the start pose tens of degrees off, the elbow onto its
  /// limits, for 2-3 s or for good (docs/estimator.md, "Methods B and C"). Off reproduces the
  /// paper's filters from their first sample.
  bool kinematicStartup = true;
  /// During the first startupSeconds the EKF iterates its update (Gauss-Newton) up to this many
  /// times, so a start while the arm moves fast cannot throw it off.
  int startupIterations = 4;
  double startupSeconds = 1.0;
  /// During start-up the joint-acceleration process noise is at least this, (rad/s^2)^2 per
  /// reference step, so the filter forgets a poor first guess (taken while the arm moved) within
  /// the start-up second. Default (100 deg/s^2)^2.
  double startupJointAccelVariance = (30.0 * kDeg) * (30.0 * kDeg);
  /// Gyroscope first: for the first gyroFirstSeconds the accelerometer variance is this many
  /// times larger, so the gyroscopes settle the rates before gravity and body acceleration are
  /// split (a first guess taken while the arm moved is otherwise locked in).
  double gyroFirstSeconds = 0.25;
  double gyroFirstAccelGain = 1e4;
  /// Start-up in mid-motion: this long (s) after each (re)start, a batch fit of one smooth motion
  /// to the window's readings (core/estimation/WindowFit.h) replaces the state when it explains
  /// them clearly better. The same window serves recovery. 0 turns both off.
  double fitWindowSeconds = 0.25;
  /// The arm is taken as lost when the IMU rows' normalised innovation squared per row stays
  /// above lostNis for lostAfterSeconds (after start-up), or a joint rate exceeds the gyroscope
  /// range; the filter then re-initialises from the recent window (counters().recoveries).
  double lostNis = 400.0;
  double lostAfterSeconds = 0.15;
  /// A stretch longer than this (s) without usable data (a gap in time, or rows whose every
  /// reading was refused at the door) restarts the filter from the next usable sample.
  double maxGap = 0.1;
  /// Rows whose every reading was refused at the door still get an estimate for this long (s)
  /// after the last usable data: the filter predicts to each row's time (UpdateResult::Predicted),
  /// its standard deviations growing with the prediction.
  double maxCoastSeconds = 1.0;
};

/// The measurement model a filter with these parameters uses during its start-up second: Method
/// A's for Methods B and C with kinematicStartup, params.model otherwise.
MeasurementModel startupModel(const EstimatorParams& params);

/// The trunk as the filter sees it (with a trunk IMU or an optical shoulder).
struct TrunkEstimate {
  bool measured = false;  ///< a trunk IMU gives the angles; false: an optical shoulder alone
  /// Flexion, lateral bending, axial rotation (rad, patient terms, core/kinematics/Trunk.h),
  /// relative to the start pose; zero without a trunk IMU.
  Eigen::Vector3d angles = Eigen::Vector3d::Zero();
  Eigen::Vector3d angleStd = Eigen::Vector3d::Zero();  ///< rad
  Eigen::Vector3d shoulder = Eigen::Vector3d::Zero();  ///< shoulder centre, world frame (m)
};

/// Output of the filter at one instant.
struct JointEstimate {
  double t = 0.0;                           ///< s
  JointVector th = JointVector::Zero();     ///< rad, wrapped to (-pi, pi]
  JointVector thd = JointVector::Zero();    ///< rad/s
  JointVector thdd = JointVector::Zero();   ///< rad/s^2
  JointVector thStd = JointVector::Zero();  ///< 1-sigma of th (rad)
};

/// Counters of everything the filter refused or repaired; never reset except by reset().
struct EstimatorCounters {
  std::uint64_t samples = 0;            ///< samples offered
  std::uint64_t rejectedNonFinite = 0;  ///< sensor blocks dropped for NaN/inf
  /// Every sensor block refused at the door (NaN/inf included), by block, reason and time.
  GateCounters implausible;
  std::uint64_t rejectedTime = 0;       ///< samples dropped: time not finite or going backwards
  std::uint64_t skippedUpdates = 0;     ///< updates skipped: innovation covariance not invertible
  std::uint64_t covarianceRepairs = 0;  ///< covariance re-symmetrised / jittered to stay PD
  std::uint64_t restarts = 0;           ///< restarts after a gap longer than maxGap
  std::uint64_t coasted = 0;            ///< rows whose readings were all refused, predicted through
  std::uint64_t recoveries = 0;         ///< re-initialisations after the arm was lost
  std::uint64_t startupRefits = 0;      ///< start-up states replaced by the window fit
  std::uint64_t limitedStates = 0;      ///< estimates projected back into the anatomical range
  std::uint64_t opticalUpdates = 0;     ///< optical position blocks fused (Kinect)
  std::uint64_t cameraUpdates = 0;      ///< marker pixels fused (webcam)
  std::uint64_t rejectedOutliers = 0;   ///< pixels and positions dropped by the innovation gate
  std::uint64_t gatedPositions = 0;     ///< of which Kinect positions
  std::uint64_t cameraNotVisible = 0;   ///< marker pixels dropped: predicted point not in view
  /// Trunk IMU readings refused: non-finite, beyond a sensor's range, or no mounting known.
  std::uint64_t rejectedTrunk = 0;
  /// Gyroscope bias found at rest (rad/s, the sensor's axes; a left arm's mirrored) and the
  /// still windows it rests on: upper arm, forearm (EstimatorParams::gyroBiasAtRest).
  std::array<Eigen::Vector3d, 2> restBias{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  std::array<std::uint64_t, 2> restWindows{0, 0};
};

enum class UpdateResult {
  Accepted,     ///< the sample was fused
  Initialised,  ///< the filter (re)started from this sample
  Waiting,      ///< not yet initialised (no IMU sample seen)
  Rejected,     ///< nothing usable in the sample (see counters)
  /// Every reading of the sample was refused at the door (counters().implausible); the filter
  /// predicted to the sample's time, so estimate() is current but rests on no measurement.
  Predicted,
  /// The filter had lost the arm (or its start-up guess was poor) and re-initialised from a fit
  /// to the recent window: the estimate may jump here without the arm having moved.
  Recovered,
};

/// Whether an update gave an estimate for the sample's time.
inline bool hasEstimate(UpdateResult r) {
  return r == UpdateResult::Accepted || r == UpdateResult::Initialised ||
         r == UpdateResult::Predicted || r == UpdateResult::Recovered;
}

/// The estimator. Not thread-safe: one thread feeds it.
class JointEstimator {
 public:
  virtual ~JointEstimator() = default;
  /// Feeds one sample (timestamps non-decreasing). Blocks with NaN/inf are dropped and counted.
  virtual UpdateResult update(const ArmSample& sample) = 0;
  virtual bool initialised() const = 0;
  virtual JointEstimate estimate() const = 0;
  virtual const EstimatorCounters& counters() const = 0;
  /// True while no optical measurement (Kinect position or marker pixel) has been fused for
  /// 5 s (a fixed span, not a setting): the arm's heading about the vertical then rests on the
  /// start-pose assumption alone.
  virtual bool headingFromStartPoseOnly() const = 0;
  virtual void reset() = 0;
  /// The trunk, once a sample brought a trunk IMU reading or an optical shoulder.
  virtual std::optional<TrunkEstimate> trunk() const { return std::nullopt; }
  /// Full state covariance (for tests and diagnostics).
  virtual Eigen::MatrixXd covariance() const = 0;
};

std::unique_ptr<JointEstimator> makeEstimator(const EstimatorParams& params);

/// Parameters for a recording: the geometry, gravity, side and camera of its sidecar; everything
/// else at the defaults.
EstimatorParams recordingParams(const RecordingMeta& meta);

/// Runs a whole recording offline; one estimate per sample that carries IMU data (after
/// initialisation). The batch entry point the CLI and the tests use.
struct BatchResult {
  std::vector<JointEstimate> estimates;
  EstimatorCounters counters;
};
BatchResult estimateSamples(const std::vector<ArmSample>& samples, const EstimatorParams& params);

/// Measurement function and its Jacobian, exposed for the tests: the stacked predicted readings
/// [ua gyro, ua acc, fa gyro, fa acc, elbow, wrist] (18) for a 15-state x = [thdd thd th] under
/// `model`, and d(prediction)/dx by automatic differentiation.
Eigen::Matrix<double, 18, 1> predictAll(const EstimatorParams& params,
                                        const Eigen::Matrix<double, 15, 1>& x);
Eigen::Matrix<double, 18, 15> predictAllJacobian(const EstimatorParams& params,
                                                 const Eigen::Matrix<double, 15, 1>& x);

/// The predicted pixel of the wrist (or elbow) marker for a 15-state x through params.camera,
/// with d(pixel)/dx when jac is given. x is the state of the (virtual right) arm the filter works
/// on; for a left arm the camera sees the mirror image of its points. Returns false when there is
/// no camera or the point is not in view.
bool predictMarkerPixel(const EstimatorParams& params, const Eigen::Matrix<double, 15, 1>& x,
                        bool wrist, Eigen::Vector2d& pixel,
                        Eigen::Matrix<double, 2, 15>* jac = nullptr);

}  // namespace armtrack
