#include "core/estimation/WindowFit.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "core/camera/PinholeCamera.h"
#include "core/estimation/MeasurementBlocks.h"

namespace armtrack {
namespace {

using Vec15 = Eigen::Matrix<double, 15, 1>;
// Per joint th(tau) = sum_k c_k s^k with s = tau / span, tau = t - tEnd <= 0: a degree-7
// polynomial represents a whole minimum-jerk reach (degree 5) and the smooth turn between two,
// where a cubic would bend the data to fit.
constexpr int kCoeffs = 8;
// A sample whose whitened residual exceeds this per row on average is an outlier of the fit.
constexpr double kOutlierSigma = 5.0;

// d[th'' th' th]_j / d(coefficients of joint j) at tau.
Eigen::Matrix<double, 3, kCoeffs> stateOfCoeffs(double tau, double span) {
  const double sv = tau / span;
  Eigen::Matrix<double, 3, kCoeffs> m = Eigen::Matrix<double, 3, kCoeffs>::Zero();
  for (int k = 0; k < kCoeffs; ++k) {
    m(2, k) = std::pow(sv, k);
    if (k >= 1) m(1, k) = k * std::pow(sv, k - 1) / span;
    if (k >= 2) m(0, k) = k * (k - 1) * std::pow(sv, k - 2) / (span * span);
  }
  return m;
}

Vec15 stateAt(const double* const* coeffs, double tau, double span) {
  const Eigen::Matrix<double, 3, kCoeffs> m = stateOfCoeffs(tau, span);
  Vec15 x;
  for (int j = 0; j < kNumJoints; ++j) {
    const Eigen::Map<const Eigen::Matrix<double, kCoeffs, 1>> c(coeffs[j]);
    const Eigen::Vector3d s = m * c;
    x(j) = s(0);
    x(5 + j) = s(1);
    x(10 + j) = s(2);
  }
  return x;
}

// The readings of one sample (or its optical part) against the motion at its time.
class SampleCost final : public ceres::CostFunction {
 public:
  SampleCost(const EstimatorParams& p, const ArmSample& s, double tau, double span, bool imuPart,
             const WindowFrame* frame = nullptr)
      : m_p(p), m_tau(tau), m_span(span) {
    if (frame) {
      m_base = frame->base;
      if (frame->camera) m_camera.emplace(*frame->camera);
    }
    const bool gyro = p.model != MeasurementModel::Inclinometer;
    const double sg = std::sqrt(p.gyroVariance), sa = std::sqrt(p.accelVariance);
    const double sp = std::sqrt(p.positionVariance), spx = std::sqrt(p.pixelVariance);
    if (imuPart) {
      if (s.upperArm) {
        if (gyro) add(0, s.upperArm->gyr, sg);
        add(3, s.upperArm->acc, sa);
      }
      if (s.forearm) {
        if (gyro) add(6, s.forearm->gyr, sg);
        add(9, s.forearm->acc, sa);
      }
    } else {
      if (s.elbow) add(12, *s.elbow, sp);
      if (s.wrist) add(15, *s.wrist, sp);
      if (p.camera && p.useCamera) {
        if (s.camWrist) m_pixels.push_back({true, *s.camWrist, spx});
        if (s.camElbow) m_pixels.push_back({false, *s.camElbow, spx});
      }
    }
    set_num_residuals(rows());
    for (int j = 0; j < kNumJoints; ++j) mutable_parameter_block_sizes()->push_back(kCoeffs);
  }

  int rows() const {
    return 3 * static_cast<int>(m_blocks.size()) + 2 * static_cast<int>(m_pixels.size());
  }

