#include "app/cli/Baseline.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string_view>

#include "app/cli/Args.h"
#include "app/cli/CsvOutput.h"
#include "app/cli/Text.h"
#include "core/baseline/BaselineStudy.h"
#include "core/estimation/ArmFilter.h"
#include "core/io/Recording.h"
#include "core/simulation/DoublePendulum.h"

namespace armtrack::cli {

namespace fs = std::filesystem;

namespace {

/// The columns of `baseline --out`: estimate's names for the angles it shares (th4, th5), and
/// the humerus' elevation, which estimate does not output.
constexpr const char* kBaselineHeader = "t,th4,th5,elevation";

constexpr std::string_view kBaselineHelp =
    R"(Usage: armtrack-cli baseline REC.csv [--out OUT.csv] [options]

Runs the complementary-filter baseline (docs/baseline.md) over a recording: elbow flexion (th4)
and pronation (th5) from the two IMUs, and the humerus' elevation from the downward vertical from
the upper-arm IMU. It cannot give shoulder flexion, abduction or humeral rotation (their heading
is not observable without a model of the whole arm). With true angles in the recording, prints
its errors.

Options:
  --out FILE            write the angles (rad) to FILE: t,th4,th5,elevation (default: none)
  --overwrite           replace FILE if it exists
  --time-constant S     how long the gyroscopes are trusted before the accelerometers pull the
                        angles back (default 1)
)";

constexpr std::string_view kPendulumHelp =
    R"(Usage: armtrack-cli simulate --pendulum --out REC.csv [options]

Simulates a double pendulum (two uniform rods, a fixed pivot, damped joints) held still, then
released, with an IMU on each rod, and writes it as a recording of the arm model: the swing is
shoulder flexion th0, the hinge elbow flexion th4 (docs/baseline.md).

Options:
  --out FILE           the recording to write (required)
  --overwrite          replace FILE and its sidecar if they exist
  --duration S         length in s (default 60)
  --rate HZ            the logger's clock, one row per tick (default 100)
  --gyro-rate HZ       gyroscope rate; below --rate the last reading is repeated (default: --rate)
  --accel-rate HZ      accelerometer rate, likewise (default: --rate)
  --zero DEG           the model's elbow flexion at the pendulum's straight hinge (default 0)
  --swing DEG          release angle of the upper rod from the vertical (default 80)
  --hinge DEG          release angle of the lower rod relative to the upper (default 70)
  --hold S             seconds held still before the release (default 1)
  --damping NMS        damping of the pivot and the hinge, N m s (default 0.002 and 0.001)
  --gyro-noise RAD_S   gyroscope white noise std (default 0)
  --accel-noise M_S2   accelerometer white noise std (default 0)
  --seed N             noise seed (default 1)
)";

constexpr std::string_view kStudyHelp =
    R"(Usage: armtrack-cli study baseline [options]

The DH filter (EKF, default settings, IMUs only) and the complementary baseline on the same
recordings: the double pendulum with ideal sensors at 1 kHz and with a 50 Hz gyroscope and a
25 Hz accelerometer held on a 90 Hz clock (Table 5 noise), each with the model's straight elbow
put at 0, 35 and 90 deg of the pendulum's straight hinge, both methods told where the forearm IMU
sits on the rod (and, for 35 and 90 deg, both given the model's mounting instead); and the
reaching simulation with Table 5 noise, IMUs only. Prints hinge, pronation and swing RMSE and
peak (markdown).

Options:
  --duration S   seconds of pendulum (default 60)
  --runs N       reaching runs of 30 s, seeds 1..N (default 3)
)";

}  // namespace

int baselineCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Args a("baseline", args,
               {{"--out", true}, {"--overwrite", false}, {"--time-constant", true}});
  if (a.help()) {
    out << kBaselineHelp;
    return 0;
  }
  const fs::path in = a.single("the recording to read");
  std::optional<fs::path> outPath;
  if (const auto o = a.value("--out")) {
    if (o->empty()) a.fail("--out: expected a file name");
    outPath = *o;
    checkOutputPath(*outPath, a.flag("--overwrite"));
  }
  const double timeConstant = a.positive("--time-constant", BaselineParams{}.timeConstant);
  const Recording rec = readRecording(in);
  for (const std::string& w : rec.warnings) err << "warning: " << w << "\n";
  BaselineParams params = baselineParamsFor(rec.meta);
  params.timeConstant = timeConstant;

  bool anyUpper = false, anyFore = false;
  for (const ArmSample& s : rec.samples) {
    anyUpper = anyUpper || s.upperArm.has_value();
    anyFore = anyFore || s.forearm.has_value();
  }
  if (!anyUpper)
    throw std::runtime_error(in.string() +
                             ": no upper-arm IMU readings; the baseline needs the upper-arm IMU "
                             "(and the forearm IMU for the elbow)");
  if (!anyFore)
    err << "warning: no forearm IMU readings: only the humerus' elevation is estimated; th4 and "
           "th5 stay empty\n";

  std::optional<CsvOutput> csv;
  if (outPath) csv.emplace(kBaselineHeader, *outPath);
  std::array<double, 3> values{};
  const BaselineRun run = runBaseline(rec, params, [&](const BaselineRow& r) {
    if (!csv) return;
    values = {r.flexion, r.pronation, r.elevation};
    csv->row(r.t, values.data(), static_cast<int>(values.size()));
  });
  if (csv) csv->commit();

  const BaselineCounters& c = run.counters;
  err << "baseline: " << c.estimates << " rows estimated of " << c.rows << "\n";
  if (c.rejectedTime || c.nonFinite || c.restarts)
    err << "baseline: skipped " << c.rejectedTime << " rows out of time order, " << c.nonFinite
        << " IMU readings that were not finite; restarted after " << c.restarts
        << " gaps longer than " << shortest(params.maxGap) << " s\n";
  if (c.withoutForearm || c.withoutUpper)
    err << "baseline: " << c.withoutForearm << " rows before any forearm reading and "
        << c.withoutUpper << " before any upper-arm reading gave no elbow angles\n";
  const JointErrors& e = run.errors;
  if (e.hinge.count || e.swing.count) {
    out << "Error of the baseline against the true angles (the first second after a (re)start "
           "left out):\n\n| angle | RMSE (deg) | peak (deg) | samples |\n|---|---:|---:|---:|\n";
    const std::array<std::pair<const char*, const AngleError*>, 3> rows = {
        std::pair{"th4 elbow flexion/extension", &e.hinge},
        std::pair{"th5 forearm pronation/supination", &e.pronation},
        std::pair{"humerus elevation from the vertical", &e.swing}};
    for (const auto& [name, err1] : rows) {
      if (!err1->count) continue;
      out << "| " << name << " | " << fixed(err1->rmseDeg(), 3) << " | "
          << fixed(err1->peakDeg(), 3) << " | " << err1->count << " |\n";
    }
  }
  return 0;
}

