// Local quadratic regression (a Savitzky-Golay filter on the actual time stamps): smoothed values
// and first derivatives of sampled signals with non-uniform times and gaps. Used for angular
// velocity and wrist speed (docs/metrics.md).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace armtrack {

struct SmoothingParams {
  /// Half-width of the fitting window (s): each sample's value and rate come from a polynomial
  /// fitted by least squares to the samples within +-halfWindowSeconds. Default 0.15 s (a 0.3 s
  /// window, 31 samples at 100 Hz): with the cubic below it keeps the rate of a 1 Hz movement
  /// within about 1 % and averages sensor noise over the window.
  double halfWindowSeconds = 0.15;
  /// Degree of the local polynomial, 1-3. A cubic gives the same smoothed value as a quadratic
  /// in a symmetric window but a far less attenuated derivative. Default 3.
  int polynomialOrder = 3;
  /// A window holding more samples than this is thinned evenly (every 2nd, 3rd... sample), which
  /// bounds the cost at high rates: 100 samples keeps every sample up to 330 Hz with the default
  /// window and every 4th at 1 kHz. 0 = no limit.
  int maxSamplesPerFit = 100;
  /// A step between consecutive time stamps longer than this (s) is a gap: no fit reaches across
  /// it and the time inside it counts neither as moving nor as resting. Default 0.25 s.
  double maxGapSeconds = 0.25;
};

/// A run of samples [begin, end) with no gap inside.
struct Segment {
  std::size_t begin = 0;
  std::size_t end = 0;
};

/// Splits strictly increasing times t (s) where a step exceeds maxGapSeconds.
std::vector<Segment> splitAtGaps(const std::vector<double>& t, double maxGapSeconds);

/// Smoothed values and first derivatives (per second) of the columns of `values` (one row per
/// time stamp), from the polynomial fitted within each sample's window and segment; the degree
/// drops to (samples in the window - 1) when the window holds too few samples, so two samples
/// give their straight line and a lone sample keeps its value with derivative 0.
/// Preconditions (checked by the callers): t strictly increasing and finite, rows == t.size(),
/// halfWindowSeconds > 0, polynomialOrder 1-3.
void smoothWithDerivative(const std::vector<double>& t, const Eigen::MatrixXd& values,
                          const SmoothingParams& params, Eigen::MatrixXd& smoothed,
                          Eigen::MatrixXd& derivative);

/// Weights of a local polynomial fit: the fitted value at tc is sum valueWeight[q] *
/// y[index[q]], its derivative (per second) sum rateWeight[q] * y[index[q]]. Reused between
/// calls to avoid allocating per sample.
struct LocalFit {
  std::vector<std::size_t> index;
  std::vector<double> valueWeight, rateWeight;
};

/// Weights of the least-squares polynomial (degree up to maxOrder, at most samples - 1) through
/// samples [lo, hi) of t around time tc, with u = (t - tc) / h. More than maxSamples samples
/// (when maxSamples > 0) are thinned evenly. Needs hi > lo.
void localFitWeights(const std::vector<double>& t, std::size_t lo, std::size_t hi, double tc,
                     double h, int maxOrder, int maxSamples, LocalFit& fit);

/// Time each sample stands for (s): half the step to each neighbour inside its segment, so the
/// weights of a segment add up to its span and a lone sample weighs 0.
std::vector<double> sampleWeights(const std::vector<double>& t,
                                  const std::vector<Segment>& segments);

}  // namespace armtrack
