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
  std::vector<double> gyr;  ///< x,y,z per sample; NaN where the file had no finite number
  std::vector<double> acc;  ///< x,y,z per sample; NaN where the file had no finite number
  std::vector<int> line;    ///< line number of each sample in the file (1 = first line)
};

/// Reads the IMU CSV: a header line naming at least the seven columns (any order; other columns
/// are ignored), then one row per sample. Blank lines and lines starting with '#' are skipped.
/// Throws RecordingError ("file:line:column: message") for malformed input: missing columns,
/// cells that are not numbers, wrong field counts, a time that is not finite or goes backwards.
/// A sensor cell holding NaN, infinity or a number beyond the range of double reads as NaN: the
/// row stays (the filter rejects it and the command reports it).
ImuSeries readImuCsv(const std::filesystem::path& path);

/// armtrack-cli orientation IMU.csv [--out QUAT.csv] [options]. Throws UsageError for usage
/// mistakes and std::exception (RecordingError for malformed input) for runtime errors.
int orientationCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace armtrack::cli
