// armtrack-cli report and export: a stored session's analysis as PDF reports and as files in the
// open formats (docs/cli.md, docs/reports.md, docs/exports.md).
#include <QDate>
#include <QDir>
#include <QFile>
#include <QGuiApplication>
#include <QTemporaryDir>
#include <memory>

#include "app/cli/Clinical.h"
#include "app/cli/ClinicalContext.h"
#include "app/cli/CsvOutput.h"
#include "app/clinical/Outputs.h"
#include "app/i18n/Language.h"
#include "core/exports/Exports.h"

namespace armtrack::cli {

namespace {

constexpr std::string_view kReportHelp =
    R"(Usage: armtrack-cli report ID --pdf OUT.pdf [--lang CODE] [--overwrite]
       armtrack-cli report --patient CODE --from YYYY-MM-DD --to YYYY-MM-DD --pdf OUT.pdf
                           [--lang CODE] [--overwrite]

The first form writes session ID's report: patient and session details, devices and calibration,
the metrics per clinical angle, joint-angle plots, repetitions, the trunk's compensation (with a
sternum IMU or an optical shoulder), the angles against normative ranges and against the
patient's earlier sessions, the notes. The second writes a progress report:
range of motion per clinical angle against date over the sessions from --from to --to
(inclusive). Every report is written to the audit log.

--lang CODE writes the report in that language (en, de or es); its numbers, dates and units
follow that language's conventions. Without it, the system's locale decides (LANG, LC_ALL),
and a language ArmTrack does not speak gives English.

--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD).
)";

constexpr std::string_view kExportHelp =
    R"(Usage: armtrack-cli export ID --format recording|csv|mot|bids --out PATH [--overwrite]

  recording  PATH and its sidecar in the open recording format, bit for bit as imported or
             recorded
  csv        PATH: time and the five clinical angles (deg) with their standard deviations;
             <PATH stem>_metrics.csv beside it: the metrics per angle and per repetition
  mot        PATH: the clinical angles as an OpenSim motion file (coordinates arm_flex_r ...)
  bids       PATH is a BIDS dataset root: sub-<patient>/ses-<session>/motion/ with one file set
             per tracking system (IMUs, Kinect, estimated joint angles); participants.tsv says
             whose data each subject holds, and another patient's subject is never added to

csv, mot and bids use the session's newest analysis (session reestimate makes a new one).
No file is replaced without --overwrite, and none of the database's own files (--db, its -wal,
-shm or -journal) ever is. Files are written readable by their owner only (mode 0600).
Every export is written to the audit log. docs/exports.md describes the formats.
--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD).
)";

/// Reports draw text, which needs a QGuiApplication; the command line has no display, so it uses
/// the offscreen platform unless told otherwise. Without a session (a cron job, root on a server)
/// there is no XDG_RUNTIME_DIR either, and Qt would warn about it on every report: the
/// application gets a private one (mode 0700, as Qt requires), removed when it ends.
struct GuiApplication {
  QTemporaryDir runtimeDir{QDir::tempPath() + "/armtrack-runtime-XXXXXX"};
  std::unique_ptr<QGuiApplication> app;
};

std::unique_ptr<GuiApplication> guiApplication() {
  if (QCoreApplication::instance()) return nullptr;
  auto gui = std::make_unique<GuiApplication>();
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR") && gui->runtimeDir.isValid()) {
    QFile::setPermissions(gui->runtimeDir.path(),
                          QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
    qputenv("XDG_RUNTIME_DIR", QFile::encodeName(gui->runtimeDir.path()));
  }
  static int argc = 1;
  static char name[] = "armtrack-cli";
  static char* argv[] = {name, nullptr};
  gui->app = std::make_unique<QGuiApplication>(argc, argv);
  return gui;
}

/// Before any work: an output that is the --db database's file, or its -wal, -shm or -journal,
/// is refused whatever --overwrite says (app/clinical checks again, for the default database
/// and for every file of a BIDS export, once the database is open).
void refuseDatabaseFiles(const Args& a, const std::vector<std::string>& outputs) {
  if (!a.value("--db")) return;
  const storage::DatabaseUrl url = storage::DatabaseUrl::parse(qs(*a.value("--db")));
  if (url.engine != storage::DatabaseUrl::Engine::Sqlite) return;
  for (const std::string& o : outputs)
    storage::Database::refuseSqliteFile(url.path, qs(o), "the output");
}

