#include "core/metrics/Smoothness.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <unsupported/Eigen/FFT>

namespace armtrack {

const char* toString(SmoothnessStatus s) {
  switch (s) {
    case SmoothnessStatus::Ok:
      return "ok";
    case SmoothnessStatus::TooShort:
      return "too few samples";
    case SmoothnessStatus::NonFinite:
      return "non-finite sample or sample rate";
    case SmoothnessStatus::NoMovement:
      return "no movement";
    case SmoothnessStatus::ZeroJerk:
      return "no jerk (constant velocity)";
  }
  return "unknown";
}

namespace {

SmoothnessValue fail(SmoothnessStatus s) {
  return {0.0, s};
}

bool allFinite(const std::vector<double>& x) {
  return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

SmoothnessValue sparc(const std::vector<double>& speed, double fs, const SparcParams& params) {
  if (!(std::isfinite(fs) && fs > 0) || !allFinite(speed)) return fail(SmoothnessStatus::NonFinite);
  if (speed.size() < 4) return fail(SmoothnessStatus::TooShort);
  if (std::all_of(speed.begin(), speed.end(), [](double v) { return v == 0.0; }))
    return fail(SmoothnessStatus::NoMovement);
  if (!(params.maxCutoffHz > 0 && params.amplitudeThreshold > 0 && params.amplitudeThreshold < 1 &&
        params.padLevel >= 0 && params.padLevel <= 8)) {
    throw std::invalid_argument("sparc: cut-off > 0, 0 < threshold < 1, pad level 0-8");
  }
  const int bits = static_cast<int>(std::ceil(std::log2(static_cast<double>(speed.size()))));
  const std::size_t nfft = std::size_t{1} << (bits + params.padLevel);
  std::vector<double> padded(nfft, 0.0);
  std::copy(speed.begin(), speed.end(), padded.begin());
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, padded);  // bins 0 .. nfft/2
  std::vector<double> mag(spectrum.size());
  double peak = 0;
  for (std::size_t k = 0; k < spectrum.size(); ++k) {
    mag[k] = std::abs(spectrum[k]);
    peak = std::max(peak, mag[k]);
  }
  // The mirrored upper half has the same magnitudes, so the maximum over the half is the
  // maximum over the whole spectrum.
  const double df = fs / static_cast<double>(nfft);
  std::size_t last = 0;  // bins with f <= maxCutoffHz
  while (last + 1 < mag.size() && static_cast<double>(last + 1) * df <= params.maxCutoffHz) ++last;
  std::size_t first = mag.size(), lastAbove = 0;
  for (std::size_t k = 0; k <= last; ++k) {
    if (mag[k] / peak >= params.amplitudeThreshold) {
      first = std::min(first, k);
      lastAbove = k;
    }
  }
  if (first == mag.size() || lastAbove == first) return {0.0, SmoothnessStatus::Ok};
  const double band = static_cast<double>(lastAbove - first) * df;
  double arc = 0;
  for (std::size_t k = first; k < lastAbove; ++k) {
    const double dfn = df / band, dm = (mag[k + 1] - mag[k]) / peak;
    arc += std::sqrt(dfn * dfn + dm * dm);
  }
  return {-arc, SmoothnessStatus::Ok};
}

SmoothnessValue ldljFromVelocity(const Eigen::MatrixXd& v, double fs) {
  if (!(std::isfinite(fs) && fs > 0) || !v.allFinite()) return fail(SmoothnessStatus::NonFinite);
  const Eigen::Index n = v.rows();
  if (n < 4) return fail(SmoothnessStatus::TooShort);
  const double vPeak = v.rowwise().norm().maxCoeff();
  if (vPeak == 0.0) return fail(SmoothnessStatus::NoMovement);
  const double dt = 1.0 / fs;
  double integral = 0;
  for (Eigen::Index i = 1; i + 1 < n; ++i) {
    const Eigen::RowVectorXd jerk = (v.row(i + 1) - 2.0 * v.row(i) + v.row(i - 1)) / (dt * dt);
    integral += jerk.squaredNorm() * dt;
  }
  if (integral == 0.0) return fail(SmoothnessStatus::ZeroJerk);
  const double duration = static_cast<double>(n) * dt;
  return {-std::log(std::pow(duration, 3) / (vPeak * vPeak) * integral), SmoothnessStatus::Ok};
}

SmoothnessValue ldljFromSpeed(const std::vector<double>& speed, double fs) {
  Eigen::MatrixXd v(static_cast<Eigen::Index>(speed.size()), 1);
  for (std::size_t i = 0; i < speed.size(); ++i) v(static_cast<Eigen::Index>(i), 0) = speed[i];
  return ldljFromVelocity(v, fs);
}

namespace {

void checkPath(const std::vector<double>& t, Eigen::Index rows,
               const PathSmoothnessParams& params) {
  if (static_cast<Eigen::Index>(t.size()) != rows) {
    throw std::invalid_argument("path smoothness: times and positions differ in length");
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i]) || (i > 0 && !(t[i] > t[i - 1]))) {
      throw std::invalid_argument(
          "path smoothness: times must be finite and increase strictly (row " + std::to_string(i) +
          ")");
    }
  }
  if (!(params.smoothing.halfWindowSeconds > 0 && params.smoothing.polynomialOrder >= 1 &&
        params.smoothing.polynomialOrder <= 3 &&
        (params.smoothing.maxSamplesPerFit == 0 || params.smoothing.maxSamplesPerFit >= 4) &&
        std::isfinite(params.resampleHz) && params.resampleHz >= 0)) {
    throw std::invalid_argument(
        "path smoothness: window > 0, order 1-3, samples per fit 0 or >= 4, resample rate >= 0");
  }
}

