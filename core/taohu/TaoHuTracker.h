// The webcam + forearm-IMU arm tracker of Tao & Hu: an EKF on the wrist position driven by the
// forearm IMU's acceleration and corrected by marker pixels, refined per camera frame by a
// Levenberg-Marquardt fit that keeps the elbow on a sphere around the shoulder. See docs/tao-hu.md.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <vector>

#include "core/ArmSample.h"
#include "core/camera/PinholeCamera.h"
#include "core/io/Recording.h"
#include "core/kinematics/ArmModel.h"
#include "core/kinematics/Side.h"
#include "core/orientation/OrientationFilter.h"

namespace armtrack {

/// Tuning of TaoHuTracker. Geometry, gravity, side and camera come from the recording.
struct TaoHuParams {
  ArmGeometry geometry;                ///< segment lengths and forearm IMU mounting (m, rad)
  Eigen::Vector3d up{-1.0, 0.0, 0.0};  ///< unit vector up, in the arm's own shoulder frame
  double g = 9.81;                     ///< m/s^2
  Side side = Side::Right;             ///< a left arm is tracked as its mirrored right twin
  CameraParams camera;                 ///< webcam (shoulder frame -> camera), see docs/camera.md

  /// Pixel noise std of both markers (px). Default 2, the paper's value.
  double pixelStd = 2.0;
  /// Use the elbow marker in the EKF and the LM fit, not only at start-up. Default true; false
  /// is the paper's wrist-only measurement.
  bool useElbowPixels = true;
  /// Chi-square gate on a marker's squared Mahalanobis innovation (2 dof). Default 13.8 (99.9 %).
  double gateChi2 = 13.8;
  /// Spectral density of the white acceleration error driving the EKF (m^2/s^3). It covers
  /// accelerometer noise and, mostly, the orientation error of the rotated acceleration.
  /// Default 0.002 (the simulated sensors at Table 5 noise; see docs/tao-hu.md).
  double accelNoiseDensity = 0.002;
  /// Random-walk density of the heading offset (rad^2/s). Default (0.5 deg)^2 per s.
  double headingNoiseDensity = 7.6e-5;
  /// Std of the EKF's pseudo-measurement |elbow| = l3 (m); 0 switches it off. Default 0.01.
  double sphereStdEkf = 0.01;
  /// Std of the sphere residual in the LM fit (m): small makes it a near-hard constraint.
  /// Default 0.0005.
  double sphereStdLm = 0.0005;
  /// Write the LM solution back into the EKF state. Default false: the hard sphere then pins the
  /// EKF to one depth branch, which the measured errors show to be worse.
  bool feedbackLm = false;
  /// Time after the first IMU sample before the tracker starts (s), so the orientation filter's
  /// inclination has settled. Default 1.
  double warmupSeconds = 1.0;
  /// Consecutive camera frames without an accepted marker after which the tracker starts
  /// again from the next frame. Default 15 (0.5 s at 30 Hz).
  int maxGatedFrames = 15;
  /// A gap between IMU samples longer than this restarts the tracker (s). Default 0.5.
  double maxImuGapSeconds = 0.5;
  /// Start-up alignment: largest RMS pixel residual accepted (px). Default 8.
  double initMaxRmsPx = 8.0;
  /// Start-up: a second alignment whose cost (chi-square units) is within this of the best
  /// counts as an equally good depth branch. Default 9.
  double initBranchChi2 = 9.0;
  OrientationParams orientation;  ///< forearm orientation filter (VQF defaults)
};

/// Parameters from a recording's sidecar. Throws std::invalid_argument when it has no camera.
TaoHuParams taoHuParams(const RecordingMeta& meta);

/// Counters; everything bad is counted, never thrown.
struct TaoHuCounters {
  std::size_t samples = 0;            ///< samples offered
  std::size_t rejectedNonFinite = 0;  ///< samples with a NaN/inf value, skipped
  std::size_t rejectedTime = 0;       ///< samples going back in time, skipped
  std::size_t imuSamples = 0;         ///< forearm readings used
  std::size_t cameraFrames = 0;       ///< samples with a marker pixel
  std::size_t wristUpdates = 0;       ///< wrist pixels fused
  std::size_t elbowUpdates = 0;       ///< elbow pixels fused
  std::size_t wristGated = 0;         ///< wrist pixels rejected by the chi-square gate
  std::size_t elbowGated = 0;         ///< elbow pixels rejected by the gate
  std::size_t notVisible = 0;         ///< predicted marker behind the camera: not fused
  std::size_t initialisations = 0;    ///< start-up alignments (1 + restarts)
  std::size_t initFailures = 0;       ///< frames at which the alignment did not converge
  std::size_t ambiguousStarts = 0;    ///< alignments with two equally good depth branches
  std::size_t restarts = 0;           ///< restarts after gating streaks or IMU gaps
  std::size_t lmRuns = 0;             ///< LM refinements
  std::size_t lmFailures = 0;         ///< LM runs that ended without convergence (EKF kept)
};

/// One estimate, made at a camera frame.
struct TaoHuFrame {
  double t = 0.0;                                   ///< s
  Eigen::Vector3d wrist = Eigen::Vector3d::Zero();  ///< shoulder frame of the arm (m)
  Eigen::Vector3d elbow = Eigen::Vector3d::Zero();  ///< shoulder frame of the arm (m)
  JointVector th = JointVector::Zero();             ///< [th0 th1 th2 th4 th5] (rad)
  double heading = 0.0;                   ///< filter-world -> shoulder heading offset (rad)
  bool refined = false;                   ///< the LM ran and converged (else the EKF estimate)
  std::optional<JointVector> trueAngles;  ///< truth interpolated to t (runTaoHu only)
};

/// Everything that changes (plain data).
struct TaoHuState {
  using Vec7 = Eigen::Matrix<double, 7, 1>;
  using Mat7 = Eigen::Matrix<double, 7, 7>;
  /// EKF state: forearm IMU position (m), its velocity (m/s), heading offset psi (rad), all in
  /// the (right-arm) shoulder frame.
  Vec7 x = Vec7::Zero();
  Mat7 P = Mat7::Identity();
  bool initialised = false;
  double tEkf = 0.0;                                   ///< time of x (s)
  double tLast = 0.0;                                  ///< last accepted sample time (s)
  bool seen = false;                                   ///< some sample accepted
  double tFirstImu = 0.0;                              ///< s
  double tLastImu = 0.0;                               ///< s
  bool imuSeen = false;                                ///< some forearm reading seen
  Eigen::Vector3d accWorld = Eigen::Vector3d::Zero();  ///< last specific force, filter world
  int gatedInARow = 0;                                 ///< camera frames with nothing fused
  TaoHuCounters counters;
};

/// What update() did with a sample.
enum class TaoHuStatus {
  Rejected,  ///< bad sample, counted and skipped
  Waiting,   ///< accepted, not started yet (warm-up, no camera frame, alignment failed)
  Tracking,  ///< accepted, no camera frame in this sample
  Frame,     ///< a camera frame was processed: frame() holds a new estimate
};

/// The tracker, one sample at a time. update() allocates only inside the LM (per camera frame).
class TaoHuTracker {
 public:
  /// Throws std::invalid_argument for a bad camera or non-positive noise parameters.
  explicit TaoHuTracker(const TaoHuParams& params);