int sessionReport(ClinicalContext& c, qint64 id, const std::string& pdf, std::ostream& err) {
  const int pages = clinical::writeSessionReport(c.store(), id, QString::fromStdString(pdf));
  err << "report: session " << id << ", " << pages << " pages, to " << pdf << "\n";
  return 0;
}

int progressReport(ClinicalContext& c, const Args& a, const std::string& pdf, std::ostream& err) {
  const QString code = qs(a.required("--patient"));
  const QString from = qs(a.required("--from")), to = qs(a.required("--to"));
  for (const QString& date : {from, to})
    if (!QDate::fromString(date, Qt::ISODate).isValid() || date.size() != 10)
      a.fail("--from and --to: expected dates as YYYY-MM-DD, got '" + ss(date) + "'");
  if (to < from) a.fail("--to is before --from");
  const reports::ProgressReportData d = clinical::progressReportData(c.store(), code, from, to);
  const int pages = clinical::writeProgressReport(c.store(), d, QString::fromStdString(pdf));
  err << "report: patient " << ss(code) << ", " << d.sessions.size() << " sessions, " << pages
      << " pages, to " << pdf << "\n";
  return 0;
}

}  // namespace

int reportCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Args a("report", args,
               withDb({{"--pdf", true},
                       {"--patient", true},
                       {"--from", true},
                       {"--to", true},
                       {"--lang", true},
                       {"--overwrite", false}}));
  if (a.help()) return out << kReportHelp, 0;
  const QString lang = qs(a.value("--lang").value_or(""));
  if (a.value("--lang") && i18n::shippedLanguageFor(lang).isEmpty())
    a.fail("--lang: ArmTrack has no translation for '" + ss(lang) + "'; choose one of " +
           ss(i18n::shippedLanguageList()));
  const std::string pdf = a.required("--pdf");
  const bool progress = a.value("--patient").has_value();
  if (progress && !a.positionals().empty())
    a.fail("give a session id or --patient with --from and --to, not both");
  if (!progress && (a.value("--from") || a.value("--to")))
    a.fail("--from and --to: only with --patient");
  const qint64 id = progress ? 0 : sessionIdArgument(a);
  refuseDatabaseFiles(a, {pdf});
  checkOutputPath(pdf, a.flag("--overwrite"), /*recording=*/false);
  const std::unique_ptr<GuiApplication> gui = guiApplication();
  const i18n::ScopedLanguage language(lang);  // the words, numbers and dates of the report
  ClinicalContext c(a, {}, true);
  return progress ? progressReport(c, a, pdf, err) : sessionReport(c, id, pdf, err);
}

int exportCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Args a("export", args,
               withDb({{"--format", true}, {"--out", true}, {"--overwrite", false}}));
  if (a.help()) return out << kExportHelp, 0;
  const qint64 id = sessionIdArgument(a);
  const std::string format = a.required("--format");
  const std::string target = a.required("--out");
  if (format != "recording" && format != "csv" && format != "mot" && format != "bids")
    a.fail("--format: must be recording, csv, mot or bids");
  const bool overwrite = a.flag("--overwrite");
  if (format == "recording")
    refuseDatabaseFiles(a, {target, armtrack::sidecarPath(target).string()});
  else if (format == "csv")
    refuseDatabaseFiles(a, {target, metricsCsvPath(target).string()});
  else
    refuseDatabaseFiles(a, {target});
  if (format == "recording" || format == "mot")
    checkOutputPath(target, overwrite, format == "recording");
  if (format == "csv") {
    checkOutputPath(target, overwrite, false);
    checkOutputPath(metricsCsvPath(target).string(), overwrite, false);
  }
  ClinicalContext c(a, {}, true);
  const clinical::ExportSummary r = clinical::exportSession(
      c.store(), id, *clinical::parseExportFormat(format), target, overwrite);
  err << "export: session " << id << (format == "recording" ? " to " : ", ") << r.what << "\n";
  for (const std::string& note : r.notes) err << "  note: " << note << "\n";
  return 0;
}

}  // namespace armtrack::cli
