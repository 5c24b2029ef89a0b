// Internals of the calibration from movement: each IMU's readings on a uniform grid (repeats,
// non-finite and saturated readings left out) and the rest found in them
// (core/calibration/MovementReadings.cpp; docs/calibration.md, "Calibration from movement").
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/ArmSample.h"
#include "core/calibration/MovementCalibration.h"

namespace armtrack::movecal {

using Vec3 = Eigen::Vector3d;

inline constexpr double kGridDt = 0.02;     ///< s, the uniform grid
inline constexpr double kHalfWidth = 0.06;  ///< s, the triangular smoother's half width

struct Channel {
  std::vector<double> t;
  std::vector<Vec3> v;
};

/// One IMU's fresh readings (repeats of the previous value, non-finite and saturated ones left
/// out), per channel.
struct ImuChannels {
  Channel gyr, acc;
  std::size_t nonFinite = 0, saturated = 0, rows = 0;
};

/// The readings at a channel's range: the largest |component| reached in at least 3 separate runs
/// or held for 8 rows in a row. Marks them.
std::vector<char> saturatedRows(const std::vector<Vec3>& v);
ImuChannels channels(const std::vector<ArmSample>& samples, bool forearm);
/// The channel at time t: a triangular-weighted mean of the readings within kHalfWidth, or the
/// linear interpolation of the nearest two when none is that close.
Vec3 smoothAt(const Channel& c, double t);

/// Both IMUs on the grid; wd: angular accelerations (central differences).
struct Grid {
  std::vector<double> t;
  std::vector<Vec3> w1, a1, w2, a2, wd1, wd2;
};
Grid makeGrid(const ImuChannels& u, const ImuChannels& f);
void differentiate(Grid& g);

struct Rest {
  std::size_t from = 0, to = 0;  ///< grid indices, [from, to)
};
/// Every stretch in which each minRestSeconds window is still for both IMUs, in time order.
std::vector<Rest> findRests(const Grid& g, const MovementCalibrationParams& p, double gravity);
/// The longest of them.
std::optional<Rest> findRest(const Grid& g, const MovementCalibrationParams& p, double gravity);
Vec3 meanOf(const std::vector<Vec3>& v, const Rest& r);

/// One decimal.
std::string fixed1(double v);

}  // namespace armtrack::movecal
