// A gyroscope's bias from the moments its sensor is still. MEMS gyroscopes read a few deg/s at
// rest (datasheets: +-3 to +-5 deg/s at switch-on, drifting with temperature); integrated, that
// turns the unobservable heading and leaks into every joint. When a sensor is still for a whole
// window its mean rate is its bias; each new still window refines it, so a bias that walks or
// warms is followed. See docs/estimator.md, "Gyroscope bias at rest".
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>

#include "core/ArmSample.h"

namespace armtrack {

struct RestBiasParams {
  /// Length of a still window (s). Shorter windows follow a drifting bias sooner but average
  /// less noise; 1 s averages a Table 5 gyroscope (0.0055 rad/s) to 0.02 deg/s at 200 Hz.
  double windowSeconds = 1.0;
  /// Still: every axis's rate varies less than this over the window (rad/s, standard
  /// deviation). 0.02 rad/s (1.1 deg/s) is four times the Table 5 noise and above a resting
  /// arm's tremor; a moving arm exceeds it within a fraction of a second.
  double maxGyroStd = 0.02;
  /// ... and the mean specific force of the window's two halves differ by less than this
  /// (m/s^2): a slow steady turn tilts gravity (0.15 m/s^2 is 0.9 deg in half a window).
  double maxAccelChange = 0.15;
  /// A mean rate above this (rad/s, any axis) is motion, not bias: 0.1 rad/s (5.7 deg/s) is
  /// beyond every datasheet's zero-rate output.
  double maxBias = 0.1;
  /// Weight of a new still window against the bias so far (the first window sets it).
  double gain = 0.5;
  /// Fewest fresh gyroscope values a window needs.
  int minSamples = 20;
};

/// One IMU's gyroscope bias. Feed it the sensor's readings in time order (held values are
/// skipped); bias() is the estimate so far (zero until a still window was seen).
class RestBias {
 public:
  explicit RestBias(const RestBiasParams& p = {}) : m_p(p) {}
  void add(double t, const ImuReading& r);
  const Eigen::Vector3d& bias() const { return m_bias; }
  /// Still windows taken so far.
  std::uint64_t windows() const { return m_windows; }
  void reset();

 private:
  void startWindow(double t);
  void closeWindow();

  RestBiasParams m_p;
  Eigen::Vector3d m_bias = Eigen::Vector3d::Zero();
  std::uint64_t m_windows = 0;
  bool m_open = false;
  double m_start = 0.0;
  double m_lastT = -std::numeric_limits<double>::infinity();
  int m_nGyr = 0;
  Eigen::Vector3d m_sumGyr = Eigen::Vector3d::Zero(), m_sumGyr2 = Eigen::Vector3d::Zero();
  int m_nAcc[2] = {0, 0};
  Eigen::Vector3d m_sumAcc[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
};

}  // namespace armtrack
