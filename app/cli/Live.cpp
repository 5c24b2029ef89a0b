#include "app/cli/Live.h"

#include <sys/resource.h>
#include <unistd.h>

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSettings>
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <thread>

#include "app/cli/Args.h"
#include "app/cli/ClinicalContext.h"
#include "app/cli/CsvOutput.h"
#include "app/plugins/DeviceRecord.h"
#include "app/plugins/PluginRegistry.h"
#include "core/io/Recording.h"
#include "core/session/Session.h"
#include "core/storage/DatabaseRecordingSink.h"
#include "core/sync/SensorPayload.h"
#include "devices/api/DeviceThread.h"
#include "devices/api/Options.h"

namespace armtrack::cli {
namespace {

constexpr const char* kDevicesHelp = R"(usage: armtrack-cli devices [--plugins DIR]...

Lists the device plugins found, their options, and the plugin files that were refused and why.
Plugins are looked for in --plugins folders, the settings' devices/pluginPath,
$ARMTRACK_PLUGIN_PATH, <exe>/../plugins (a build) and the installed plugin folder
(/usr/lib/<multiarch>/armtrack/plugins for /usr/bin/armtrack-cli).
)";

constexpr const char* kRecordHelp =
    R"(usage: armtrack-cli record --device NAME[:OPTIONS] [--device ...] --duration S --out FILE.csv
                          [--plugins DIR] [--filter ekf|ukf] [--no-estimate] [--side right|left]
                          [--latency-window S] [--no-auto-calibration] [--quiet] [--overwrite]
       armtrack-cli record --device ... --duration S --db URL --user NAME --patient CODE
                          [--protocol NAME] [other options as above]

Runs a live session and records it in the open format (docs/recording-format.md): the raw
samples in time order, the angles estimated live (est_th*) and, with the virtual arm, the true
angles (true_th*). OPTIONS are key=value pairs joined by ',' (armtrack-cli devices lists them),
e.g. --device virtual-arm:sensors=upper+forearm+kinect,disappear=10+3
Device states and problems are printed as they happen; Ctrl-C (SIGINT), SIGTERM or SIGHUP ends
the session early and keeps everything recorded so far. An existing FILE.csv (or its sidecar) is
only replaced with --overwrite, and a file another recording is being written to never is.
The straps are fitted from the movement as the session goes (the first fit after 30 s, refits
every 60 s on the newest 90 s) and used only when they explain the readings clearly better, as
`estimate` does; each fit is told, and the one used is kept beside FILE.csv as
FILE.movement-calibration.json. --no-auto-calibration switches it off.
The row count printed is what the file holds; if rows could not be written (a full disk), the
number lost is printed and the exit status is 1.

With --db the session is recorded straight into the clinical records (docs/storage.md) as a new
session of patient CODE, committed about every second: if the process is killed, the session
keeps all but the last second and is marked interrupted the next time the database is opened.
The password of NAME comes from ARMTRACK_PASSWORD (or a prompt on a terminal). The first line
printed is "session ID", the new session's id.
)";

constexpr const char* kLiveHelp =
    R"(usage: armtrack-cli live --device NAME[:OPTIONS] [--device ...] [--duration S] [--stats]
                        [--stats-interval S] [--out FILE.csv] [--plugins DIR] [--filter ekf|ukf]
                        [--side right|left] [--latency-window S] [--no-auto-calibration]
                        [--quiet] [--overwrite]

Runs a live session (until --duration, or Ctrl-C) and prints the joint angles once a second, or
with --stats the pipeline's figures: per stream the sample rate, samples received, rejected and
late, link losses; samples lost; sample-to-estimate latency percentiles; CPU use; resident
memory. --out records the session as `record` does (--overwrite to replace an existing file).
The straps are fitted from the movement as `record` fits them (--no-auto-calibration: not).
)";

std::atomic<bool> g_interrupted{false};
extern "C" void onInterrupt(int) {
  g_interrupted = true;
}

/// A QCoreApplication for the duration of a command when the caller has none.
struct QtApp {
  QtApp() {
    if (!QCoreApplication::instance()) {
      static int argc = 1;
      static char name[] = "armtrack-cli";
      static char* argv[] = {name, nullptr};
      app = std::make_unique<QCoreApplication>(argc, argv);
    }
  }
  std::unique_ptr<QCoreApplication> app;
};

