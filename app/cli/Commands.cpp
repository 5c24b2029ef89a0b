// Command dispatch and the simulate / estimate / study commands of armtrack-cli.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <exception>
#include <filesystem>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "app/cli/Args.h"
#include "app/cli/Baseline.h"
#include "app/cli/Calibrate.h"
#include "app/cli/Camera.h"
#include "app/cli/Cli.h"
#include "app/cli/Clinical.h"
#include "app/cli/ClinicalContext.h"
#include "app/cli/CsvOutput.h"
#include "app/cli/Estimate.h"
#include "app/cli/Live.h"
#include "app/cli/Orientation.h"
#include "app/cli/SimulateTrunk.h"
#include "app/cli/Text.h"
#include "core/camera/PinholeCamera.h"
#include "core/io/Recording.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"
#include "core/studies/Studies.h"

#ifndef ARMTRACK_VERSION
#define ARMTRACK_VERSION "0.0.0"
#endif

namespace armtrack::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kMainHelp =
    R"(armtrack-cli: shoulder and elbow joint angles from two IMUs and a Kinect.

Usage:
  armtrack-cli <command> [options]
  armtrack-cli <command> --help
  armtrack-cli --help | --version

Commands:
  simulate   write a simulated recording with the true joint angles
  estimate   estimate joint angles from a recording (EKF or UKF)
  baseline   elbow angles and humerus elevation by a plain complementary filter (docs/baseline.md)
  calibrate  sensor-to-segment calibration from a protocol recording (docs/calibration.md)
  study      simulation studies: the paper's Table 6 and Figs. 5, 7, 8; the sensor study; the
             baseline beside the DH filter
  orientation  orientation of one IMU (gyroscope + accelerometer) as quaternions
  devices    list the device plugins and their options
  record     record a live session from devices (with the live estimates)
  live       run a live session; --stats prints rates, losses and latency
  camera-calibrate  camera intrinsics from chessboard images (docs/devices/webcam.md)
  camera-register   camera pose in the shoulder frame from an ArUco board image
  db         create, check, migrate or back up the clinical records (docs/storage.md)
  user       add or list accounts (administrators)
  patient    add or list patients
  protocol   add or list exercise protocols
  programme  a patient's home programme: exercises, sets, repetitions, targets, rest
  device     enrolment codes for home devices that sync with armtrack-server; list, revoke
  session    import a recording into the records (estimated and measured), list, show or
             re-estimate sessions
  export     write a stored session as a recording, clinical CSV, OpenSim .mot or BIDS motion
  report     a session's PDF report, or a patient's progress over a date range
  audit      who viewed, changed or exported what (administrators)

Exit status: 0 success, 1 runtime or input error, 2 usage error.
See docs/cli.md for details.
)";

constexpr std::string_view kSimulateHelp =
    R"(Usage: armtrack-cli simulate --trajectory NAME --out REC.csv [options]

Simulates both IMUs and the Kinect along a joint trajectory and writes a recording (REC.csv plus
the sidecar REC.json) that includes the true joint angles (and, with a moving trunk or a sternum
IMU, the true trunk angles).

