// The "calibrate" command of armtrack-cli: sensor-to-segment calibration from a recording of the
// calibration protocol (core/calibration/, docs/calibration.md), and the helper that applies a
// calibration file to a recording before "estimate".
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

#include "core/calibration/Calibration.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"

namespace armtrack::cli {

/// armtrack-cli calibrate REC.csv --out CALIB.json [options]. Writes the calibration, prints a
/// summary table to out and progress to err. Throws UsageError for usage mistakes (exit 2) and
/// std::exception (CalibrationError, RecordingError, std::invalid_argument) for input and runtime
/// errors (exit 1), like the other commands; runCli maps them.
int calibrateCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// Whether calibrate's arguments ask for the calibration from movement (--from-movement).
bool wantsMovementCalibration(const std::vector<std::string>& args);
/// armtrack-cli calibrate --from-movement REC.csv [--out CALIB.json] [--rest-pose start]
/// (app/cli/CalibrateMovement.cpp): prints the report, writes the calibration when --out is
/// given. Throws, as calibrateCommand, on a recording it cannot use (no rest, too little
/// movement, ...).
int calibrateFromMovementCommand(const std::vector<std::string>& args, std::ostream& out,
                                 std::ostream& err);

/// For "estimate --calibration CALIB.json": reads the file, checks that it is for the recording's
/// arm, corrects every IMU sample of rec and puts the calibrated geometry into rec.meta (so
/// filter parameters made from rec.meta afterwards use it). Writes one line to err saying what
/// was applied and, when the calibration's heading rested on the start pose alone, says so.
/// Throws CalibrationError (unreadable or malformed file) or std::runtime_error (wrong arm).
Calibration applyCalibrationFile(const std::filesystem::path& path, Recording& rec,
                                 std::ostream& err);

/// The same for a recording read row by row: reads the file, checks the side against meta, puts
/// the calibrated geometry into meta and writes the same lines to err; the caller corrects each
/// sample (applyCalibration(c, sample)).
Calibration loadCalibrationFor(const std::filesystem::path& path, RecordingMeta& meta,
                               std::ostream& err);
/// The same with the file already read (c, from path): for a batch of recordings.
void useCalibration(const Calibration& c, const std::filesystem::path& path, RecordingMeta& meta,
                    std::ostream& err);

/// The same for filter parameters already made: sets params.geometry (checks the side).
void applyCalibrationToParams(const Calibration& calibration, EstimatorParams& params);

}  // namespace armtrack::cli