QStringList pluginFolders(const Args& a) {
  QStringList folders;
  for (const std::string& d : a.values("--plugins")) folders << QString::fromStdString(d);
  const QSettings settings(QStringLiteral("ArmTrack"), QStringLiteral("ArmTrack"));
  const QString configured = settings.value(QStringLiteral("devices/pluginPath")).toString();
  if (!configured.isEmpty()) folders << configured.split(u':', Qt::SkipEmptyParts);
  folders << app::PluginRegistry::defaultFolders();
  return folders;
}

double residentMegabytes() {
  std::ifstream statm("/proc/self/statm");
  double size = 0, resident = 0;
  statm >> size >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

double processCpuSeconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

/// The rows a recording holds (a last line cut short not counted). Throws RecordingError.
std::uint64_t rowsInRecording(const std::string& path) {
  RecordingReader reader(path);
  ArmSample s;
  while (reader.next(s)) {
  }
  return reader.rows();
}

struct LiveOptions {
  std::vector<std::string> devices;
  double duration = 0.0;  // 0 = until Ctrl-C
  std::string out;
  bool stats = false;
  double statsInterval = 10.0;
  bool anglesEverySecond = false;
  bool quiet = false;
};

const std::vector<OptionSpec> kSessionOptions = {{"--device", true},
                                                 {"--duration", true},
                                                 {"--out", true},
                                                 {"--plugins", true},
                                                 {"--filter", true},
                                                 {"--no-estimate", false},
                                                 {"--side", true},
                                                 {"--latency-window", true},
                                                 {"--stats", false},
                                                 {"--stats-interval", true},
                                                 {"--quiet", false},
                                                 {"--overwrite", false},
                                                 {"--db", true},
                                                 {"--user", true},
                                                 {"--patient", true},
                                                 {"--protocol", true},
                                                 {"--no-auto-calibration", false}};

/// recorded: the rows to report as recorded (the session's count unless given).
void printStats(std::ostream& out, const session::SessionStats& s, double cpuPercent, double rssMb,
                std::optional<std::uint64_t> recorded = std::nullopt) {
  char line[256];
  // Lost: rows dropped on the way to the recorder, and, once the recording is read back, rows
  // the recorder was given that did not reach it (a full disk, a refused write).
  const std::uint64_t stored = recorded.value_or(s.recordedRows);
  const std::uint64_t notStored =
      recorded && *recorded < s.rowsToRecord ? s.rowsToRecord - *recorded : 0;
  std::snprintf(
      line, sizeof line, "[%7.1f s] rows %llu  estimates %llu  recorded %llu  lost %llu\n",
      s.elapsed, static_cast<unsigned long long>(s.rows),
      static_cast<unsigned long long>(s.estimates), static_cast<unsigned long long>(stored),
      static_cast<unsigned long long>(s.lost() + notStored));
  out << line;
  for (std::size_t i = 0; i < s.streams.size(); ++i) {
    const session::StreamStats& st = s.streams[i];
    std::snprintf(
        line, sizeof line,
        "  %-14s %-8s %8.1f Hz  received %9llu  rejected %5llu  late %5llu  "
        "link lost %6llu  corrupt %5llu  drift %+7.1f ppm  jitter %5.2f ms\n",
        st.device.c_str(), st.stream.c_str(), st.rateHz,
        static_cast<unsigned long long>(st.received), static_cast<unsigned long long>(st.rejected),
        static_cast<unsigned long long>(st.late), static_cast<unsigned long long>(st.deviceDropped),
        static_cast<unsigned long long>(st.deviceCorrupt), st.driftPpm, st.jitterMs);
    out << line;
  }
  std::snprintf(line, sizeof line,
                "  latency p50 %.1f ms  p90 %.1f ms  p99 %.1f ms  max %.1f ms   CPU %.1f %% of one "
                "core   resident %.1f MB   input queue max %zu\n",
                s.latency.quantile(0.5) * 1e3, s.latency.quantile(0.9) * 1e3,
                s.latency.quantile(0.99) * 1e3, s.latency.max() * 1e3, cpuPercent, rssMb,
                s.maxInputQueued);
  out << line;
  const EstimatorCounters& e = s.estimator;
  if (e.implausible.total() > 0 || e.recoveries > 0 || e.restarts > 0) {
    std::snprintf(line, sizeof line,
                  "  estimator: predicted through refused readings %llu  recoveries %llu  "
                  "restarts %llu\n",
                  static_cast<unsigned long long>(e.coasted),
                  static_cast<unsigned long long>(e.recoveries),
                  static_cast<unsigned long long>(e.restarts));
    out << line;
    if (e.implausible.total() > 0) out << "  estimator: " << e.implausible.summary() << "\n";
  }
  out.flush();
}

/// What the options ask of a session, checked before anything starts.
struct SessionSetup {
  LiveOptions o;
  session::SessionParams params;
  std::string filter;  // "ekf" or "ukf"
  bool toDb = false;
  bool overwrite = false;
};

SessionSetup parseSession(const Args& a, bool record) {
  SessionSetup s;
  LiveOptions& o = s.o;
  if (!a.positionals().empty()) a.fail("unexpected argument '" + a.positionals()[0] + "'");
  o.devices = a.values("--device");
  if (o.devices.empty()) a.fail("--device is required (armtrack-cli devices lists them)");
  if (record && !a.value("--duration")) a.fail("--duration is required");
  o.duration = record ? a.positive("--duration", 0.0) : a.nonNegative("--duration", 0.0);
  s.toDb = a.value("--db").has_value();
  if (!s.toDb)
    for (const char* option : {"--user", "--patient", "--protocol"})
      if (a.value(option)) a.fail(std::string(option) + ": only applies with record --db");
  if (s.toDb && !record) a.fail("--db: only record writes into the clinical records");
  if (s.toDb && a.value("--out"))
    a.fail("--out and --db: record into a file or into the clinical records, not both");
  o.out = record && !s.toDb ? a.required("--out") : a.value("--out").value_or("");
  o.stats = a.flag("--stats");
  o.statsInterval = a.positive("--stats-interval", 10.0);
  o.quiet = a.flag("--quiet");
  o.anglesEverySecond = !record && !o.stats;
  s.overwrite = a.flag("--overwrite");
  if (s.overwrite && o.out.empty()) a.fail("--overwrite: only applies with --out");
  if (!o.out.empty()) {  // before anything starts
    try {
      checkOutputPath(o.out, s.overwrite, true);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(std::string("cannot record: ") + e.what());
    }
  }

  session::SessionParams& params = s.params;
  s.filter = a.value("--filter").value_or("ekf");
  if (s.filter == "ekf")
    params.estimator.filter = FilterKind::Ekf;
  else if (s.filter == "ukf")
    params.estimator.filter = FilterKind::Ukf;
  else
    a.fail("--filter: expected ekf or ukf, got '" + s.filter + "'");
  const std::string side = a.value("--side").value_or("right");
  if (side == "left")
    params.meta.side = Side::Left;
  else if (side != "right")
    a.fail("--side: expected right or left, got '" + side + "'");
  params.estimate = !a.flag("--no-estimate");
  // No calibration file is given to a live session: the straps are fitted from the movement.
  params.movementCalibration.enabled = !a.flag("--no-auto-calibration");
  params.latencyWindow = a.positive("--latency-window", params.latencyWindow);
  params.recordingPath = o.out;
  // The session claims the name itself (O_EXCL) unless --overwrite, so a recording that appears
  // between the check above and the start is never replaced.
  params.overwrite = s.overwrite;
  return s;
}

/// A recording into the clinical records: the signed-in store, the session it begins (once the
/// devices' columns are known) and the devices it names.
struct RecordsTarget {
  std::unique_ptr<ClinicalContext> records;
  qint64 sessionId = 0;
  QJsonObject devicesUsed;  // filled as the devices are made, stored when the session begins
};

/// Signs in and checks the patient before any device starts, and sets the session's sink to
/// begin the session in the records. target must outlive the session.
void prepareRecordsTarget(const Args& a, SessionSetup& s, RecordsTarget& target,
                          std::ostream& out) {
  if (s.overwrite) a.fail("--overwrite: only applies with --out");
  const QString patient = qs(a.required("--patient"));
  const QString protocol = qs(a.value("--protocol").value_or(""));
  target.records = std::make_unique<ClinicalContext>(a, storage::Database::Options{}, true);
  target.records->store().patient(patient);  // StorageError(NotFound) names it
  if (!protocol.isEmpty()) target.records->store().protocol(protocol);
  const storage::DatabaseUrl url = target.records->db().url();
  s.params.flushInterval = storage::DatabaseRecordingSink::kFlushInterval;
  const QString filterName = QString::fromStdString(s.filter);
  s.params.openSink = [&target, &out, url, patient, protocol, filterName](
                          const RecordingMeta& meta,
                          const RecordingColumns& columns) -> std::unique_ptr<RecordingSink> {
    storage::SessionSettings settings;
    settings.devicesJson =
        QString::fromUtf8(QJsonDocument(target.devicesUsed).toJson(QJsonDocument::Compact));
    // The live filter, which the session's analysis then uses too.
    settings.filterJson = QString::fromUtf8(
        QJsonDocument(QJsonObject{{"filter", filterName}}).toJson(QJsonDocument::Compact));
    try {
      target.sessionId =
          target.records->store().beginRecording(patient, protocol, meta, columns, settings);
    } catch (const storage::StorageError& e) {
      throw RecordingError(ss(url.display()), 0, 0, e.what());
    }
    out << "session " << target.sessionId << "\n" << std::flush;
    return std::make_unique<storage::DatabaseRecordingSink>(url, target.sessionId, columns);
  };
}

/// Makes each device of the options and adds it to the session; false (and what is wrong on
/// err) when one cannot be made.
bool addDevices(const LiveOptions& o, const app::PluginRegistry& registry,
                session::Session& session, QJsonObject& devicesUsed, std::ostream& err) {
  for (const std::string& spec : o.devices) {
    const auto colon = spec.find(':');
    const QString name = QString::fromStdString(spec.substr(0, colon));
    const QVariantMap options = devices::Options::parse(
        colon == std::string::npos ? QString() : QString::fromStdString(spec.substr(colon + 1)));
    devices::DevicePlugin* plugin = registry.plugin(name);
    if (!plugin) {
      err << "armtrack-cli: error: no device plugin '" << name.toStdString()
          << "'; found: " << registry.names().join(QStringLiteral(", ")).toStdString()
          << " (armtrack-cli devices tells which files were refused)\n";
      return false;
    }
    QString why;
    std::unique_ptr<devices::Device> device = plugin->create(options, &why);
    if (!device) {
      err << "armtrack-cli: error: " << why.toStdString() << "\n";
      return false;
    }
    const QString label = QStringLiteral("%1#%2").arg(name).arg(
        o.devices.size() > 1 ? QString::number(&spec - o.devices.data() + 1) : QStringLiteral("1"));
    devicesUsed.insert(label, app::deviceRecord(name, options, *device));
    session.addDevice(std::make_unique<devices::DeviceThread>(std::move(device), label), label);
  }
  return true;
}

/// The session's new messages to err (unless --quiet).
void drainEvents(session::Session& session, const LiveOptions& o, std::ostream& err) {
  std::vector<std::string> events;
  session.takeEvents(events);
  if (!o.quiet)
    for (const std::string& e : events) err << "  " << e << "\n";
}

/// The run's clock and resources: at its start, after its first minute and at its end.
struct RunTimes {
  double start = 0.0, end = 0.0;
  double cpu0 = 0.0, cpu = 0.0, rss = 0.0;
  double rssAtMinute = 0.0, cpuAtMinute = 0.0, minuteTime = 0.0;
};

/// Runs the started session until its duration, Ctrl-C (SIGINT, SIGTERM, SIGHUP) or the end of
/// every device, printing angles, statistics and messages as asked; stops it.
RunTimes runUntilDone(session::Session& session, const LiveOptions& o, std::ostream& out,
                      std::ostream& err) {
  g_interrupted = false;
  const auto oldInt = std::signal(SIGINT, onInterrupt);
  const auto oldTerm = std::signal(SIGTERM, onInterrupt);
  const auto oldHup = std::signal(SIGHUP, onInterrupt);  // a closed terminal ends it cleanly too

  RunTimes r;
  r.start = hostNow();
  r.cpu0 = processCpuSeconds();
  double nextStats = r.start + o.statsInterval, nextAngles = r.start + 1.0;
  std::vector<session::EstimateRow> results;
  while (!g_interrupted) {
    const double now = hostNow();
    if (o.duration > 0.0 && now - r.start >= o.duration) break;
    const session::SessionStats st = session.stats();
    const bool allEnded = std::all_of(st.deviceStates.begin(), st.deviceStates.end(), [](auto s) {
      return s == DeviceState::Disconnected || s == DeviceState::Error;
    });
    if (allEnded && now - r.start > 1.0) {
      out << "every device has ended; stopping\n";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    QCoreApplication::processEvents();
    drainEvents(session, o, err);
    results.clear();
    session.takeResults(results);  // the GUI drains this buffer the same way
    if (r.rssAtMinute == 0.0 && now - r.start >= 60.0) {
      r.rssAtMinute = residentMegabytes();
      r.cpuAtMinute = processCpuSeconds();
      r.minuteTime = now;
    }
    if (o.anglesEverySecond && now >= nextAngles && !results.empty()) {
      const session::EstimateRow& row = results.back();
      char line[160];
      std::snprintf(line, sizeof line,
                    "t %9.3f s  th0 %7.2f  th1 %7.2f  th2 %7.2f  th4 %7.2f  th5 %7.2f deg\n", row.t,
                    row.th(0) * 180 / M_PI, row.th(1) * 180 / M_PI, row.th(2) * 180 / M_PI,
                    row.th(3) * 180 / M_PI, row.th(4) * 180 / M_PI);
      out << line << std::flush;
      nextAngles = now + 1.0;
    }
    if (o.stats && now >= nextStats) {
      printStats(out, session.stats(), 100.0 * (processCpuSeconds() - r.cpu0) / (now - r.start),
                 residentMegabytes());
      nextStats = now + o.statsInterval;
    }
  }
  r.end = hostNow();
  r.cpu = processCpuSeconds();
  r.rss = residentMegabytes();
  session.stop();
  std::signal(SIGINT, oldInt);
  std::signal(SIGTERM, oldTerm);
  std::signal(SIGHUP, oldHup);
  drainEvents(session, o, err);
  return r;
}

/// After the session: the recording read back and, in the records, the session closed (and
/// analysed when whole); the summary. The exit status: 1 when rows were lost or the recording
/// cannot be read back or closed.
int finishRun(const SessionSetup& setup, RecordsTarget& target, const session::SessionStats& s,
              const RunTimes& t, bool record, std::ostream& out, std::ostream& err) {
  const LiveOptions& o = setup.o;
  // The account of the recording is what the file holds, read back, not what the recorder was
  // handed: rows that a full disk kept from the file are counted as lost.
  std::optional<std::uint64_t> onDisk;
  std::string unreadable;
  std::string where = o.out;
  bool finishFailed = false;
  bool analysisFailed = false;
  if (setup.toDb) {
    // Complete, also after Ctrl-C (the user ended it), when every row is stored; interrupted
    // when rows were lost. If the status cannot be written the session stays "recording" and is
    // marked interrupted when the database is next opened.
    storage::ClinicalStore& store = target.records->store();
    where = "session " + std::to_string(target.sessionId);
    try {
      onDisk = static_cast<std::uint64_t>(store.session(target.sessionId).sampleRows);
    } catch (const std::exception& e) {
      unreadable = e.what();
    }
    const bool whole = onDisk && *onDisk == s.rowsToRecord;
    try {
      store.finishSession(
          target.sessionId,
          QString::fromLatin1(whole ? storage::kStatusComplete : storage::kStatusInterrupted));
    } catch (const std::exception& e) {
      err << "armtrack-cli: error: cannot close " << where << ": " << e.what()
          << "; it will be marked interrupted when the database is next opened\n";
      finishFailed = true;
    }
    if (whole && !finishFailed && !analyseNewSession(store, target.sessionId, "record", err))
      analysisFailed = true;
  } else if (!o.out.empty()) {
    try {
      onDisk = rowsInRecording(o.out);
    } catch (const std::exception& e) {
      unreadable = e.what();
    }
  }
  if (o.stats || record) {
    out << (g_interrupted ? "interrupted; " : "") << "session summary:\n";
    printStats(out, s, 100.0 * (t.cpu - t.cpu0) / (t.end - t.start), t.rss, onDisk);
    if (t.rssAtMinute > 0.0) {
      char line[200];
      std::snprintf(line, sizeof line,
                    "  after the first minute: resident %.1f -> %.1f MB (%+.1f %%), CPU %.1f %% of "
                    "one core\n",
                    t.rssAtMinute, t.rss, 100.0 * (t.rss - t.rssAtMinute) / t.rssAtMinute,
                    100.0 * (t.cpu - t.cpuAtMinute) / (t.end - t.minuteTime));
      out << line;
    }
  }
  if (!where.empty()) {
    if (!onDisk) {
      err << "armtrack-cli: error: the recording cannot be read back: " << unreadable << "\n";
      return 1;
    }
    out << "recorded " << *onDisk << " rows in " << where << "\n";
    const std::uint64_t handed = s.rowsToRecord;
    if (*onDisk < handed) {
      err << "armtrack-cli: error: the recording is incomplete: " << handed - *onDisk << " of "
          << handed << " rows were lost"
          << (s.recorderError.empty() ? std::string() : " (" + s.recorderError + ")") << "\n";
      return 1;
    }
    if (finishFailed || analysisFailed) return 1;
    if (!s.recorderError.empty())
      err << "note: writing the recording failed for a while (" << s.recorderError
          << ") and then went on; no row was lost\n";
  }
  return 0;
}

int runSession(const std::string& command, const std::vector<std::string>& args, bool record,
               std::ostream& out, std::ostream& err) {
  const Args a(command, args, kSessionOptions);
  if (a.help()) {
    out << (record ? kRecordHelp : kLiveHelp);
    return 0;
  }
  SessionSetup setup = parseSession(a, record);
  RecordsTarget target;  // outlives the session, whose sink refers to it
  if (setup.toDb) prepareRecordsTarget(a, setup, target, out);

  QtApp qt;
  app::PluginRegistry registry;
  registry.load(pluginFolders(a));
  session::Session session(setup.params);
  if (!addDevices(setup.o, registry, session, target.devicesUsed, err)) return 1;
  if (const QString why = session.start(); !why.isEmpty()) {
    err << "armtrack-cli: error: " << why.toStdString() << "\n";
    return 1;
  }
  const RunTimes times = runUntilDone(session, setup.o, out, err);
  return finishRun(setup, target, session.stats(), times, record, out, err);
}

}  // namespace

int devicesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&) {
  const Args a("devices", args, {{"--plugins", true}});
  if (a.help()) {
    out << kDevicesHelp;
    return 0;
  }
  if (!a.positionals().empty()) a.fail("unexpected argument '" + a.positionals()[0] + "'");
  QtApp qt;
  app::PluginRegistry registry;
  registry.load(pluginFolders(a));
  for (const app::PluginRecord& r : registry.records()) {
    if (!r.loaded) continue;
    devices::DevicePlugin* p = registry.plugin(r.name);
    out << r.name.toStdString() << ": " << p->description().toStdString() << "\n";
    for (const QString& line : p->optionsHelp().split(u'\n'))
      out << "    " << line.toStdString() << "\n";
    out << "    (" << r.file.toStdString() << ")\n";
  }
  for (const app::PluginRecord& r : registry.records())
    if (!r.loaded)
      out << "refused " << r.file.toStdString() << ": " << r.refusal.toStdString() << "\n";
  if (registry.names().isEmpty()) out << "no device plugins found\n";
  return 0;
}

int recordCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  return runSession("record", args, true, out, err);
}

int liveCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  return runSession("live", args, false, out, err);
}

}  // namespace armtrack::cli