Options:
  --trajectory NAME    sinusoid, multi-joint, shoulder-wheel, calibration, reaching or session
                       (reaches from a resting hand and back, resting 1-3 s between them, after
                       3 s still at the start) (required)
  --out FILE           the recording to write (required)
  --overwrite          replace FILE and its sidecar if they exist (otherwise an error)
  --duration S         length in s (default 10; calibration: the whole protocol, 54 s)
  --seed N             seed for the trajectory, noise and misalignment (default 1)
  --imu-rate HZ        rate of both IMUs (default 1000)
  --kinect-rate HZ     Kinect rate (default 30)
  --kinect-noise M     Kinect position noise std per axis, m (default 0.01)
  --no-kinect          no Kinect rows
  --webcam             add webcam pixels of the wrist and elbow markers (camera block in the
                       sidecar; 640x480, fx = fy = 600, mild barrel distortion)
  --webcam-rate HZ     webcam frame rate (default 30)
  --webcam-noise PX    marker pixel noise std (default 1)
  --webcam-outliers P  probability a marker is mis-detected anywhere in the image (default 0)
  --camera-distance M  camera distance in front of the shoulder, looking back (default 2)
  --side right|left    which arm (default right; a left arm is the right one mirrored)
  --gyro-noise RAD_S   gyroscope noise std, rad/s (default Table 5: sqrt(0.1) deg/s)
  --accel-noise M_S2   accelerometer noise std, m/s^2 (default Table 5: 0.1)
  --gyro-bias RAD_S    constant gyroscope bias on every axis of every IMU (default 0)
  --misalignment DEG   IMU mounting error: rotation by DEG about a random axis per IMU (default 0)
  --sensors MODEL      ideal (default: noise and bias only) or realistic: each IMU gets a real
                       MEMS part's errors drawn from the seed (scale, cross-axis, walking and
                       warming bias, g-sensitivity, 50 Hz gyroscope and 25 Hz accelerometer held
                       on a 90 Hz clock unless --imu-rate is given, jitter, clock offset, range,
                       LSB, strap wobble and slip; docs/simulation.md)
  --amplitude DEG      sinusoid: amplitude of every joint (default 28.6, i.e. 0.5 rad)
  --frequency HZ       sinusoid: frequency of every joint (default 0.5)
  --wheel-period S     shoulder-wheel: seconds per turn (default 4)
  --peak-rate DEG_S    reaching, session: fastest joint rate of a move (default 420)
  --peak-accel DEG_S2  reaching, session: fastest joint acceleration of a move (default 4000)
  --pendulum           a double pendulum instead of an arm (simulate --pendulum --help)
)";

constexpr std::string_view kStudyHelp =
    R"(Usage: armtrack-cli study table6|fig5|fig7|fig8|sensors [options]

Runs a simulation study and prints its table (markdown).
  table6   body-acceleration compensation: Methods A, B, C (the paper's Table 6)
  fig5     error against motion frequency per measurement model, EKF and UKF
  fig7     IMU perturbations against the accuracy of the position measurements, 1 mm to 1 m
  fig8     perturbation error against motion frequency, with and without Kinect positions
  sensors  five joints from IMUs only, + Kinect, + webcam, + both, and the Tao-Hu tracker
  baseline the DH filter and the complementary baseline on the same recordings
           (study baseline --help)

Options:
  --runs N          Monte Carlo runs per setting (default 10; sensors: 3)
  --filter ekf|ukf  filter for table6, fig7 and fig8 (default ekf; fig5 runs both, sensors EKF)
  --duration S      seconds per run, the first second is start-up (default 10; fig7 and
                    sensors: 30, fig7 measures the steady state over the second half)
)";

void noPositionals(const Args& a) {
  if (!a.positionals().empty()) a.fail("unexpected argument " + inQuotes(a.positionals()[0]));
}

// ---------------------------------------------------------------------------------------------

