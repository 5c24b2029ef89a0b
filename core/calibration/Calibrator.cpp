// Batch calibration by Ceres. Layout of the problem (docs/calibration.md, "Formulation"):
//   - joint trajectory: uniform cubic B-spline, one 5-vector control point per knot;
//   - per IMU a mounting block [l_axial, l_radial, strap angle, tilt_x, tilt_z] and a gyro bias;
//   - segment lengths [l3, l6], estimated only with optical positions;
//   - residuals: binned gyro/accelerometer readings of both IMUs, optical elbow/wrist positions,
//     the start-pose prior along the gauge directions, weak priors on the calibration blocks.
#include "core/calibration/Calibrator.h"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "core/calibration/CalibrationCosts.h"
#include "core/calibration/CalibrationStart.h"
#include "core/calibration/TrajectoryMoves.h"
#include "core/calibration/TrunkMounting.h"
#include "core/estimation/ArmFilter.h"
#include "core/estimation/Heading.h"
#include "core/estimation/SampleGate.h"
#include "core/kinematics/Side.h"

namespace armtrack {
namespace {

// The start-pose prior only fixes gauges (directions the data cannot see), so it can be stiff;
// a stiff one keeps the solver's damped steps from drifting along them (rad).
constexpr double kGaugeStd = 0.01 * std::numbers::pi / 180.0;

using calib::binImu;
using calib::DeadReckoning;
using calib::evalSpline;
using calib::firstTrajectory;
using calib::fitSpline;
using calib::guessGyroBias;
using calib::ImuBin;
using calib::ImuCost;
using calib::normalPrior;
using calib::PositionCost;
using calib::prepare;
using calib::Prepared;
using calib::SplineGrid;
using calib::splineWeights;
using calib::SplineWeights;
using calib::StartPoseCost;
using calib::StillStats;
using calib::stillStats;
using calib::turnKnots;
using calib::unwrappedNear;
using calib::Vec3;
using calib::Vec5T;

class ProgressCallback final : public ceres::IterationCallback {
 public:
  explicit ProgressCallback(const CalibrationProgress& progress) : m_progress(progress) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    if (m_progress) {
      char line[160];
      std::snprintf(line, sizeof line, "calibrate: iteration %d, cost %.6g, step %s, %.1f s",
                    s.iteration, s.cost, s.step_is_successful ? "taken" : "rejected",
                    s.cumulative_time_in_seconds);
      m_progress(line);
    }
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const CalibrationProgress& m_progress;
};

double rmsOf(ceres::Problem& problem, const std::vector<ceres::ResidualBlockId>& blocks, int offset,
             int stride, int count) {
  if (blocks.empty()) return 0.0;
  ceres::Problem::EvaluateOptions opt;
  opt.residual_blocks = blocks;
  opt.apply_loss_function = false;
  std::vector<double> r;
  problem.Evaluate(opt, nullptr, &r, nullptr, nullptr);
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i + stride <= r.size(); i += stride) {
    for (int k = 0; k < count; ++k) sum += r[i + offset + k] * r[i + offset + k];
    n += count;
  }
  return n ? std::sqrt(sum / n) : 0.0;
}

}  // namespace

Eigen::Matrix3d mountingRotation(double strapAngle, double referenceStrapAngle,
                                 const Eigen::Matrix3d& residual) {
  return Eigen::AngleAxisd(strapAngle - referenceStrapAngle, Vec3::UnitY()).toRotationMatrix() *
         residual;
}