// The grid's rate and start, without checks.
UniformVelocity gridOf(const std::vector<double>& t, const PathSmoothnessParams& params) {
  UniformVelocity out;
  if (t.size() < 2) return out;
  std::vector<double> steps(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) steps[i - 1] = t[i] - t[i - 1];
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                   sorted.end());
  const double median = sorted[sorted.size() / 2];
  double sum = 0;
  std::size_t count = 0;
  for (double d : steps) {
    if (d <= 2 * median) {
      sum += d;
      ++count;
    }
  }
  out.sampleRateHz = params.resampleHz > 0 ? params.resampleHz : static_cast<double>(count) / sum;
  out.t0 = t.front();
  return out;
}

// Grid rows [first, first + count) of the velocity.
Eigen::MatrixXd velocityRows(const std::vector<double>& t, const Eigen::MatrixXd& positions,
                             const PathSmoothnessParams& params, const UniformVelocity& grid,
                             Eigen::Index first, Eigen::Index count) {
  // The local fit evaluated at each uniform time directly (no interpolation of a rate): the
  // velocity stays smooth enough for the second differences of the jerk.
  const double h = params.smoothing.halfWindowSeconds;
  Eigen::MatrixXd velocity = Eigen::MatrixXd::Zero(count, positions.cols());
  LocalFit fit;
  Eigen::RowVectorXd rate(positions.cols());
  for (Eigen::Index r = 0; r < count; ++r) {
    const double tq = grid.t0 + static_cast<double>(first + r) / grid.sampleRateHz;
    const auto lo =
        static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), tq - h) - t.begin());
    const auto hi =
        static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), tq + h) - t.begin());
    if (hi < lo + 2) continue;  // inside a gap: no estimate, counted as still
    localFitWeights(t, lo, hi, tq, h, params.smoothing.polynomialOrder,
                    params.smoothing.maxSamplesPerFit, fit);
    rate.setZero();
    for (std::size_t q = 0; q < fit.index.size(); ++q)
      rate.noalias() += fit.rateWeight[q] * positions.row(static_cast<Eigen::Index>(fit.index[q]));
    velocity.row(r) = rate;
  }
  return velocity;
}

}  // namespace

UniformVelocity uniformGrid(const std::vector<double>& t, const PathSmoothnessParams& params) {
  checkPath(t, static_cast<Eigen::Index>(t.size()), params);
  return gridOf(t, params);
}

