// SPARC and LDLJ against values computed independently of the implementation: the authors'
// reference code (its documented examples), the continuous Fourier transform of the speed profile
// (by quadrature or in closed form, no FFT), and the analytic jerk of a minimum-jerk movement.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <limits>
#include <numbers>
#include <random>

#include "core/metrics/Smoothness.h"

namespace armtrack {
namespace {

constexpr double kPi = std::numbers::pi;

/// Minimum-jerk speed of a unit move over [0, T]: 30/T u^2 (1-u)^2, u = t/T; 0 outside.
double minJerkSpeed(double t, double T) {
  if (t < 0 || t > T) return 0.0;
  const double u = t / T;
  return 30.0 / T * u * u * (1 - u) * (1 - u);
}

/// Minimum-jerk position of a unit move over [0, T].
double minJerkPosition(double t, double T) {
  const double u = std::clamp(t / T, 0.0, 1.0);
  return u * u * u * (10 - 15 * u + 6 * u * u);
}

std::vector<double> sample(const std::function<double(double)>& f, double t0, double t1,
                           double fs) {
  std::vector<double> out;
  const int n = static_cast<int>(std::round((t1 - t0) * fs)) + 1;
  for (int k = 0; k < n; ++k) out.push_back(f(t0 + k / fs));
  return out;
}

/// SPARC from a normalised magnitude spectrum given as a function of frequency (Hz), scanned on
/// a fine grid: the paper's eq. 6 with the adaptive cut-off, no FFT and no sampling of v(t).
double sparcOfSpectrum(const std::function<double(double)>& mag, double df = 1e-3,
                       double fcMax = 10.0, double threshold = 0.05) {
  const int n = static_cast<int>(fcMax / df);
  std::vector<double> m(n + 1);
  for (int k = 0; k <= n; ++k) m[k] = mag(k * df);
  int last = 0;
  for (int k = 0; k <= n; ++k)
    if (m[k] >= threshold) last = k;
  const double fc = last * df;
  double arc = 0;
  for (int k = 0; k < last; ++k) arc += std::hypot(df / fc, m[k + 1] - m[k]);
  return -arc;
}

/// |V(f)| / V(0) of v on [0, T] by Simpson's rule (2000 intervals).
std::function<double(double)> quadratureSpectrum(const std::function<double(double)>& v, double T) {
  return [v, T](double f) {
    const int n = 2000;
    const double h = T / n;
    std::complex<double> acc = 0, dc = 0;
    for (int i = 0; i <= n; ++i) {
      const double t = i * h, w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
      acc += w * v(t) * std::polar(1.0, -2 * kPi * f * t);
      dc += w * v(t);
    }
    return std::abs(acc) / std::abs(dc);
  };
}

// The examples documented in the authors' scripts/smoothness.py (github.com/siva82kb/SPARC): a
// Gaussian speed profile exp(-5 t^2), t = -1 : 0.01 : 0.99, sampled at 100 Hz.
TEST(Smoothness, MatchesTheAuthorsDocumentedExamples) {
  std::vector<double> v;
  for (int i = 0; i < 200; ++i) {
    const double t = -1.0 + 0.01 * i;
    v.push_back(std::exp(-5 * t * t));
  }
  const SmoothnessValue s = sparc(v, 100.0);
  const SmoothnessValue l = ldljFromSpeed(v, 100.0);
  ASSERT_TRUE(s.ok());
  ASSERT_TRUE(l.ok());
  EXPECT_NEAR(s.value, -1.41403, 5e-5);
  EXPECT_NEAR(l.value, -5.81636, 5e-5);
  std::printf("Gaussian: SPARC %.5f (reference -1.41403), LDLJ %.5f (reference -5.81636)\n",
              s.value, l.value);
}

TEST(Smoothness, MinimumJerkSparcMatchesTheContinuousSpectrum) {
  const double T = 1.0;
  const double reference =
      sparcOfSpectrum(quadratureSpectrum([T](double t) { return minJerkSpeed(t, T); }, T));
  for (double fs : {100.0, 1000.0}) {
    const SmoothnessValue s =
        sparc(sample([T](double t) { return minJerkSpeed(t, T); }, 0, T, fs), fs);
    ASSERT_TRUE(s.ok());
    EXPECT_NEAR(s.value, reference, 0.01) << fs;
    std::printf("minimum jerk at %.0f Hz: SPARC %.4f, continuous-spectrum reference %.4f\n", fs,
                s.value, reference);
  }
  // Dimensionless: the same for another duration (the cut-off stays below 10 Hz).
  const SmoothnessValue slow =
      sparc(sample([](double t) { return 3.0 * minJerkSpeed(t, 2.5); }, 0, 2.5, 200.0), 200.0);
  EXPECT_NEAR(slow.value, reference, 0.01);
}

TEST(Smoothness, HalfSineSpeedMatchesTheClosedFormSpectrum) {
  // v(t) = sin(pi t / T) on [0, T]: |V(f)| / V(0) = |cos(pi f T)| / |1 - (2 f T)^2|.
  const double T = 0.8;
  const double reference = sparcOfSpectrum([T](double f) {
    const double x = 2 * f * T;
    if (std::abs(x - 1) < 1e-9) return kPi / 4;
    return std::abs(std::cos(kPi * f * T)) / std::abs(1 - x * x);
  });
  const double fs = 500.0;
  const SmoothnessValue s =
      sparc(sample([T](double t) { return std::sin(kPi * t / T); }, 0, T, fs), fs);
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s.value, reference, 0.01);
  std::printf("half-sine speed: SPARC %.4f, closed-form reference %.4f\n", s.value, reference);
}

TEST(Smoothness, MinimumJerkLdljMatchesTheAnalyticJerk) {
  // For a unit move over T: integral of jerk^2 = 720 / T^5 and v_peak = 1.875 / T, so
  // LDLJ = -ln(720 / 1.875^2) = -ln(204.8) whatever T. The implementation takes the duration as
  // N / fs (the authors' convention), one sample longer than T.
  const double T = 1.2, fs = 1000.0;
  const std::vector<double> v = sample([T](double t) { return minJerkSpeed(t, T); }, 0, T, fs);
  const SmoothnessValue l = ldljFromSpeed(v, fs);
  ASSERT_TRUE(l.ok());
  const double analytic = -std::log(720.0 / (1.875 * 1.875));
  const double withSampleDuration = analytic - 3 * std::log((v.size() / fs) / T);
  EXPECT_NEAR(l.value, withSampleDuration, 0.005);
  EXPECT_NEAR(l.value, analytic, 0.01);
  std::printf("minimum jerk: LDLJ %.4f, analytic %.4f\n", l.value, analytic);
}

// Two overlapping minimum-jerk sub-movements: the second starts before the first ends.
double twoSubmovements(double t) {
  return minJerkSpeed(t, 1.0) + 0.6 * minJerkSpeed(t - 0.55, 0.7);
}

TEST(Smoothness, SubmovementsAreLessSmooth) {
  const double fs = 200.0;
  const std::vector<double> one =
      sample([](double t) { return minJerkSpeed(t, 1.0); }, 0, 1.25, fs);
  const std::vector<double> two = sample(twoSubmovements, 0, 1.25, fs);
  const SmoothnessValue s1 = sparc(one, fs), s2 = sparc(two, fs);
  const SmoothnessValue l1 = ldljFromSpeed(one, fs), l2 = ldljFromSpeed(two, fs);
  ASSERT_TRUE(s1.ok() && s2.ok() && l1.ok() && l2.ok());
  EXPECT_LT(s2.value, s1.value - 0.1);
  EXPECT_LT(l2.value, l1.value - 0.2);
  std::printf("one reach: SPARC %.4f LDLJ %.4f; with a sub-movement: SPARC %.4f LDLJ %.4f\n",
              s1.value, l1.value, s2.value, l2.value);
}

// ---- From a path ------------------------------------------------------------------------------

/// A reach of 0.3 m along a fixed direction with jittered 100 Hz time stamps.
void reachPath(bool withSubmovement, std::vector<double>& t, Eigen::MatrixXd& p) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> jitter(-0.002, 0.002);
  const Eigen::Vector3d d1 = Eigen::Vector3d(0.3, 0.1, 0.2).normalized() * 0.3;
  const Eigen::Vector3d d2 = Eigen::Vector3d(-0.1, 0.2, 0.0).normalized() * 0.12;
  t.clear();
  for (int k = 0; k <= 150; ++k) t.push_back(k * 0.01 + (k > 0 && k < 150 ? jitter(rng) : 0.0));
  p.resize(static_cast<Eigen::Index>(t.size()), 3);
  for (std::size_t k = 0; k < t.size(); ++k) {
    Eigen::Vector3d x = Eigen::Vector3d(0.1, 0.2, -0.3) + d1 * minJerkPosition(t[k] - 0.1, 1.0);
    if (withSubmovement) x += d2 * minJerkPosition(t[k] - 0.7, 0.6);
    p.row(static_cast<Eigen::Index>(k)) = x.transpose();
  }
}