namespace {

/// Ceres reports a failed evaluation through glog, LOG(WARNING) with every parameter value (about
/// 60 lines), whatever Solver::Options::logging_type says; glog writes that to the process's
/// stderr even before InitGoogleLogging. A library has no business writing there, so glog's
/// threshold is raised to FATAL while a calibration runs and put back when the last one ends.
/// FLAGS_minloglevel is process-wide: other glog users are quiet for that time too.
class QuietGlog {
 public:
  QuietGlog() {
    const std::lock_guard lock(mutex());
    if (depth()++ == 0) {
      saved() = FLAGS_minloglevel;
      FLAGS_minloglevel = google::GLOG_FATAL;
    }
  }
  ~QuietGlog() {
    const std::lock_guard lock(mutex());
    if (--depth() == 0) FLAGS_minloglevel = saved();
  }
  QuietGlog(const QuietGlog&) = delete;
  QuietGlog& operator=(const QuietGlog&) = delete;

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static int& depth() {
    static int d = 0;
    return d;
  }
  static int& saved() {
    static int s = 0;
    return s;
  }
};

/// Steps 3 to 5: the Ceres problem (parameter blocks, priors, data), its solution and the
/// calibration it gives. The parameter blocks are members, so their addresses stay fixed.
class CalibrationFit {
 public:
  CalibrationFit(const Prepared& in, const std::array<Vec3, 2>& biasGuess,
                 const CalibrationOptions& options, const CalibrationProgress& say)
      : m_in(in), m_options(options), m_say(say), m_problem(problemOptions()) {
    const ArmGeometry& nominal = in.nominal;
    m_grid.t0 = in.tFirst;
    m_grid.dt = options.knotSpacing;
    m_grid.segments = std::max(1, static_cast<int>(std::ceil((in.tLast - in.tFirst) / m_grid.dt)));
    m_priorWeights = splineWeights(m_grid, in.tFirst + 0.5 * options.startStillSeconds);
    // 3. Parameter blocks.
    m_mountUa = {nominal.lu3, nominal.lu5, nominal.thu4, 0.0, 0.0};
    m_mountFa = {nominal.lf6, nominal.lf8, nominal.thf7, 0.0, 0.0};
    m_biasUa = {biasGuess[0].x(), biasGuess[0].y(), biasGuess[0].z()};
    m_biasFa = {biasGuess[1].x(), biasGuess[1].y(), biasGuess[1].z()};
    m_seg = {nominal.l3, nominal.l6};
    const double binSeconds = 1.0 / options.residualRateHz;
    m_bins[0] = binImu(in.samples, false, in.tFirst, binSeconds, biasGuess[0]);
    m_bins[1] = binImu(in.samples, true, in.tFirst, binSeconds, biasGuess[1]);
    if (in.optical) {
      for (const ArmSample& s : in.samples) {
        if (s.t < in.tFirst || s.t > in.tLast) continue;
        if (s.elbow && s.elbow->allFinite()) m_points.push_back({s.t, *s.elbow, false});
        if (s.wrist && s.wrist->allFinite()) m_points.push_back({s.t, *s.wrist, true});
      }
    }
  }

  std::size_t imuBins() const { return m_bins[0].size() + m_bins[1].size(); }
  std::size_t opticalPoints() const { return m_points.size(); }

  /// The spline fitted to the filter's trajectory, then put on the start pose.
  void start(const std::vector<JointEstimate>& first) {
    m_ctrl = fitSpline(m_grid, first, m_options.startPose);
    const JointVector th = thAt(m_priorWeights);
    char line[200];
    std::snprintf(line, sizeof line,
                  "calibrate: the filter's start pose [%.1f %.1f %.1f %.1f %.1f] deg", th(0) / kDeg,
                  th(1) / kDeg, th(2) / kDeg, th(3) / kDeg, th(4) / kDeg);
    m_say(line);
    alignGauges();
  }

  /// Priors first (they bring in the calibration blocks): the start pose at the middle of the
  /// still start, along pronation (th5 + thf7 is a gauge) and, without optical data, along the
  /// heading about the vertical; weak priors on the calibration; the bounds.
  void addPriors() {
    const ArmGeometry& nominal = m_in.nominal;
    std::vector<JointVector> directions;
    directions.push_back(JointVector::Unit(4));
    if (!m_in.optical) directions.push_back(headingDirection(m_options.startPose, m_in.up));
    for (const JointVector& d : directions) {
      auto* cost = new ceres::AutoDiffCostFunction<StartPoseCost, 1, 5, 5, 5, 5>(
          new StartPoseCost(m_priorWeights, d, m_options.startPose, kGaugeStd));
      m_problem.AddResidualBlock(cost, nullptr, ctrlBlocks(m_priorWeights));
    }
    Eigen::VectorXd mean(5), std(5);
    const double L = m_options.lengthPriorStd, A = m_options.strapAnglePriorStd,
                 R = m_options.tiltPriorStd;
    mean << nominal.lu3, nominal.lu5, nominal.thu4, 0.0, 0.0;
    std << L, L, A, R, R;
    m_problem.AddResidualBlock(normalPrior(mean, std), nullptr, m_mountUa.data());
    // thf7: no real prior, the start pose fixes it (1e3 rad is only numerical safety).
    mean << nominal.lf6, nominal.lf8, nominal.thf7, 0.0, 0.0;
    std << L, L, 1e3, R, R;
    m_problem.AddResidualBlock(normalPrior(mean, std), nullptr, m_mountFa.data());
    const Eigen::VectorXd b0 = Eigen::VectorXd::Zero(3);
    const Eigen::VectorXd bs = Eigen::VectorXd::Constant(3, m_options.biasPriorStd);
    m_problem.AddResidualBlock(normalPrior(b0, bs), nullptr, m_biasUa.data());
    m_problem.AddResidualBlock(normalPrior(b0, bs), nullptr, m_biasFa.data());
    Eigen::VectorXd sm(2), ss(2);
    sm << nominal.l3, nominal.l6;
    ss << L, L;
    m_problem.AddResidualBlock(normalPrior(sm, ss), nullptr, m_seg.data());

    for (double* m : {m_mountUa.data(), m_mountFa.data()}) {
      m_problem.SetParameterLowerBound(m, 0, 0.0);
      m_problem.SetParameterLowerBound(m, 1, 0.0);
    }
    if (fitSegments()) {
      m_problem.SetParameterLowerBound(m_seg.data(), 0, 0.05);
      m_problem.SetParameterLowerBound(m_seg.data(), 1, 0.05);
    } else {
      m_problem.SetParameterBlockConstant(m_seg.data());
    }
  }