  bool Evaluate(double const* const* params, double* residuals, double** jacobians) const override {
    const Vec15 x = stateAt(params, m_tau, m_span);
    Eigen::Map<Eigen::VectorXd> r(residuals, rows());
    Eigen::MatrixXd dx(rows(), 15);  // d(residual)/d(state)
    dx.setZero();
    int row = 0;
    if (!m_blocks.empty()) {
      const FrameState<double>* base = m_base ? &*m_base : nullptr;
      Eigen::Matrix<double, 18, 1> h;
      Eigen::Matrix<double, 18, 15> jac;
      if (!base) {
        h = predictAll(m_p, x);
        if (jacobians) jac = predictAllJacobian(m_p, x);
      } else if (jacobians) {
        detail::predictBaseWithJacobian(m_p, x, h, jac, base);
      } else {
        detail::predictBase<double>(m_p, x, h, base);
      }
      for (const Block& b : m_blocks) {
        r.segment<3>(row) = (h.segment<3>(b.offset) - b.z) / b.sigma;
        if (jacobians) dx.middleRows<3>(row) = jac.middleRows<3>(b.offset) / b.sigma;
        row += 3;
      }
    }
    for (const Pixel& px : m_pixels) {
      Eigen::Vector2d predicted;
      Eigen::Matrix<double, 2, 15> jac;
      if (pixel(x, px.wrist, predicted, jacobians ? &jac : nullptr)) {
        r.segment<2>(row) = (predicted - px.z) / px.sigma;
        if (jacobians) dx.middleRows<2>(row) = jac / px.sigma;
      } else {
        r.segment<2>(row).setZero();  // out of view at this motion: no information
      }
      row += 2;
    }
    if (!r.allFinite()) return false;
    if (jacobians) {
      const Eigen::Matrix<double, 3, kCoeffs> m = stateOfCoeffs(m_tau, m_span);
      for (int j = 0; j < kNumJoints; ++j) {
        if (!jacobians[j]) continue;
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, kCoeffs, Eigen::RowMajor>> out(
            jacobians[j], rows(), kCoeffs);
        out = dx.col(j) * m.row(0) + dx.col(5 + j) * m.row(1) + dx.col(10 + j) * m.row(2);
      }
    }
    return true;
  }

 private:
  // The marker's pixel from the camera as frame 0 saw it, or params.camera for a still trunk.
  bool pixel(const Vec15& x, bool wrist, Eigen::Vector2d& out,
             Eigen::Matrix<double, 2, 15>* jac) const {
    if (!m_camera) return predictMarkerPixel(m_p, x, wrist, out, jac);
    Eigen::Matrix<double, 18, 1> h;
    Eigen::Matrix<double, 18, 15> all;
    detail::predictBaseWithJacobian(m_p, x, h, all, m_base ? &*m_base : nullptr);
    const int row = wrist ? 15 : 12;
    const Eigen::Matrix<double, 3, 15> dp = all.middleRows<3>(row);
    return detail::markerPixel(*m_camera, m_p.side == Side::Left, h.segment<3>(row), &dp, out, jac);
  }

  struct Block {
    int offset;
    Eigen::Vector3d z;
    double sigma;
  };
  struct Pixel {
    bool wrist;
    Eigen::Vector2d z;
    double sigma;
  };
  void add(int offset, const Eigen::Vector3d& z, double sigma) {
    m_blocks.push_back({offset, z, sigma});
  }

  const EstimatorParams& m_p;
  double m_tau, m_span;
  std::optional<FrameState<double>> m_base;  // frame 0's motion; none: a still trunk
  std::optional<PinholeCamera> m_camera;     // the camera seen from frame 0; none: params'
  std::vector<Block> m_blocks;
  std::vector<Pixel> m_pixels;
};

// Holds the heading of the angles at the window's end (the constant coefficients) at an
// anchor's: (h . (th - anchor)) / 0.5 deg, h the unit heading direction at the anchor.
class HeadingAnchor final : public ceres::CostFunction {
 public:
  HeadingAnchor(const JointVector& anchor, const Eigen::Vector3d& up)
      : m_anchor(anchor), m_h(headingDirection(anchor, up)) {
    set_num_residuals(1);
    for (int j = 0; j < kNumJoints; ++j) mutable_parameter_block_sizes()->push_back(kCoeffs);
  }
  bool Evaluate(double const* const* params, double* residuals, double** jacobians) const override {
    constexpr double kSigma = 0.5 * std::numbers::pi / 180.0;
    double r = 0.0;
    for (int j = 0; j < kNumJoints; ++j) r += m_h(j) * wrapAngle(params[j][0] - m_anchor(j));
    residuals[0] = r / kSigma;
    if (jacobians) {
      for (int j = 0; j < kNumJoints; ++j) {
        if (!jacobians[j]) continue;
        for (int k = 0; k < kCoeffs; ++k) jacobians[j][k] = 0.0;
        jacobians[j][0] = m_h(j) / kSigma;
      }
    }
    return true;
  }