int simulate(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (std::find(args.begin(), args.end(), "--pendulum") != args.end())
    return simulatePendulumCommand(args, out, err);
  std::vector<OptionSpec> specs = {{"--trajectory", true},      {"--out", true},
                                   {"--duration", true},        {"--seed", true},
                                   {"--imu-rate", true},        {"--kinect-rate", true},
                                   {"--kinect-noise", true},    {"--no-kinect", false},
                                   {"--webcam", false},         {"--webcam-rate", true},
                                   {"--webcam-noise", true},    {"--webcam-outliers", true},
                                   {"--camera-distance", true}, {"--side", true},
                                   {"--gyro-noise", true},      {"--accel-noise", true},
                                   {"--gyro-bias", true},       {"--misalignment", true},
                                   {"--amplitude", true},       {"--frequency", true},
                                   {"--wheel-period", true},    {"--peak-rate", true},
                                   {"--peak-accel", true},      {"--overwrite", false},
                                   {"--sensors", true}};
  for (const OptionSpec& o : trunkOptionSpecs()) specs.push_back(o);
  const Args a("simulate", args, specs);
  if (a.help()) {
    out << kSimulateHelp << kTrunkOptionsHelp;
    return 0;
  }
  noPositionals(a);
  const std::string name = a.required("--trajectory");
  const fs::path outPath = a.required("--out");
  checkOutputPath(outPath, a.flag("--overwrite"), true);

  SimulationParams sim = defaultSimulation();
  // The calibration protocol has its own length; everything else defaults to 10 s.
  sim.duration = a.positive(
      "--duration",
      name == "calibration" ? std::ceil(CalibrationProtocolTrajectory().duration()) : 10.0);
  sim.seed = a.integer("--seed", 1);
  const double imuRate = a.positive("--imu-rate", 1000.0);
  const double gyroNoise = a.nonNegative("--gyro-noise", Table5::gyroStd());
  const double accelNoise = a.nonNegative("--accel-noise", Table5::accelStd());
  const double gyroBias = a.number("--gyro-bias", 0.0);
  const double misalignDeg = a.number("--misalignment", 0.0);
  for (ImuSimParams* imu : {&sim.upperArm, &sim.forearm}) {
    imu->rateHz = imuRate;
    imu->gyroNoiseStd = gyroNoise;
    imu->accelNoiseStd = accelNoise;
    imu->gyroBias = Eigen::Vector3d::Constant(gyroBias);
  }
  if (misalignDeg != 0.0) {
    // Separate seeds per IMU so the two axes differ.
    sim.upperArm.misalignment = randomMisalignment(misalignDeg * kDeg, 2 * sim.seed + 1);
    sim.forearm.misalignment = randomMisalignment(misalignDeg * kDeg, 2 * sim.seed + 2);
  }
  sim.kinect.enabled = !a.flag("--no-kinect");
  applyTrunkOptions(a, sim, misalignDeg, err);
  // After the trunk options, so that the sternum IMU draws its own errors.
  try {
    applySensorModel(parseSensorModel(a.value("--sensors").value_or("ideal")), sim,
                     a.flag("--imu-rate") ? std::optional<double>(imuRate) : std::nullopt);
  } catch (const std::invalid_argument& e) {
    a.fail(std::string("--sensors: ") + e.what());
  }
  if (const auto side = a.value("--side")) {
    try {
      sim.side = parseSide(*side);
    } catch (const std::invalid_argument& e) {
      a.fail(std::string("--side: ") + e.what());
    }
  }
  sim.kinect.rateHz = a.positive("--kinect-rate", 30.0);
  sim.kinect.noiseStd = a.nonNegative("--kinect-noise", Table5::posStd());
  sim.webcam.enabled = a.flag("--webcam");
  sim.webcam.rateHz = a.positive("--webcam-rate", 30.0);
  sim.webcam.noiseStdPx = a.nonNegative("--webcam-noise", 1.0);
  sim.webcam.outlierProbability = a.nonNegative("--webcam-outliers", 0.0);
  if (sim.webcam.outlierProbability > 1.0) a.fail("--webcam-outliers: expected a probability");
  sim.webcam.camera = frontCamera(a.positive("--camera-distance", 2.0));
  for (std::string_view o :
       {"--webcam-rate", "--webcam-noise", "--webcam-outliers", "--camera-distance"}) {
    if (a.flag(o) && !sim.webcam.enabled)
      err << "warning: " << o << " only applies with --webcam; ignored\n";
  }

  TrajectoryOptions traj;
  traj.seed = sim.seed;
  traj.geometry = sim.geometry;
  if (const auto amp = a.number("--amplitude")) traj.amplitude.setConstant(*amp * kDeg);
  traj.frequency.setConstant(a.nonNegative("--frequency", traj.frequency(0)));
  traj.wheelPeriod = a.positive("--wheel-period", traj.wheelPeriod);
  traj.peakRate = a.positive("--peak-rate", traj.peakRate / kDeg) * kDeg;
  traj.peakAccel = a.positive("--peak-accel", traj.peakAccel / kDeg) * kDeg;
  traj.duration = sim.duration;
  const auto ignoredFor = [&](std::string_view option, std::string_view trajectory) {
    if (a.flag(option) && name != trajectory) {
      err << "warning: " << option << " only applies to the " << trajectory
          << " trajectory; ignored\n";
    }
  };
  ignoredFor("--amplitude", "sinusoid");
  ignoredFor("--frequency", "sinusoid");
  ignoredFor("--wheel-period", "shoulder-wheel");
  for (std::string_view o : {"--peak-rate", "--peak-accel"}) {
    if (a.flag(o) && name != "reaching" && name != "session")
      err << "warning: " << o
          << " only applies to the reaching and session trajectories; ignored\n";
  }

  std::unique_ptr<Trajectory> trajectory;
  try {
    trajectory = makeTrajectory(name, traj);
  } catch (const std::invalid_argument& e) {
    a.fail(std::string("--trajectory: ") + e.what());
  }
  const Recording rec = simulateRecording(*trajectory, sim);
  writeRecording(outPath, rec);
  err << "simulate: wrote " << rec.samples.size() << " rows (" << shortest(sim.duration) << " s of "
      << name << ") to " << outPath.string() << " and " << sidecarPath(outPath).string() << "\n";
  return 0;
}

