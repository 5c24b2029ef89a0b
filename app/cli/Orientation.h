// The "orientation" command of armtrack-cli: 6D orientation of one IMU from a CSV of gyroscope
// and accelerometer samples (core/orientation/OrientationFilter.h, docs/orientation.md).
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace armtrack::cli {

/// One IMU's samples as read from "t,gyr_x,gyr_y,gyr_z,acc_x,acc_y,acc_z" (s, rad/s, m/s^2).
struct ImuSeries {
  std::vector<double> t;    ///< s, never decreasing
  std::vector<double> gyr;  ///< x,y,z per sample
  std::vector<double> acc;  ///< x,y,z per sample
};

/// Reads the IMU CSV: a header line naming at least the seven columns (any order; other columns
/// are ignored), then one row per sample. Blank lines and lines starting with '#' are skipped.
/// Throws RecordingError ("file:line:column: message") for malformed input: missing columns,
/// bad or non-finite numbers, wrong field counts, time going backwards.
ImuSeries readImuCsv(const std::filesystem::path& path);

/// armtrack-cli orientation IMU.csv [--out QUAT.csv] [options]. Throws UsageError for usage
/// mistakes and std::exception (RecordingError for malformed input) for runtime errors.
int orientationCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace armtrack::cli