UniformVelocity uniformVelocity(const std::vector<double>& t, const Eigen::MatrixXd& positions,
                                const PathSmoothnessParams& params) {
  checkPath(t, positions.rows(), params);
  UniformVelocity out = gridOf(t, params);
  if (t.size() < 2) return out;
  const auto m =
      static_cast<Eigen::Index>(std::floor((t.back() - t.front()) * out.sampleRateHz + 1e-9)) + 1;
  out.velocity = velocityRows(t, positions, params, out, 0, m);
  return out;
}

UniformVelocity uniformVelocityBetween(const std::vector<double>& t,
                                       const Eigen::MatrixXd& positions,
                                       const PathSmoothnessParams& params,
                                       const UniformVelocity& grid, double fromS, double toS) {
  UniformVelocity out;
  out.sampleRateHz = grid.sampleRateHz;
  if (t.size() < 2 || !(grid.sampleRateHz > 0) ||
      static_cast<Eigen::Index>(t.size()) != positions.rows())
    return out;
  const auto rows =
      static_cast<Eigen::Index>(std::floor((t.back() - t.front()) * grid.sampleRateHz + 1e-9)) + 1;
  const auto first = std::clamp<Eigen::Index>(
      static_cast<Eigen::Index>(std::ceil((fromS - grid.t0) * grid.sampleRateHz - 1e-9)), 0, rows);
  const auto last = std::clamp<Eigen::Index>(
      static_cast<Eigen::Index>(std::floor((toS - grid.t0) * grid.sampleRateHz + 1e-9)), -1,
      rows - 1);
  const Eigen::Index count = std::max<Eigen::Index>(last - first + 1, 0);
  out.t0 = grid.t0 + static_cast<double>(first) / grid.sampleRateHz;
  out.velocity = velocityRows(t, positions, params, grid, first, count);
  return out;
}

PathSmoothness velocitySmoothness(const Eigen::MatrixXd& velocity, double sampleRateHz,
                                  const PathSmoothnessParams& params) {
  PathSmoothness out;
  out.sampleRateHz = sampleRateHz;
  if (!velocity.allFinite()) {
    out.sparc = out.ldlj = fail(SmoothnessStatus::NonFinite);
    return out;
  }
  if (velocity.rows() < 4) return out;  // TooShort
  std::vector<double> speed(static_cast<std::size_t>(velocity.rows()));
  for (Eigen::Index k = 0; k < velocity.rows(); ++k)
    speed[static_cast<std::size_t>(k)] = velocity.row(k).norm();
  out.peakSpeedMPerS = *std::max_element(speed.begin(), speed.end());
  if (out.peakSpeedMPerS < params.minPeakSpeedMPerS) {
    out.sparc = out.ldlj = fail(SmoothnessStatus::NoMovement);
    return out;
  }
  out.sparc = sparc(speed, sampleRateHz, params.sparc);
  out.ldlj = ldljFromVelocity(velocity, sampleRateHz);
  return out;
}

PathSmoothness pathSmoothness(const std::vector<double>& t, const Eigen::MatrixXd& positions,
                              const PathSmoothnessParams& params) {
  const UniformVelocity v = uniformVelocity(t, positions, params);
  return velocitySmoothness(v.velocity, v.sampleRateHz, params);
}

Eigen::MatrixXd wristPath(const std::vector<ClinicalRow>& anglesRad, const ArmGeometry& geometry) {
  // armPositions() is the closed-form chain of forwardKinematics() (eq. 11) without the 4x4
  // products; test_smoothness checks the two agree.
  const ArmGeometryT<double> geo = geometryAs<double>(geometry);
  Eigen::MatrixXd out(static_cast<Eigen::Index>(anglesRad.size()), 3);
  Eigen::Vector3d elbow, wrist;
  for (std::size_t i = 0; i < anglesRad.size(); ++i) {
    armPositions<double>(jointsFromClinical(anglesRad[i]), geo, elbow, wrist);
    out.row(static_cast<Eigen::Index>(i)) = wrist.transpose();
  }
  return out;
}

}  // namespace armtrack