int simulatePendulumCommand(const std::vector<std::string>& args, std::ostream& out,
                            std::ostream& err) {
  const Args a("simulate", args,
               {{"--pendulum", false},
                {"--out", true},
                {"--overwrite", false},
                {"--duration", true},
                {"--rate", true},
                {"--gyro-rate", true},
                {"--accel-rate", true},
                {"--zero", true},
                {"--swing", true},
                {"--hinge", true},
                {"--hold", true},
                {"--damping", true},
                {"--gyro-noise", true},
                {"--accel-noise", true},
                {"--seed", true}});
  if (a.help()) {
    out << kPendulumHelp;
    return 0;
  }
  if (!a.positionals().empty()) a.fail("unexpected argument " + inQuotes(a.positionals()[0]));
  const fs::path outPath = a.required("--out");
  checkOutputPath(outPath, a.flag("--overwrite"), true);
  PendulumSimParams p;
  p.duration = a.positive("--duration", 60.0);
  if (p.duration > RecordingLimits::kMaxRecordingSeconds) a.fail("--duration: at most 12 h");
  p.outputRateHz = a.positive("--rate", 100.0);
  p.gyroRateHz = a.positive("--gyro-rate", p.outputRateHz);
  p.accelRateHz = a.positive("--accel-rate", p.outputRateHz);
  if (p.gyroRateHz >= p.outputRateHz) p.gyroRateHz = 0.0;  // a new reading every row
  if (p.accelRateHz >= p.outputRateHz) p.accelRateHz = 0.0;
  if (p.outputRateHz * p.duration > 5e7) a.fail("--rate and --duration: more than 50 million rows");
  p.zeroOffset = a.number("--zero", 0.0) * kDeg;
  p.pendulum.swing0 = a.number("--swing", 80.0) * kDeg;
  p.pendulum.hinge0 = a.number("--hinge", 70.0) * kDeg;
  p.pendulum.holdSeconds = a.nonNegative("--hold", p.pendulum.holdSeconds);
  if (const auto d = a.number("--damping")) {
    if (*d < 0) a.fail("--damping: must be >= 0, got " + shortest(*d));
    p.pendulum.pivotDamping = p.pendulum.hingeDamping = *d;
  }
  p.gyroNoiseStd = a.nonNegative("--gyro-noise", 0.0);
  p.accelNoiseStd = a.nonNegative("--accel-noise", 0.0);
  p.seed = a.integer("--seed", 1);
  for (std::string_view o : {"--swing", "--hinge", "--zero"}) {
    if (const auto v = a.number(o); v && std::abs(*v) > 360.0)
      a.fail(std::string(o) + ": expected an angle within +-360 deg");
  }
  Recording rec;
  try {
    rec = simulatePendulum(p);
  } catch (const std::invalid_argument& e) {
    a.fail(e.what());
  }
  writeRecording(outPath, rec);
  err << "simulate: wrote " << rec.samples.size() << " rows (" << shortest(p.duration)
      << " s of the double pendulum) to " << outPath.string() << " and "
      << sidecarPath(outPath).string() << "\n";
  return 0;
}

int baselineStudyCommand(const std::vector<std::string>& args, std::ostream& out,
                         std::ostream& err) {
  const Args a("study", args, {{"--duration", true}, {"--runs", true}});
  if (a.help()) {
    out << kStudyHelp;
    return 0;
  }
  if (!a.positionals().empty()) a.fail("unexpected argument " + inQuotes(a.positionals()[0]));
  BaselineStudySetup setup;
  setup.pendulumSeconds = a.number("--duration", setup.pendulumSeconds);
  if (!(setup.pendulumSeconds > 2.0) || setup.pendulumSeconds > 3600.0)
    a.fail("--duration: must be more than 2 s (1 s hold, 1 s start-up) and at most 3600 s");
  const std::uint64_t runs = a.integer("--runs", 3);
  if (runs > 1000) a.fail("--runs: at most 1000");
  setup.reachingRuns = static_cast<int>(runs);
  const auto rows = runBaselineStudy(setup, [&](int done, int total) {
    err << "progress: " << done << "/" << total << " recordings\n";
  });
  out << formatBaselineStudy(rows, setup);
  return 0;
}

}  // namespace armtrack::cli