// ---------------------------------------------------------------------------------------------

int study(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (!args.empty() && args[0] == "baseline")
    return baselineStudyCommand({args.begin() + 1, args.end()}, out, err);
  const Args a("study", args, {{"--runs", true}, {"--filter", true}, {"--duration", true}});
  if (a.help()) {
    out << kStudyHelp;
    return 0;
  }
  constexpr std::string_view kStudies = "table6, fig5, fig7, fig8 or sensors";
  const std::string which = a.single("the study to run: " + std::string(kStudies));
  if (which != "table6" && which != "fig5" && which != "fig7" && which != "fig8" &&
      which != "sensors")
    a.fail("unknown study " + inQuotes(which) + ": expected " + std::string(kStudies));

  const bool sensors = which == "sensors";
  StudySetup setup;
  const std::uint64_t runs = a.integer("--runs", sensors ? 3 : 10);
  if (runs < 1 || runs > 100000) a.fail("--runs: must be between 1 and 100000");
  setup.runs = static_cast<int>(runs);
  setup.filter = parseFilter(a);
  setup.duration = a.number("--duration", sensors || which == "fig7" ? 30.0 : 10.0);
  if (!(setup.duration > 1.0))
    a.fail("--duration: must be > 1 (the first second is start-up), got " +
           shortest(setup.duration));

  if (which == "fig5" && a.flag("--filter"))
    err << "warning: --filter is ignored by fig5, which runs both EKF and UKF\n";
  if (sensors && a.flag("--filter"))
    err << "warning: --filter is ignored by sensors, which runs the EKF and Tao-Hu\n";
  int lastTenth = 0;
  const StudyProgress progress = [&](int done, int total) {
    if (total <= 0) return;
    const int tenth = static_cast<int>(10LL * done / total);
    if (tenth == lastTenth) return;
    lastTenth = tenth;
    err << "progress: " << 10 * tenth << "% (" << done << "/" << total << " runs)\n";
  };
  if (which == "table6") {
    out << formatTable6(runTable6(setup, progress), setup);
  } else if (which == "fig5") {
    out << formatFig5(runFig5(setup, progress), setup);
  } else if (which == "fig7") {
    out << formatFig7(runFig7(setup, progress), setup);
  } else if (which == "fig8") {
    out << formatFig8(runFig8(setup, progress), setup);
  } else {
    out << formatSensors(runSensors(setup, progress), setup);
  }
  return 0;
}

}  // namespace