  // 4. Solve: in stages without optical data, then over everything, then the polish after the
  // gauges are put back on the start pose.
  void solve(CalibrationResult& result) {
    ProgressCallback callback(m_say);
    m_solverOptions.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    m_solverOptions.num_threads = std::max(1, m_options.threads);
    m_solverOptions.function_tolerance = 1e-6;
    m_solverOptions.parameter_tolerance = 1e-9;
    m_solverOptions.logging_type = ceres::SILENT;
    m_solverOptions.minimizer_progress_to_stdout = false;
    m_solverOptions.callbacks.push_back(&callback);
    if (!m_in.optical && m_options.stageSeconds > 0.0) solveInStages();
    addDataUpTo(std::numeric_limits<double>::infinity());
    m_say("calibrate: solving, " + std::to_string(m_grid.controlPoints()) + " knots, " +
          std::to_string(imuBins()) + " IMU bins, " + std::to_string(opticalPoints()) +
          " optical points");
    solveOnce(m_options.maxIterations);
    alignGauges();
    solveOnce(m_options.polishIterations);
    m_solverOptions.callbacks.clear();
    result.iterations = m_iterations;
    result.converged = m_summary.termination_type == ceres::CONVERGENCE;
    result.initialCost = m_summary.initial_cost;
    result.finalCost = m_summary.final_cost;
    if (!result.converged)
      result.warnings.push_back("the solver stopped before converging: " + m_summary.message);
    result.imuBins = imuBins();
    result.opticalPoints = opticalPoints();
    result.rmsUpperGyro = rmsOf(m_problem, m_upperBlocks, 0, 6, 3);
    result.rmsUpperAcc = rmsOf(m_problem, m_upperBlocks, 3, 6, 3);
    result.rmsForearmGyro = rmsOf(m_problem, m_forearmBlocks, 0, 6, 3);
    result.rmsForearmAcc = rmsOf(m_problem, m_forearmBlocks, 3, 6, 3);
    result.rmsPosition = rmsOf(m_problem, m_positionBlocks, 0, 3, 3);
  }

  /// The fitted joint trajectory at residualRateHz, in the recording's time.
  std::vector<JointEstimate> trajectory() const {
    std::vector<JointEstimate> out;
    const double binSeconds = 1.0 / m_options.residualRateHz;
    for (double t = m_in.tFirst; t <= m_in.tLast; t += binSeconds) {
      const SplineWeights w = splineWeights(m_grid, t);
      Vec5T<double> th, thd, thdd;
      evalAt(m_ctrl, w, th, thd, thdd);
      JointEstimate e;
      e.t = t;
      for (int j = 0; j < kNumJoints; ++j) e.th(j) = wrapAngle(th(j));
      e.thd = thd;
      e.thdd = thdd;
      out.push_back(e);
    }
    return out;
  }

