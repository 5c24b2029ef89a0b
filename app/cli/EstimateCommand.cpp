// armtrack-cli estimate: one recording streamed row by row, or a batch of recordings estimated in
// parallel (docs/cli.md, "estimate").
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "app/cli/AutoCalibration.h"
#include "app/cli/Batch.h"
#include "app/cli/Calibrate.h"
#include "app/cli/Estimate.h"
#include "app/cli/TaoHu.h"
#include "app/cli/Text.h"
#include "core/io/AtomicFile.h"

namespace armtrack::cli {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kEstimateHelp = R"(Usage: armtrack-cli estimate REC.csv [options]
       armtrack-cli estimate REC.csv... [--out-dir DIR] [--jobs N] [options]

Runs the joint-angle filter over a recording, with the geometry and gravity of its sidecar.
Writes the angles (rad) as CSV "t,th0,th1,th2,th4,th5", one row per IMU sample. When the
recording holds true angles, prints RMSE and peak error per joint (deg). The recording is read
row by row, so memory does not grow with its length.

With several recordings (or --out-dir) they are estimated in parallel, one per core: each
REC.csv gives DIR/REC.csv (the angles) and DIR/REC.md (its diagnostics and report), and a
summary table goes to standard output. A recording that fails is reported with its error and
does not stop the others; the exit status is then 1.

Options:
  --filter ekf|ukf         filter (default ekf)
  --method A|B|C|inclinometer|tao-hu
                           IMU measurement model (default A). tao-hu instead runs the webcam +
                           forearm-IMU tracker of Tao & Hu (needs a camera block and the forearm
                           IMU): one row per camera frame, "t,wrist_x,wrist_y,wrist_z,elbow_x,
                           elbow_y,elbow_z,th0,th1,th2,th4,th5" (m, shoulder frame; rad), and
                           wrist/elbow position errors in cm when there is truth
  --no-kinect              ignore the Kinect's elbow/wrist positions
  --no-webcam              ignore the webcam's marker pixels (used when the sidecar has a
                           camera block)
  --joint-accel-std DEG_S2 joint-acceleration process noise std (default 1, the paper's Table 5)
  --gyro-noise-std DEG_S   the gyroscopes' white noise per axis (default 0.32, Table 5's
                           0.0055 rad/s), for sensors known to be noisier
  --accel-noise-std M_S2   the accelerometers' white noise per axis (default 0.1, Table 5's
                           variance 0.01 m^2/s^4)
  --calibration FILE       apply a calibration made by "armtrack-cli calibrate" (IMU mounting,
                           gyroscope biases, segment lengths; docs/calibration.md)
  --no-auto-calibration    without --calibration, do not try the calibration from movement on
                           the first 60 s (by default it is fitted, and applied only when it
                           explains the readings clearly better than the sidecar's mounting;
                           one line on standard error says what happened)
  --out FILE               write the angles here (default: statistics only; one recording)
  --out-dir DIR            several recordings: write each one's angles and report here (made
                           if missing; default: statistics only)
  --jobs N                 several recordings: estimate N at a time (default: every core)
  --overwrite              replace the output files if they exist (otherwise an error)
)";

/// What the options ask for, whatever the number of recordings.
struct Setup {
  EstimateOptions options;
  bool taoHu = false;
  std::optional<fs::path> calibration;
  bool autoCalibration = true;  ///< without --calibration, try the calibration from movement
  bool overwrite = false;
};

