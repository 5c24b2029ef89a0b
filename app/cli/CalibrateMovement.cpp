// "armtrack-cli calibrate --from-movement REC.csv [--out CALIB.json]": the calibration from
// ordinary movement (core/calibration/MovementCalibration.h, docs/calibration.md).
#include <algorithm>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "app/cli/Args.h"
#include "app/cli/Calibrate.h"
#include "app/cli/Text.h"
#include "core/calibration/MovementCalibration.h"

namespace armtrack::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kHelp =
    R"(Usage: armtrack-cli calibrate --from-movement REC.csv [--out CALIB.json] [options]

Estimates each arm IMU's strap rotation, lever arm and gyroscope bias from 20-60 s of ordinary
arm movement that includes a moment of rest (the arm still for at least 0.5 s); no protocol
(docs/calibration.md, "Calibration from movement"). Prints a plain-language report, with a
standard deviation per parameter and what the movement did not excite (left at the sidecar's
values). Refuses a recording with no rest or too little movement.

Options:
  --out FILE         write the calibration (the same file format as the protocol's)
  --rest-pose start  the rest was the protocol's start pose (upper arm hanging, elbow at 90 deg,
                     thumb up): fixes the upper arm's inclination and the forearm sensor's roll
)";

}  // namespace

bool wantsMovementCalibration(const std::vector<std::string>& args) {
  return std::find(args.begin(), args.end(), "--from-movement") != args.end();
}

int calibrateFromMovementCommand(const std::vector<std::string>& args, std::ostream& out,
                                 std::ostream& err) {
  const Args a("calibrate", args,
               {{"--from-movement", true}, {"--out", true}, {"--rest-pose", true}});
  if (a.help()) {
    out << kHelp;
    return 0;
  }
  if (!a.positionals().empty()) a.fail("unexpected argument '" + a.positionals().front() + "'");
  const fs::path input = a.required("--from-movement");
  MovementCalibrationParams p;
  if (const auto pose = a.value("--rest-pose")) {
    if (*pose != "start")
      a.fail("--rest-pose: the only known pose is \"start\", got \"" + *pose + "\"");
    p.restPose = protocolStartPose();
  }
  std::optional<fs::path> outPath;
  if (const auto o = a.value("--out")) {
    outPath = *o;
    if (samePath(*outPath, input) || samePath(*outPath, sidecarPath(input)))
      a.fail("--out: \"" + outPath->string() + "\" would overwrite the recording");
  }
  std::error_code ec;
  if (!fs::exists(input, ec)) throw std::runtime_error(input.string() + ": no such file");
  const Recording rec = readRecording(input);
  for (const std::string& w : rec.warnings) err << "warning: " << w << "\n";
  MovementCalibration m;
  try {
    m = calibrateFromMovement(rec, p);
  } catch (const std::exception& e) {
    throw std::runtime_error(input.string() + ": " + e.what());
  }
  out << formatMovementReport(m);
  if (outPath) {
    writeCalibration(*outPath, m.calibration);
    err << "calibrate: wrote " << outPath->string() << "\n";
  }
  return 0;
}

}  // namespace armtrack::cli