TEST(Smoothness, PathOfAMinimumJerkReach) {
  std::vector<double> t;
  Eigen::MatrixXd p;
  reachPath(false, t, p);
  const PathSmoothness s = pathSmoothness(t, p);
  ASSERT_TRUE(s.sparc.ok());
  ASSERT_TRUE(s.ldlj.ok());
  EXPECT_NEAR(s.sampleRateHz, 100.0, 1.0);
  EXPECT_NEAR(s.peakSpeedMPerS, 1.875 * 0.3, 0.01);
  // The speed profile alone, sampled the same way (with the rest before and after).
  const std::vector<double> v =
      sample([](double x) { return 0.3 * minJerkSpeed(x - 0.1, 1.0); }, 0, 1.5, 100.0);
  const SmoothnessValue ref = sparc(v, 100.0);
  EXPECT_NEAR(s.sparc.value, ref.value, 0.03);
  // LDLJ counts the whole window, rest included: the analytic value for a 1 s move, corrected
  // for the 1.5 s window (the duration enters cubed).
  EXPECT_NEAR(s.ldlj.value, -std::log(204.8) - 3 * std::log(1.5), 0.05);
  std::printf("reach path: SPARC %.4f (speed profile %.4f), LDLJ %.4f (analytic %.4f)\n",
              s.sparc.value, ref.value, s.ldlj.value, -std::log(204.8) - 3 * std::log(1.5));

  std::vector<double> t2;
  Eigen::MatrixXd p2;
  reachPath(true, t2, p2);
  const PathSmoothness s2 = pathSmoothness(t2, p2);
  ASSERT_TRUE(s2.sparc.ok() && s2.ldlj.ok());
  EXPECT_LT(s2.sparc.value, s.sparc.value - 0.1);
  EXPECT_LT(s2.ldlj.value, s.ldlj.value - 0.5);
  std::printf("reach path with a corrective sub-movement: SPARC %.4f, LDLJ %.4f\n", s2.sparc.value,
              s2.ldlj.value);
}