Setup parseSetup(const Args& a) {
  Setup s;
  s.taoHu = a.value("--method") == std::optional<std::string>("tao-hu");
  s.options.filter = parseFilter(a);
  if (const auto m = a.value("--method"); m && !s.taoHu) {
    try {
      s.options.model = parseMethod(*m);
    } catch (const std::invalid_argument& e) {
      a.fail(std::string("--method: ") + e.what());
    }
  }
  s.options.useOptical = !a.flag("--no-kinect");
  s.options.useCamera = !a.flag("--no-webcam");
  if (a.flag("--joint-accel-std"))
    s.options.jointAccelStdDeg = a.positive("--joint-accel-std", 1.0);
  if (a.flag("--gyro-noise-std")) s.options.gyroNoiseStdDeg = a.positive("--gyro-noise-std", 1.0);
  if (a.flag("--accel-noise-std")) s.options.accelNoiseStd = a.positive("--accel-noise-std", 1.0);
  if (a.flag("--calibration")) s.calibration = a.required("--calibration");
  s.autoCalibration = !a.flag("--no-auto-calibration");
  s.overwrite = a.flag("--overwrite");
  return s;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The line that sums a run up: "estimate: N estimates from R rows (...), EKF, ..., T s".
std::string summaryLine(const EstimateStats& st, const EstimateOptions& opt, double seconds,
                        const std::optional<fs::path>& outPath) {
  std::string s =
      "estimate: " + std::to_string(st.estimates) + " estimates from " + std::to_string(st.rows) +
      " rows (" + shortest(st.tFirst) + " to " + shortest(st.tLast) + " s), " +
      (opt.filter == FilterKind::Ekf ? "EKF" : "UKF") + ", method " + methodName(opt.model) +
      (st.opticalUsed ? ", optical fused" : ", no optical data") + ", " + fixed(seconds, 2) + " s";
  if (outPath) s += "; wrote " + outPath->string();
  return s + "\n";
}

// The output's header: with the trunk's columns when the recording has a trunk IMU or an optical
// shoulder. A recording that cannot be opened gets the plain header; reading it reports why.
std::string estimateHeaderFor(const fs::path& input) {
  try {
    RecordingReader peek(input);
    return hasTrunkOutput(peek.columns()) ? kEstimateTrunkHeader : kEstimateHeader;
  } catch (const RecordingError&) {
    return kEstimateHeader;
  }
}

void requireFile(const fs::path& input) {
  std::error_code ec;
  if (!fs::exists(input, ec)) throw std::runtime_error(input.string() + ": no such file");
}

/// Everything of a run of one recording file that a report needs.
struct FileRun {
  EstimateStats stats;
  EstimatorParams params;
  double seconds = 0.0;
};

/// Streams input through the filter (and into writer). Warnings and the calibration's lines go to
/// log as they come; a recording without any IMU row is an error. With overlap, reading and
/// writing run in their own threads (estimateStream).
FileRun runFile(const fs::path& input, const Setup& setup, const Calibration* calibration,
                CsvOutput* writer, const FileProgress& progress, std::ostream& log, bool overlap) {
  requireFile(input);
  RecordingReader reader(input);
  for (const std::string& w : reader.warnings()) log << "warning: " << w << "\n";
  const std::size_t warned = reader.warnings().size();
  RecordingMeta meta = reader.meta();
  if (calibration) useCalibration(*calibration, *setup.calibration, meta, log);
  std::optional<Calibration> automatic;
  if (!calibration && setup.autoCalibration) {
    // The fitted mounting is judged by how well the model explains the readings: with Method
    // A's filter whatever method estimates. Methods B and C read body acceleration as tilt, so
    // their angles explain the readings roughly with any mounting, and with them the fit of a
    // strap turned 30 deg was refused as no better than the sidecar's (IMUs only; issue 27).
    EstimateOptions judged = setup.options;
    judged.model = MeasurementModel::AccelGyro;
    AutoCalibrationResult found = autoCalibrate(input, judged);
    log << found.line << "\n";
    if (found.calibration) {
      automatic = std::move(found.calibration);
      applyCalibration(*automatic, meta);
      calibration = &*automatic;
    }
  }
  FileRun run;
  run.params = makeParams(meta, setup.options);
  const auto start = std::chrono::steady_clock::now();
  run.stats = estimateStream(reader, run.params, calibration, writer, progress, nullptr, overlap);
  // A last line cut short is found at the end.
  for (std::size_t i = warned; i < reader.warnings().size(); ++i)
    log << "warning: " << reader.warnings()[i] << "\n";
  if (run.stats.imuRows == 0)
    throw std::runtime_error(input.string() + ": no IMU samples to estimate from");
  if (writer) writer->commit();
  run.seconds = secondsSince(start);
  return run;
}

int estimateTaoHu(const Args& a, const fs::path& input, const std::optional<fs::path>& outPath,
                  const Setup& setup, std::ostream& out, std::ostream& err) {
  requireFile(input);
  Recording rec = readRecording(input);
  for (const std::string& w : rec.warnings) err << "warning: " << w << "\n";
  if (setup.calibration) applyCalibrationFile(*setup.calibration, rec, err);
  if (std::none_of(rec.samples.begin(), rec.samples.end(),
                   [](const ArmSample& s) { return s.hasImu(); }))
    throw std::runtime_error(input.string() + ": no IMU samples to estimate from");
  for (std::string_view o : {"--filter", "--no-kinect", "--no-webcam", "--joint-accel-std",
                             "--gyro-noise-std", "--accel-noise-std", "--no-auto-calibration"}) {
    if (a.flag(o)) err << "warning: " << o << " does not apply to --method tao-hu; ignored\n";
  }
  std::optional<CsvOutput> writer;
  if (outPath) writer.emplace(kTaoHuHeader, *outPath);
  const TaoHuRun run = runTaoHuRecording(rec, writer ? &*writer : nullptr);
  if (writer) writer->commit();
  const TaoHuCounters& c = run.result.counters;
  err << "estimate: " << run.result.frames.size() << " camera-frame estimates from " << c.samples
      << " rows, method tao-hu (" << c.wristUpdates << " wrist and " << c.elbowUpdates
      << " elbow pixels fused, " << c.wristGated + c.elbowGated << " gated), "
      << fixed(run.seconds, 2) << " s";
  if (outPath) err << "; wrote " << outPath->string();
  err << "\n";
  if (c.rejectedNonFinite || c.rejectedTime || c.restarts || c.initFailures || c.lmFailures) {
    err << "tao-hu: rejected non-finite " << c.rejectedNonFinite << ", rejected time "
        << c.rejectedTime << ", restarts " << c.restarts << ", alignment failures "
        << c.initFailures << ", LM failures " << c.lmFailures << "\n";
  }
  if (run.result.frames.empty())
    err << "estimate: the tracker never started (no frame with both markers after the "
           "orientation warm-up)\n";
  else if (run.errors.count == 0)
    err << "estimate: no true angles in the recording, so no error statistics\n";
  out << formatTaoHuReport(run);
  return 0;
}

int estimateOne(const Args& a, std::ostream& out, std::ostream& err) {
  const fs::path input = a.single("the recording to read (estimate REC.csv)");
  const Setup setup = parseSetup(a);
  if (a.flag("--jobs")) err << "warning: --jobs applies to several recordings; ignored\n";
  std::optional<fs::path> outPath;
  if (a.flag("--out")) {
    outPath = a.required("--out");
    if (samePath(*outPath, input) || samePath(*outPath, sidecarPath(input)))
      a.fail("--out: " + inQuotes(outPath->string()) + " would overwrite the recording");
    checkOutputPath(*outPath, setup.overwrite);
  }
  if (setup.taoHu) return estimateTaoHu(a, input, outPath, setup, out, err);

  requireFile(input);
  std::optional<Calibration> calibration;
  if (setup.calibration) calibration = readCalibration(*setup.calibration);
  std::optional<CsvOutput> writer;
  if (outPath) writer.emplace(estimateHeaderFor(input), *outPath);
  // Progress for recordings of more than kProgressRows rows, judged by the bytes per row of the
  // first ones (the number of rows is known only at the end).
  std::optional<bool> showProgress;
  int nextPercent = 10;
  const FileProgress progress = [&](std::uint64_t rows, std::uint64_t bytes, std::uint64_t size) {
    if (!showProgress)
      showProgress =
          size > 0 && bytes > 0 &&
          static_cast<double>(rows) * static_cast<double>(size) / static_cast<double>(bytes) >
              static_cast<double>(kProgressRows);
    for (; *showProgress && nextPercent <= 100 &&
           bytes * 100 >= static_cast<std::uint64_t>(nextPercent) * size;
         nextPercent += 10)
      err << "progress: " << nextPercent << "%\n";
  };
  const FileRun run = runFile(input, setup, calibration ? &*calibration : nullptr,
                              writer ? &*writer : nullptr, progress, err, true);
  err << summaryLine(run.stats, setup.options, run.seconds, outPath);
  writeDiagnostics(err, run.stats, run.params);
  out << formatReport(run.stats);
  return 0;
}

// ---------------------------------------------------------------------------------------------
// Several recordings

void writeTextFile(const fs::path& path, const std::string& text) {
  try {
    AtomicFile f(path);
    f.write(text);
    f.commit();
  } catch (const AtomicFileError& e) {
    throw std::runtime_error(e.what());
  }
}

int estimateBatch(const Args& a, std::ostream& out, std::ostream& err) {
  const Setup setup = parseSetup(a);
  if (setup.taoHu) a.fail("--method tao-hu: give one recording at a time");
  if (a.flag("--out")) a.fail("--out takes one recording; use --out-dir DIR for several");
  const std::vector<std::string>& names = a.positionals();
  if (names.empty()) a.fail("missing the recordings to read (estimate REC.csv...)");
  std::vector<fs::path> inputs(names.begin(), names.end());
  unsigned threads = defaultBatchThreads();
  if (a.flag("--jobs")) {
    const std::uint64_t j = a.integer("--jobs", threads);
    if (j < 1 || j > 1024) a.fail("--jobs: must be between 1 and 1024");
    threads = static_cast<unsigned>(j);
  }

  // Outputs: DIR/<stem>.csv and DIR/<stem>.md, checked before any work is done.
  std::optional<fs::path> outDir;
  std::vector<fs::path> csvOut(inputs.size()), reportOut(inputs.size());
  if (a.flag("--out-dir")) {
    outDir = a.required("--out-dir");
    std::map<std::string, std::string> byStem;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      const std::string stem = inputs[i].stem().string();
      if (const auto [it, fresh] = byStem.emplace(stem, names[i]); !fresh)
        a.fail(inQuotes(names[i]) + " and " + inQuotes(it->second) + " would both be written as " +
               inQuotes(stem + ".csv") + " in --out-dir");
      csvOut[i] = *outDir / (stem + ".csv");
      reportOut[i] = *outDir / (stem + ".md");
      for (const fs::path& o : {csvOut[i], reportOut[i]})
        for (const fs::path& in : inputs)
          if (samePath(o, in) || samePath(o, sidecarPath(in)))
            a.fail("--out-dir: " + inQuotes(o.string()) + " would overwrite the recording " +
                   inQuotes(in.string()));
    }
    std::error_code ec;
    if (fs::exists(*outDir, ec) && !fs::is_directory(*outDir, ec))
      throw std::runtime_error(outDir->string() + ": is not a folder; give a folder for --out-dir");
    fs::create_directories(*outDir, ec);
    if (ec)
      throw std::runtime_error(outDir->string() + ": cannot make the folder: " + ec.message());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      checkOutputPath(csvOut[i], setup.overwrite);
      checkOutputPath(reportOut[i], setup.overwrite);
    }
  }
  std::optional<Calibration> calibration;
  if (setup.calibration) calibration = readCalibration(*setup.calibration);

  std::vector<BatchJob> jobs(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    jobs[i].name = names[i];
    std::error_code ec;
    jobs[i].weight = fs::file_size(inputs[i], ec);
    if (ec) jobs[i].weight = 1;
  }
  std::vector<FileRun> runs(inputs.size());
  const auto start = std::chrono::steady_clock::now();
  // Reading and writing get threads of their own only when the recordings leave cores idle.
  const bool overlap = std::min<std::size_t>(threads, inputs.size()) < defaultBatchThreads();
  const BatchWork work = [&](std::size_t i, const BatchProgress& progress) {
    std::ostringstream log;
    std::optional<CsvOutput> writer;
    if (outDir) writer.emplace(estimateHeaderFor(inputs[i]), csvOut[i]);
    runs[i] = runFile(
        inputs[i], setup, calibration ? &*calibration : nullptr, writer ? &*writer : nullptr,
        [&](std::uint64_t, std::uint64_t bytes, std::uint64_t size) {
          if (size > 0) progress(static_cast<double>(bytes) / static_cast<double>(size));
        },
        log, overlap);
    if (!outDir) return;
    log << summaryLine(runs[i].stats, setup.options, runs[i].seconds,
                       std::optional<fs::path>(csvOut[i]));
    writeDiagnostics(log, runs[i].stats, runs[i].params);
    const std::string report = formatReport(runs[i].stats);
    writeTextFile(reportOut[i], "# " + names[i] + "\n\n```\n" + log.str() + "```\n" +
                                    (report.empty() ? "" : "\n" + report));
  };
  const std::vector<BatchOutcome> outcomes =
      runBatch(jobs, threads, work, BatchDisplay{&err, isTerminal(err), "estimate"});

  out << "| recording | rows | estimates | optical | seconds | worst RMSE (deg) | result |\n"
      << "|---|---:|---:|---|---:|---:|---|\n";
  std::size_t failed = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const BatchOutcome& o = outcomes[i];
    const EstimateStats& st = runs[i].stats;
    out << "| " << tableCell(names[i]) << " | ";
    if (o.ok) {
      const std::string worst =
          st.truthCount > 0 ? fixed(st.rmseDeg.maxCoeff(), 3) : std::string("-");
      out << st.rows << " | " << st.estimates << " | " << (st.opticalUsed ? "yes" : "no") << " | "
          << fixed(o.seconds, 2) << " | " << worst << " | ok |\n";
    } else {
      ++failed;
      out << "- | - | - | " << fixed(o.seconds, 2) << " | - | failed: " << tableCell(o.error)
          << " |\n";
    }
  }
  err << "estimate: " << inputs.size() - failed << " of " << inputs.size()
      << " recordings estimated, " << failed << " failed, in " << fixed(secondsSince(start), 2)
      << " s on " << std::min<std::size_t>(threads, inputs.size()) << " threads";
  if (outDir) err << "; wrote " << outDir->string();
  err << "\n";
  return failed > 0 ? 1 : 0;
}

}  // namespace

int estimateCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Args a("estimate", args,
               {{"--filter", true},
                {"--method", true},
                {"--no-kinect", false},
                {"--no-webcam", false},
                {"--joint-accel-std", true},
                {"--gyro-noise-std", true},
                {"--accel-noise-std", true},
                {"--calibration", true},
                {"--no-auto-calibration", false},
                {"--out", true},
                {"--out-dir", true},
                {"--jobs", true},
                {"--overwrite", false}});
  if (a.help()) {
    out << kEstimateHelp;
    return 0;
  }
  if (a.positionals().size() > 1 || a.flag("--out-dir")) return estimateBatch(a, out, err);
  return estimateOne(a, out, err);
}

}  // namespace armtrack::cli