  // 5. The calibration, in the real sensors' axes.
  Calibration calibration(Side side) const {
    Calibration c;
    c.side = side;
    c.geometry = m_in.nominal;
    c.geometry.lu3 = m_mountUa[0];
    c.geometry.lu5 = m_mountUa[1];
    c.geometry.thu4 = wrapAngle(m_mountUa[2]);
    c.geometry.lf6 = m_mountFa[0];
    c.geometry.lf8 = m_mountFa[1];
    c.geometry.thf7 = wrapAngle(m_mountFa[2]);
    c.geometry.l3 = m_seg[0];
    c.geometry.l6 = m_seg[1];
    auto tilt = [](const std::array<double, 5>& m) {
      const Vec3 v(m[3], 0.0, m[4]);
      const double a = v.norm();
      return a < 1e-300 ? Eigen::Matrix3d::Identity()
                        : Eigen::AngleAxisd(a, v / a).toRotationMatrix();
    };
    c.upperArm.rotation = tilt(m_mountUa);
    c.upperArm.gyroBias = Vec3(m_biasUa[0], m_biasUa[1], m_biasUa[2]);
    c.forearm.rotation = tilt(m_mountFa);
    c.forearm.gyroBias = Vec3(m_biasFa[0], m_biasFa[1], m_biasFa[2]);
    if (m_in.left) {
      c.upperArm = mirrorImuCalibration(c.upperArm);
      c.forearm = mirrorImuCalibration(c.forearm);
    }
    c.opticalUsed = m_in.optical;
    c.headingFromStartPoseOnly = !m_in.optical;
    c.estimated = {"lu3",
                   "lu5",
                   "thu4",
                   "upperArm.rotation",
                   "upperArm.gyroBias",
                   "lf6",
                   "lf8",
                   "forearm.rotation",
                   "forearm.gyroBias"};
    c.fromStartPose = {"thf7"};
    if (!m_in.optical) c.fromStartPose.push_back("heading");
    if (fitSegments()) {
      c.estimated.push_back("l3");
      c.estimated.push_back("l6");
    } else {
      c.heldFixed = {"l3", "l6"};
    }
    return c;
  }

 private:
  struct Point {
    double t;
    Vec3 p;
    bool wrist;
  };

  static ceres::Problem::Options problemOptions() {
    ceres::Problem::Options popt;
    popt.cost_function_ownership = ceres::TAKE_OWNERSHIP;
    return popt;
  }

  bool fitSegments() const { return m_in.optical && m_options.estimateSegmentLengths; }

  static void evalAt(const std::vector<double>& cp, const SplineWeights& w, Vec5T<double>& th,
                     Vec5T<double>& thd, Vec5T<double>& thdd) {
    const double* const c[4] = {cp.data() + 5 * w.first, cp.data() + 5 * (w.first + 1),
                                cp.data() + 5 * (w.first + 2), cp.data() + 5 * (w.first + 3)};
    evalSpline(w, c, th, thd, thdd);
  }
  JointVector thAt(const SplineWeights& w) const {
    Vec5T<double> th, thd, thdd;
    evalAt(m_ctrl, w, th, thd, thdd);
    return JointVector(th);
  }
  double* ctrlAt(int i) { return m_ctrl.data() + 5 * i; }
  std::vector<double*> ctrlBlocks(const SplineWeights& w) {
    return std::vector<double*>{ctrlAt(w.first), ctrlAt(w.first + 1), ctrlAt(w.first + 2),
                                ctrlAt(w.first + 3)};
  }

  /// The gauges, moved exactly instead of by the solver (whose damped steps barely move along a
  /// direction that only one prior term sees): pronation th5 and the strap angle thf7 only appear
  /// as th5 + thf7, and without optical data turning the whole trajectory about the vertical
  /// changes no reading. Both are put where the start pose says.
  void alignGauges() {
    const JointVector& pose = m_options.startPose;
    double alpha = 0.0;
    if (!m_in.optical) {
      const JointVector th = thAt(m_priorWeights);
      const JointVector d = headingDirection(pose, m_in.up);
      auto f = [&](double a) {
        return d.dot(unwrappedNear(turnAboutVertical(th, a, m_in.up), pose) - pose);
      };
      double a0 = 0.0, a1 = 0.02, f0 = f(a0), f1 = f(a1);
      for (int it = 0; it < 30 && std::abs(f1) > 1e-10 && f1 != f0; ++it) {
        const double a2 = a1 - f1 * (a1 - a0) / (f1 - f0);
        a0 = a1;
        f0 = f1;
        a1 = a2;
        f1 = f(a1);
      }
      if (std::isfinite(a1) && std::abs(f1) < 1e-6) {
        alpha = a1;
        turnKnots(m_ctrl, 0, alpha, m_in.up);
      }
    }
    const double dth5 = thAt(m_priorWeights)(4) - pose(4);
    for (int i = 0; i < m_grid.controlPoints(); ++i) m_ctrl[5 * i + 4] -= dth5;
    m_mountFa[2] += dth5;
    char line[160];
    std::snprintf(line, sizeof line,
                  "calibrate: to the start pose: turned %.2f deg about the vertical, th5 %.2f deg",
                  alpha / kDeg, -dth5 / kDeg);
    m_say(line);
  }