  TaoHuStatus update(const ArmSample& sample);

  const TaoHuFrame& frame() const { return m_frame; }  ///< the latest estimate
  const TaoHuState& state() const { return m_s; }
  void setState(const TaoHuState& s) { m_s = s; }
  const TaoHuCounters& counters() const { return m_s.counters; }
  const TaoHuParams& params() const { return m_p; }
  /// Forearm sensor -> shoulder frame (right-arm twin for a left arm) at the current state.
  Eigen::Matrix3d forearmRotation() const;
  void reset();

  /// The joint angles implied by elbow and wrist positions and the forearm IMU's rotation,
  /// all in a right arm's shoulder frame: th0, th1 from the elbow direction, th2, th4 from the
  /// forearm direction (branch th4 <= 0), th5 from the IMU rotation about the forearm.
  static JointVector anglesFromPoints(const ArmGeometry& geo, const Eigen::Vector3d& elbow,
                                      const Eigen::Vector3d& wrist,
                                      const Eigen::Matrix3d& forearmImuRotation);

 private:
  Eigen::Matrix3d headingRotation(double psi) const;
  enum class Fuse { Fused, Gated, NotVisible };
  void predictTo(double t);
  void predict(TaoHuState::Vec7& x, TaoHuState::Mat7& P, double dt) const;
  bool initialise(const ArmSample& s);
  void cameraUpdate(const ArmSample& s);
  Fuse fuseMarker(TaoHuState::Vec7& x, TaoHuState::Mat7& P, const Eigen::Vector2d& z,
                  const Eigen::Vector3d& offset) const;
  void fuseSphere(TaoHuState::Vec7& x, TaoHuState::Mat7& P) const;
  void makeFrame(double t, bool refined);
  void restart();

  TaoHuParams m_p;
  PinholeCamera m_camera;
  Eigen::Vector3d m_up;        ///< up in the right-arm frame (unit)
  Eigen::Matrix3d m_align;     ///< filter world -> shoulder frame at psi = 0 (z -> up)
  Eigen::Vector3d m_offWrist;  ///< wrist in the forearm IMU frame (m)
  Eigen::Vector3d m_offElbow;  ///< elbow in the forearm IMU frame (m)
  OrientationFilter m_orient;
  Eigen::Matrix3d m_Rfw = Eigen::Matrix3d::Identity();  ///< sensor -> filter world
  TaoHuState m_s;
  TaoHuFrame m_frame;
};

/// Batch result of runTaoHu.
struct TaoHuResult {
  std::vector<TaoHuFrame> frames;  ///< one per processed camera frame, in time order
  TaoHuCounters counters;
};

/// Runs the tracker over a whole recording. Frames carry the true angles (interpolated between
/// the neighbouring rows) when the recording has them. Throws std::invalid_argument when the
/// recording has no camera block or no forearm IMU reading.
TaoHuResult runTaoHu(const Recording& recording, const TaoHuParams& params);

/// Errors of a run against its truth.
struct TaoHuErrors {
  std::size_t count = 0;                        ///< frames compared
  JointVector rmseDeg = JointVector::Zero();    ///< per joint (deg)
  JointVector peakDeg = JointVector::Zero();    ///< per joint (deg)
  double wristRmseCm = 0.0, wristPeakCm = 0.0;  ///< 3D distance (cm)
  double elbowRmseCm = 0.0, elbowPeakCm = 0.0;  ///< 3D distance (cm)
  double wristAxisPeakCm = 0.0;  ///< largest error of a single coordinate (cm), the paper's +/-5
};

/// Compares frames that carry true angles and lie at least skipSeconds after the first frame
/// with the forward kinematics of the truth (geometry and side of the recording).
TaoHuErrors taoHuErrors(const TaoHuResult& result, const ArmGeometry& geometry, Side side,
                        double skipSeconds = 1.0);

}  // namespace armtrack