TEST(Smoothness, WristPathFollowsTheArmModel) {
  const ArmGeometry geo;
  const std::vector<ClinicalRow> rows{
      {0, 0, 0, 0, 0}, {kPi / 2, 0, 0, 0, 0}, {0, 0, 0, kPi / 2, 0}};
  const Eigen::MatrixXd w = wristPath(rows, geo);
  // Arm hanging: wrist straight down (x0) at l3 + l6; flexed 90 deg: forward (y0); elbow at 90:
  // forearm forward from the elbow.
  EXPECT_TRUE(w.row(0).isApprox(Eigen::RowVector3d(geo.l3 + geo.l6, 0, 0), 1e-12));
  EXPECT_NEAR(w(1, 1), geo.l3 + geo.l6, 1e-12);
  EXPECT_NEAR(w(2, 0), geo.l3, 1e-12);
  EXPECT_NEAR(w(2, 1), geo.l6, 1e-12);
  // Any posture: the same wrist as the DH chain of forwardKinematics().
  const ClinicalRow any{0.4, 0.3, -0.5, 1.1, 0.7};
  const Eigen::MatrixXd one = wristPath({any}, geo);
  EXPECT_TRUE(one.row(0).transpose().isApprox(forwardKinematics(geo, jointsFromClinical(any)).wrist,
                                              1e-12));
}