 private:
  JointVector m_anchor, m_h;
};

double spanOf(const std::vector<ArmSample>& window) {
  return std::max(window.back().t - window.front().t, 1e-3);
}

// The problem over a window with coefficient storage `coeffs` (5 x 4). Returns the number of
// residual rows.
int buildProblem(ceres::Problem& problem, const EstimatorParams& p,
                 const std::vector<ArmSample>& window, int maxImuSamples,
                 std::array<std::array<double, kCoeffs>, kNumJoints>& coeffs,
                 std::vector<const SampleCost*>& costs, const std::vector<WindowFrame>* frames) {
  const double tEnd = window.back().t;
  const double span = spanOf(window);
  std::vector<double*> blocks;
  for (auto& c : coeffs) blocks.push_back(c.data());
  std::size_t imuCount = 0;
  for (const ArmSample& s : window) imuCount += s.hasImu();
  const double every = std::max(1.0, double(imuCount) / std::max(1, maxImuSamples));
  double next = 0.0;
  std::size_t imuIndex = 0;
  int rows = 0;
  for (std::size_t i = 0; i < window.size(); ++i) {
    const ArmSample& s = window[i];
    const WindowFrame* frame = frames && i < frames->size() ? &(*frames)[i] : nullptr;
    const double tau = s.t - tEnd;
    if (s.hasImu()) {
      // Thin evenly, always keeping the last IMU sample (where the state is wanted).
      const bool last = imuIndex + 1 == imuCount;
      if (double(imuIndex) >= next || last) {
        next += every;
        auto* cost = new SampleCost(p, s, tau, span, true, frame);
        if (cost->rows() > 0) {
          rows += cost->rows();
          costs.push_back(cost);
          // Huber on the sample's whitened norm: a reading the motion cannot explain at all
          // (an undetected glitch) pulls linearly, not quadratically.
          problem.AddResidualBlock(cost, new ceres::HuberLoss(3.0 * std::sqrt(cost->rows())),
                                   blocks);
        } else {
          delete cost;
        }
      }
      ++imuIndex;
    }
    auto* optical = new SampleCost(p, s, tau, span, false, frame);
    if (optical->rows() > 0) {
      rows += optical->rows();
      costs.push_back(optical);
      problem.AddResidualBlock(optical, new ceres::HuberLoss(3.0), blocks);
    } else {
      delete optical;
    }
  }
  for (int j = 0; j < kNumJoints; ++j) {
    if (!p.activeJoints[j] && problem.HasParameterBlock(coeffs[j].data()))
      problem.SetParameterBlockConstant(coeffs[j].data());
  }
  return rows;
}

// Coefficients of the constant-acceleration motion through x at the window's end.
std::array<std::array<double, kCoeffs>, kNumJoints> coeffsOf(const EstimatorParams& p,
                                                             const Vec15& x, double span) {
  std::array<std::array<double, kCoeffs>, kNumJoints> c{};
  for (int j = 0; j < kNumJoints; ++j) {
    if (p.activeJoints[j]) {
      c[j][0] = x(10 + j);
      c[j][1] = x(5 + j) * span;
      c[j][2] = 0.5 * x(j) * span * span;
    } else {
      c[j][0] = p.fixedAngles(j);
    }
  }
  return c;
}

}  // namespace

WindowFitResult fitWindow(const EstimatorParams& params, const std::vector<ArmSample>& window,
                          const std::vector<Vec15>& seeds,
                          const std::optional<JointVector>& headingAnchor, int maxImuSamples,
                          const std::vector<WindowFrame>* frames) {
  WindowFitResult best;
  if (window.empty() || seeds.empty()) return best;
  best.tEnd = window.back().t;
  double bestCost = std::numeric_limits<double>::infinity();
  for (const Vec15& seed : seeds) {
    auto coeffs = coeffsOf(params, seed, spanOf(window));
    ceres::Problem problem;
    std::vector<const SampleCost*> costs;  // owned by the problem
    const int rows = buildProblem(problem, params, window, maxImuSamples, coeffs, costs, frames);
    if (rows == 0) return best;
    if (headingAnchor) {
      std::vector<double*> blocks;
      for (auto& c : coeffs) blocks.push_back(c.data());
      problem.AddResidualBlock(new HeadingAnchor(*headingAnchor, params.gUp.normalized()), nullptr,
                               blocks);
    }
    ceres::Solver::Options opt;
    opt.linear_solver_type = ceres::DENSE_QR;
    opt.max_num_iterations = 30;
    opt.logging_type = ceres::SILENT;
    opt.minimizer_progress_to_stdout = false;
    opt.num_threads = 1;
    ceres::Solver::Summary summary;
    ceres::Solve(opt, &problem, &summary);
    if (!summary.IsSolutionUsable() || !(summary.final_cost < bestCost)) continue;
    bestCost = summary.final_cost;
    std::array<const double*, kNumJoints> ptrs{};
    for (int j = 0; j < kNumJoints; ++j) ptrs[j] = coeffs[j].data();
    best.x = stateAt(ptrs.data(), 0.0, spanOf(window));
    for (int j = 0; j < kNumJoints; ++j) best.x(10 + j) = wrapAngle(best.x(10 + j));
    best.ok = true;
    best.residuals = rows;
    // The RMS over the samples the motion explains: a sample whose whitened residual is beyond
    // kOutlierSigma per row on average (a glitch the Huber loss already discounted) is counted,
    // not averaged in, so a few bad readings in the window cannot hide a good fit.
    double inlierSum = 0.0;
    int inlierRows = 0;
    best.outlierSamples = 0;
    for (const SampleCost* cost : costs) {
      Eigen::VectorXd r(cost->rows());
      if (!cost->Evaluate(ptrs.data(), r.data(), nullptr)) {
        ++best.outlierSamples;
        continue;
      }
      if (r.squaredNorm() > kOutlierSigma * kOutlierSigma * cost->rows()) {
        ++best.outlierSamples;
        continue;
      }
      inlierSum += r.squaredNorm();
      inlierRows += cost->rows();
    }
    best.samples = static_cast<int>(costs.size());
    best.rms = inlierRows > 0 ? std::sqrt(inlierSum / inlierRows)
                              : std::numeric_limits<double>::infinity();
  }
  return best;
}

double trajectoryRms(const EstimatorParams& params, const std::vector<ArmSample>& window,
                     const std::vector<Vec15>& states, const std::vector<WindowFrame>* frames) {
  double sum = 0.0;
  int rows = 0;
  std::array<std::array<double, kCoeffs>, kNumJoints> coeffs{};
  std::array<const double*, kNumJoints> ptrs{};
  for (int j = 0; j < kNumJoints; ++j) ptrs[j] = coeffs[j].data();
  for (std::size_t i = 0; i < window.size() && i < states.size(); ++i) {
    // The state itself as a constant motion evaluated at tau = 0.
    coeffs = coeffsOf(params, states[i], 1.0);
    for (bool imu : {true, false}) {
      const SampleCost cost(params, window[i], 0.0, 1.0, imu,
                            frames && i < frames->size() ? &(*frames)[i] : nullptr);
      if (cost.rows() == 0) continue;
      Eigen::VectorXd r(cost.rows());
      if (!cost.Evaluate(ptrs.data(), r.data(), nullptr))
        return std::numeric_limits<double>::infinity();
      sum += r.squaredNorm();
      rows += cost.rows();
    }
  }
  return rows > 0 ? std::sqrt(sum / rows) : 0.0;
}

}  // namespace armtrack