  /// The data, added in time order up to a horizon (s).
  void addDataUpTo(double horizon) {
    for (int imu = 0; imu < 2; ++imu) {
      const bool fa = imu == 1;
      for (; m_nextBin[imu] < m_bins[imu].size() && m_bins[imu][m_nextBin[imu]].t <= horizon;
           ++m_nextBin[imu]) {
        const ImuBin& bin = m_bins[imu][m_nextBin[imu]];
        const SplineWeights w = splineWeights(m_grid, bin.t);
        auto* cost = new ceres::AutoDiffCostFunction<ImuCost, 6, 5, 5, 5, 5, 5, 3, 2>(
            new ImuCost(w, bin, m_in.nominal, m_in.gUp, m_options.gyroStd, m_options.accelStd, fa));
        std::vector<double*> blocks = ctrlBlocks(w);
        blocks.push_back(fa ? m_mountFa.data() : m_mountUa.data());
        blocks.push_back(fa ? m_biasFa.data() : m_biasUa.data());
        blocks.push_back(m_seg.data());
        (fa ? m_forearmBlocks : m_upperBlocks)
            .push_back(m_problem.AddResidualBlock(cost, nullptr, blocks));
      }
    }
    for (; m_nextPoint < m_points.size() && m_points[m_nextPoint].t <= horizon; ++m_nextPoint) {
      const Point& pt = m_points[m_nextPoint];
      const SplineWeights w = splineWeights(m_grid, pt.t);
      auto* cost = new ceres::AutoDiffCostFunction<PositionCost, 3, 5, 5, 5, 5, 2>(
          new PositionCost(w, pt.p, pt.wrist, m_in.nominal, m_options.positionStd));
      std::vector<double*> blocks = ctrlBlocks(w);
      blocks.push_back(m_seg.data());
      m_positionBlocks.push_back(m_problem.AddResidualBlock(cost, nullptr, blocks));
    }
  }

  void solveOnce(int maxIterations) {
    m_solverOptions.max_num_iterations = maxIterations;
    ceres::Solve(m_solverOptions, &m_problem, &m_summary);
    m_iterations += static_cast<int>(m_summary.iterations.size()) - 1;
    if (m_summary.IsSolutionUsable()) return;
    std::string why = m_summary.message;
    std::replace(why.begin(), why.end(), '\n', ' ');
    if (why.find("evaluation failed") != std::string::npos) {
      throw std::runtime_error(
          "calibration failed: the model could not be evaluated on the data (the solver: " + why +
          "); the recording holds readings the fit cannot use");
    }
    throw std::runtime_error("calibration failed: " + why);
  }

  /// Without optical data the filter's heading wanders (tens of degrees over a minute with a
  /// wrong mounting), and the solver cannot turn a long stretch of trajectory back about the
  /// vertical: that is a curved valley of the cost. So the data enter in stages. The first
  /// stage starts from the filter; each later one from the solved trajectory continued by
  /// integrating the gyroscopes with the calibration found so far (dead reckoning).
  void solveInStages() {
    const double tFirst = m_in.tFirst, tLast = m_in.tLast;
    double horizon = tFirst + 0.5 * m_options.startStillSeconds + m_options.stageSeconds;
    addDataUpTo(horizon);
    m_say("calibrate: stage 1, data up to " +
          std::to_string(static_cast<int>(std::round(horizon - tFirst))) + " s");
    solveOnce(m_options.stageIterations);
    for (int stage = 2; horizon < tLast; ++stage) {
      const double next = std::min(horizon + m_options.stageSeconds, tLast);
      const DeadReckoning dr{m_grid,          m_bins,           m_in.nominal,
                             m_in.gUp,        m_mountUa.data(), m_mountFa.data(),
                             m_biasUa.data(), m_biasFa.data(),  m_seg.data()};
      dr.extend(m_ctrl, horizon, next + 3.0 * m_grid.dt);
      addDataUpTo(next);
      m_say("calibrate: stage " + std::to_string(stage) + ", data up to " +
            std::to_string(static_cast<int>(std::round(next - tFirst))) + " s");
      solveOnce(m_options.stageIterations);
      horizon = next;
    }
  }