// ---- Hostile input ----------------------------------------------------------------------------

TEST(SmoothnessHostile, UndefinedCasesSayWhy) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(sparc({}, 100).status, SmoothnessStatus::TooShort);
  EXPECT_EQ(sparc({1.0}, 100).status, SmoothnessStatus::TooShort);
  EXPECT_EQ(ldljFromSpeed({1.0}, 100).status, SmoothnessStatus::TooShort);
  EXPECT_EQ(sparc({0, 1, nan, 1, 0}, 100).status, SmoothnessStatus::NonFinite);
  EXPECT_EQ(ldljFromSpeed({0, 1, nan, 1, 0}, 100).status, SmoothnessStatus::NonFinite);
  EXPECT_EQ(sparc({0, 1, 2, 1, 0}, 0).status, SmoothnessStatus::NonFinite);
  EXPECT_EQ(sparc({0, 1, 2, 1, 0}, nan).status, SmoothnessStatus::NonFinite);
  EXPECT_EQ(sparc(std::vector<double>(50, 0.0), 100).status, SmoothnessStatus::NoMovement);
  EXPECT_EQ(ldljFromSpeed(std::vector<double>(50, 0.0), 100).status, SmoothnessStatus::NoMovement);
  EXPECT_EQ(ldljFromSpeed(std::vector<double>(50, 0.2), 100).status, SmoothnessStatus::ZeroJerk);
  // Constant speed has a defined spectrum: SPARC is finite.
  const SmoothnessValue c = sparc(std::vector<double>(50, 0.2), 100);
  EXPECT_TRUE(c.ok());
  EXPECT_TRUE(std::isfinite(c.value));
  EXPECT_STREQ(toString(SmoothnessStatus::NoMovement), "no movement");
}

TEST(SmoothnessHostile, PathInputs) {
  std::vector<double> t{0.0, 0.01, 0.02, 0.03, 0.04};
  Eigen::MatrixXd still = Eigen::MatrixXd::Constant(5, 3, 0.4);
  const PathSmoothness s = pathSmoothness(t, still);
  EXPECT_EQ(s.sparc.status, SmoothnessStatus::NoMovement);
  EXPECT_EQ(s.ldlj.status, SmoothnessStatus::NoMovement);

  Eigen::MatrixXd withNan = still;
  withNan(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(pathSmoothness(t, withNan).sparc.status, SmoothnessStatus::NonFinite);

  EXPECT_EQ(pathSmoothness({0.0}, Eigen::MatrixXd::Zero(1, 3)).sparc.status,
            SmoothnessStatus::TooShort);
  EXPECT_EQ(pathSmoothness({}, Eigen::MatrixXd::Zero(0, 3)).ldlj.status,
            SmoothnessStatus::TooShort);

  std::vector<double> back = t;
  back[3] = 0.015;
  EXPECT_THROW(pathSmoothness(back, still), std::invalid_argument);
  EXPECT_THROW(pathSmoothness(t, Eigen::MatrixXd::Zero(4, 3)), std::invalid_argument);
}

}  // namespace
}  // namespace armtrack