namespace {

constexpr std::string_view kError = "armtrack-cli: error: ";

/// calibrate's own options do not know --overwrite (docs/cli.md): the check is made here.
int calibrateWithOutputCheck(std::vector<std::string> args, std::ostream& out, std::ostream& err) {
  const bool overwrite = takeOverwriteFlag(args);
  const bool help = std::find_if(args.begin(), args.end(), [](const std::string& a) {
                      return a == "--help" || a == "-h";
                    }) != args.end();
  if (!help) {
    if (const auto target = rawOptionValue(args, "--out"); target && !target->empty())
      checkOutputPath(*target, overwrite);
  }
  const int code = calibrateCommand(args, out, err);
  if (help)
    out << "  --overwrite          replace the --out file if it exists (otherwise an error)\n";
  return code;
}

int dispatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  try {
    if (args.empty()) throw UsageError("", "missing command");
    const std::string& cmd = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (cmd == "--help" || cmd == "-h" || cmd == "help") {
      out << kMainHelp;
      return 0;
    }
    if (cmd == "--version") {
      out << "armtrack-cli " << ARMTRACK_VERSION << "\n";
      return 0;
    }
    if (cmd == "simulate") return simulate(rest, out, err);
    if (cmd == "estimate") return estimateCommand(rest, out, err);
    if (cmd == "baseline") return baselineCommand(rest, out, err);
    if (cmd == "study") return study(rest, out, err);
    if (cmd == "calibrate") return calibrateWithOutputCheck(rest, out, err);
    if (cmd == "orientation") return orientationCommand(rest, out, err);
    if (cmd == "devices") return devicesCommand(rest, out, err);
    if (cmd == "record") return recordCommand(rest, out, err);
    if (cmd == "live") return liveCommand(rest, out, err);
    if (cmd == "camera-calibrate") return cameraCalibrateCommand(rest, out, err);
    if (cmd == "camera-register") return cameraRegisterCommand(rest, out, err);
    if (cmd == "db") return dbCommand(rest, out, err);
    if (cmd == "user") return userCommand(rest, out, err);
    if (cmd == "patient") return patientCommand(rest, out, err);
    if (cmd == "protocol") return protocolCommand(rest, out, err);
    if (cmd == "programme") return programmeCommand(rest, out, err);
    if (cmd == "device") return deviceCommand(rest, out, err);
    if (cmd == "session") return sessionCommand(rest, out, err);
    if (cmd == "export") return exportCommand(rest, out, err);
    if (cmd == "audit") return auditCommand(rest, out, err);
    if (cmd == "report") return reportCommand(rest, out, err);
    if (cmd.starts_with("-")) throw UsageError("", "unknown option '" + cmd + "'");
    throw UsageError("", "unknown command '" + cmd + "'");
  } catch (const UsageError& e) {
    err << kError << e.what() << "\n"
        << "run 'armtrack-cli " << (e.command().empty() ? "" : e.command() + " ") << "--help'\n";
    return 2;
  } catch (const std::bad_alloc&) {
    err << kError << "out of memory\n";
  } catch (const std::exception& e) {
    err << kError << e.what() << "\n";  // RecordingError's text names file:line:column
  } catch (...) {
    err << kError << "unexpected failure\n";
  }
  return 1;
}

}  // namespace

int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const ScopedNoticeStream notices(err);
  const int code = dispatch(args, out, err);
  // A report that never reached its reader (a full disk, /dev/full, a closed file) is a failure.
  errno = 0;
  out.flush();
  if (!out) {
    const int e = errno;
    err << kError << "cannot write the results to standard output"
        << (e != 0 ? " (" + std::generic_category().message(e) + ")" : std::string())
        << "; they are lost\n";
    return code == 0 ? 1 : code;
  }
  return code;
}

}  // namespace armtrack::cli