  const Prepared& m_in;
  const CalibrationOptions& m_options;
  const CalibrationProgress& m_say;
  SplineGrid m_grid;
  SplineWeights m_priorWeights;
  std::vector<double> m_ctrl;
  std::array<double, 5> m_mountUa{}, m_mountFa{};
  std::array<double, 3> m_biasUa{}, m_biasFa{};
  std::array<double, 2> m_seg{};
  std::vector<ImuBin> m_bins[2];
  std::vector<Point> m_points;
  ceres::Problem m_problem;
  ceres::Solver::Options m_solverOptions;
  ceres::Solver::Summary m_summary;
  int m_iterations = 0;
  std::vector<ceres::ResidualBlockId> m_upperBlocks, m_forearmBlocks, m_positionBlocks;
  std::size_t m_nextBin[2] = {0, 0}, m_nextPoint = 0;
};

}  // namespace

namespace {

// The sternum sensor's tilt from the still start pose, when the recording has one; its heading
// and position stay the sidecar's (or the default flat on the sternum).
void calibrateSternum(const Recording& recording, const CalibrationOptions& options,
                      CalibrationResult& result, const CalibrationProgress& say) {
  const auto first = std::find_if(recording.samples.begin(), recording.samples.end(),
                                  [](const ArmSample& s) { return s.trunk.has_value(); });
  if (first == recording.samples.end()) return;
  const double t0 = recording.samples.front().t;
  TrunkMountingParams p;
  p.up = recording.meta.up;
  p.g = recording.meta.g;
  p.fromS = t0 + 0.3;
  p.toS = t0 + options.startStillSeconds;
  const TrunkMount initial = recording.meta.trunk.value_or(defaultTrunkMount(recording.meta.side));
  const TrunkMounting m = calibrateTrunkMount(recording.samples, initial, p);
  if (!m.mount) {
    result.warnings.push_back("the sternum sensor's mounting was not calibrated: " + m.problem);
    say("calibrate: " + result.warnings.back());
    return;
  }
  result.calibration.trunk = m.mount;
  char line[160];
  std::snprintf(line, sizeof line,
                "calibrate: sternum sensor levelled from the start pose (%.1f deg from the "
                "assumed mounting; heading kept)",
                m.tiltDeg);
  say(line);
}

}  // namespace

CalibrationResult calibrate(const Recording& recording, const CalibrationOptions& options,
                            const CalibrationProgress& progress) {
  const auto wallStart = std::chrono::steady_clock::now();
  const CalibrationProgress say = [&](const std::string& line) {
    if (progress) progress(line);
  };
  const QuietGlog quiet;
  CalibrationResult result;
  const Prepared in = prepare(recording, options);
  result.implausible = in.implausible;
  if (in.implausible.total() > 0)
    say("calibrate: " + in.implausible.summary() + "; they take no part in the fit");
  const std::array<Vec3, 2> biasGuess = guessGyroBias(in, options, result, say);
  CalibrationFit fit(in, biasGuess, options, say);
  fit.start(firstTrajectory(in, biasGuess, options, say));
  fit.addPriors();
  fit.solve(result);
  result.trajectory = fit.trajectory();
  result.calibration = fit.calibration(recording.meta.side);
  calibrateSternum(recording, options, result, say);
  // A fit no real arm can have (e.g. segment lengths pulled to their bounds) is refused.
  if (const std::string problem = calibrationProblem(result.calibration); !problem.empty()) {
    throw std::runtime_error(
        "the fitted calibration is impossible: " + problem +
        ". The recording does not determine the calibration: redo the calibration protocol "
        "(docs/calibration.md), start pose held still and every movement made, and calibrate "
        "again");
  }
  result.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  char line[200];
  std::snprintf(line, sizeof line, "calibrate: done, %d iterations, cost %.6g -> %.6g, %.1f s",
                result.iterations, result.initialCost, result.finalCost, result.seconds);
  say(line);
  return result;
}

}  // namespace armtrack
