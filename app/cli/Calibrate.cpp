#include "app/cli/Calibrate.h"

#include <stdlib.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "app/cli/Args.h"
#include "app/cli/CsvOutput.h"
#include "app/cli/Text.h"
#include "core/calibration/Calibrator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kCalibrateHelp =
    R"(Usage: armtrack-cli calibrate REC.csv --out CALIB.json [options]
       armtrack-cli calibrate --from-movement REC.csv [--out CALIB.json] (see --from-movement --help)

Estimates the sensor-to-segment calibration from a recording of the calibration protocol
(docs/calibration.md): the IMU strap distances and angles (lu3, lu5, thu4, lf6, lf8, thf7), a
small residual rotation of each IMU, a constant gyroscope bias per IMU and, with optical data,
the segment lengths l3 and l6. Batch nonlinear least squares over the whole recording on the
filter's measurement model. The recording must start with the protocol's start pose held still
(upper arm hanging, elbow at 90 deg, forearm forward, thumb up). Without optical data the arm's
heading about the vertical rests on that start pose alone; the tool says so.
Use the result with: armtrack-cli estimate REC2.csv --calibration CALIB.json

Options:
  --out FILE           the calibration to write (JSON, required)
  --no-kinect          ignore the optical elbow/wrist positions
  --knot-spacing S     spline knot spacing of the joint trajectory, s (default 0.04)
  --rate HZ            IMU readings are averaged into bins at this rate (default 100)
  --still S            seconds of still start pose at the beginning (default 2)
  --threads N          solver threads (default 2)
)";

std::string deg(double rad, int decimals = 2) {
  return fixed(rad / kDeg, decimals);
}
std::string mm(double m) {
  return fixed(m * 1000.0, 1);
}

double rotationDeg(const Eigen::Matrix3d& r) {
  return Eigen::AngleAxisd(r).angle() / kDeg;
}

/// Refuses an output that could not be written, before the solve (tens of seconds): a directory
/// or a missing folder (checkOutputPath; whether an existing file may be replaced is the
/// dispatcher's --overwrite check) and a folder in which no file can be created (read-only,
/// no permission), found by creating and removing a probe file there as the writer will.
void checkWritable(const fs::path& target) {
  checkOutputPath(target, /*overwrite=*/true);
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::string probe = (folder / ".armtrack-calibrate-probe-XXXXXX").string();
  errno = 0;
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) {
    const int e = errno;
    throw std::runtime_error(target.string() + ": cannot write the calibration there (" +
                             std::strerror(e) + "); choose another --out");
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

}  // namespace

int calibrateCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (wantsMovementCalibration(args)) return calibrateFromMovementCommand(args, out, err);
  const Args a("calibrate", args,
               {{"--out", true},
                {"--no-kinect", false},
                {"--knot-spacing", true},
                {"--rate", true},
                {"--still", true},
                {"--threads", true}});
  if (a.help()) {
    out << kCalibrateHelp;
    return 0;
  }
  const fs::path input = a.single("the recording to read (calibrate REC.csv)");
  const fs::path outPath = a.required("--out");
  if (samePath(outPath, input) || samePath(outPath, sidecarPath(input)))
    a.fail("--out: " + inQuotes(outPath.string()) + " would overwrite the recording");

  CalibrationOptions opt;
  opt.useOptical = !a.flag("--no-kinect");
  opt.knotSpacing = a.positive("--knot-spacing", opt.knotSpacing);
  if (opt.knotSpacing > 0.5)
    a.fail("--knot-spacing: at most 0.5 s, got " + shortest(opt.knotSpacing));
  opt.residualRateHz = a.positive("--rate", opt.residualRateHz);
  opt.startStillSeconds = a.positive("--still", opt.startStillSeconds);
  const std::uint64_t threads = a.integer("--threads", 2);
  if (threads < 1 || threads > 64) a.fail("--threads: must be between 1 and 64");
  opt.threads = static_cast<int>(threads);

  std::error_code ec;
  if (!fs::exists(input, ec)) throw std::runtime_error(input.string() + ": no such file");
  checkWritable(outPath);
  const Recording rec = readRecording(input);
  for (const std::string& w : rec.warnings) err << "warning: " << w << "\n";
  CalibrationResult r;
  try {
    r = calibrate(rec, opt, [&](const std::string& line) { err << line << "\n"; });
  } catch (const std::exception& e) {  // unusable recording, failed solve, impossible result
    throw std::runtime_error(input.string() + ": " + e.what());
  }
  for (const std::string& w : r.warnings) err << "warning: " << w << "\n";
  // A short recording may lack the movements that separate some parameters (measured: a 10 s
  // start of the protocol without optical data left 2.9 deg on the elbow, the whole 57 s 0.3).
  const double protocol = CalibrationProtocolTrajectory().duration();
  const double covered = rec.samples.empty() ? 0.0 : rec.samples.back().t - rec.samples.front().t;
  if (covered < 0.9 * protocol) {
    err << "warning: the recording covers " << fixed(covered, 1) << " s; the protocol takes "
        << fixed(protocol, 0) << " s (docs/calibration.md). Parameters the missing movements "
        << "would excite may be poorly determined: record the whole protocol.\n";
  }
  writeCalibration(outPath, r.calibration);

  const Calibration& c = r.calibration;
  const ArmGeometry& g0 = rec.meta.geometry;
  const ArmGeometry& g = c.geometry;
  out << "# Calibration (" << sideName(c.side) << " arm, "
      << (c.opticalUsed ? "with optical positions" : "IMU only") << ")\n\n"
      << "| parameter | sidecar | calibrated | from |\n|---|---|---|---|\n";
  const auto row = [&](const std::string& name, const std::string& before, const std::string& after,
                       const std::string& from) {
    out << "| " << name << " | " << before << " | " << after << " | " << from << " |\n";
  };
  const std::string data = "data";
  const std::string lengths = c.opticalUsed ? data : "held (needs optical data)";
  row("l3 upper arm (mm)", mm(g0.l3), mm(g.l3), lengths);
  row("l6 forearm (mm)", mm(g0.l6), mm(g.l6), lengths);
  row("lu3 upper-arm strap distance (mm)", mm(g0.lu3), mm(g.lu3), data);
  row("lu5 upper-arm strap radius (mm)", mm(g0.lu5), mm(g.lu5), data);
  row("thu4 upper-arm strap angle (deg)", deg(g0.thu4), deg(g.thu4), data);
  row("lf6 forearm strap distance (mm)", mm(g0.lf6), mm(g.lf6), data);
  row("lf8 forearm strap radius (mm)", mm(g0.lf8), mm(g.lf8), data);
  row("thf7 forearm strap angle (deg)", deg(g0.thf7), deg(g.thf7), "start pose (th5 = 0)");
  row("upper-arm IMU tilt (deg)", "0", fixed(rotationDeg(c.upperArm.rotation), 2), data);
  row("forearm IMU tilt (deg)", "0", fixed(rotationDeg(c.forearm.rotation), 2), data);
  const auto bias = [](const Eigen::Vector3d& b) {
    return "[" + deg(b.x(), 3) + " " + deg(b.y(), 3) + " " + deg(b.z(), 3) + "]";
  };
  row("upper-arm gyro bias (deg/s)", "0", bias(c.upperArm.gyroBias), data);
  row("forearm gyro bias (deg/s)", "0", bias(c.forearm.gyroBias), data);
  out << "\nResiduals (RMS, in noise standard deviations; about 1 is a good fit): upper-arm gyro "
      << fixed(r.rmsUpperGyro, 2) << ", accelerometer " << fixed(r.rmsUpperAcc, 2)
      << "; forearm gyro " << fixed(r.rmsForearmGyro, 2) << ", accelerometer "
      << fixed(r.rmsForearmAcc, 2);
  if (c.opticalUsed) out << "; optical positions " << fixed(r.rmsPosition, 2);
  out << ".\n";
  if (c.headingFromStartPoseOnly) {
    out << "\nNo optical data: the arm's heading about the vertical rests on the start-pose "
           "assumption alone (as does pronation, always).\n";
  }
  err << "calibrate: wrote " << outPath.string() << " (" << r.iterations << " iterations, "
      << fixed(r.seconds, 1) << " s)\n";
  return 0;
}

Calibration loadCalibrationFor(const fs::path& path, RecordingMeta& meta, std::ostream& err) {
  Calibration c = readCalibration(path);
  useCalibration(c, path, meta, err);
  return c;
}

void useCalibration(const Calibration& c, const fs::path& path, RecordingMeta& meta,
                    std::ostream& err) {
  if (c.side != meta.side) {
    throw std::runtime_error(path.string() + ": the calibration is for the " + sideName(c.side) +
                             " arm but the recording is of the " + sideName(meta.side) + " arm");
  }
  meta.geometry = c.geometry;
  err << "calibration: applied " << path.string() << " (" << sideName(c.side) << " arm, "
      << (c.opticalUsed ? "made with optical data" : "made without optical data") << ")\n";
  if (c.headingFromStartPoseOnly) {
    err << "calibration: its heading about the vertical rested on the start-pose assumption "
           "alone\n";
  }
}

Calibration applyCalibrationFile(const fs::path& path, Recording& rec, std::ostream& err) {
  const Calibration c = loadCalibrationFor(path, rec.meta, err);
  for (ArmSample& s : rec.samples) applyCalibration(c, s);
  return c;
}

void applyCalibrationToParams(const Calibration& calibration, EstimatorParams& params) {
  applyCalibration(calibration, params);
}

}  // namespace armtrack::cli
