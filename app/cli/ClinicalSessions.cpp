// armtrack-cli session, export and audit: recordings in the records (docs/cli.md).
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include "app/cli/Batch.h"
#include "app/cli/Clinical.h"
#include "app/cli/ClinicalContext.h"
#include "app/cli/CsvOutput.h"
#include "app/cli/ImportPipeline.h"
#include "app/cli/SessionBatch.h"
#include "app/cli/Text.h"
#include "core/kinematics/ClinicalAngles.h"
#include "core/storage/SessionAnalysis.h"
#include "core/storage/TextRules.h"

namespace armtrack::cli {

namespace {

constexpr std::string_view kSessionHelp =
    R"(Usage: armtrack-cli session <import|reestimate|list|show> [options]

  session import REC.csv --patient CODE [--protocol NAME]
                            store a recording (CSV + sidecar) losslessly as a complete session,
                            estimate its joint angles and store them with its clinical metrics;
                            prints the new session id
  session reestimate ID [--filter ekf|ukf] [--method A|B|C] [--no-optical]
                            estimate the stored recording again (the session's filter settings,
                            else the defaults, with these overrides) and store the estimates and
                            metrics as a new version; earlier versions are kept. Overrides become
                            the session's filter settings. Prints the version
  session reestimate ID... | --patient CODE [--jobs N] [options as above]
                            several sessions (or every finished session of a patient) in
                            parallel, N at a time (default: every core), with a progress line and
                            a summary table; a session that fails is reported and does not stop
                            the others (exit status 1)
  session list --patient CODE [--json]
  session show ID [--json]  id, patient, status (complete, interrupted or recording), duration_s,
                            samples (rows with IMU data), rows, chunks, stored_bytes, devices,
                            filter_settings, setting (clinic or home), a home session's
                            pain_score, patient_comment and home_summary, and the newest
                            metrics: per clinical angle, repetitions, sparc, ldlj, trunk
                            (largest trunk flexion, lateral bending, axial rotation and
                            shoulder displacement; null where not measured), estimate_version
                            (docs/cli.md)

--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD).
)";

constexpr std::string_view kAuditHelp =
    R"(Usage: armtrack-cli audit [--json] --user ADMIN
       armtrack-cli audit --verify [--expect ID:HASH] [--json] --user ADMIN

The audit log: who created, changed, viewed or exported what, and when; failed sign-ins and
refused actions (administrators only). One entry a line, tab-separated: time, account, action,
object type, object, detail; control characters in them are shown escaped (\t, \n, \xHH, \\).

  --verify          check the log's hash chain instead of printing it: each entry's hash over
                    its content and the hash of the entry before. Prints the number of entries
                    and the newest entry as ID:HASH: keep that line elsewhere (on paper, in
                    another system). Exit status 1 at a broken link, naming the first entry that
                    does not fit and how (edited, deleted, inserted)
  --expect ID:HASH  with --verify: also check that entry ID still has that hash, as kept before.
                    A log rewritten from some entry on with every later hash recomputed, or cut
                    off at the end, has no broken link; this shows it

--db URL as for every database command (password: ARMTRACK_PASSWORD).
)";

/// A stored value as one field of a line of text output (storage::escapedForLine).
std::string line(const QString& value) {
  return ss(storage::escapedForLine(value));
}

/// A JSON column's object (empty when the text is not one).
QJsonObject objectOf(const QString& json) {
  return QJsonDocument::fromJson(json.toUtf8()).object();
}

QJsonObject sessionJson(const storage::SessionInfo& s) {
  return QJsonObject{{"id", s.id},
                     {"patient", s.patientCode},
                     {"status", s.status},
                     {"started_at", s.startedAt},
                     {"duration_s", s.durationS},
                     {"samples", s.imuSamples},
                     {"rows", s.sampleRows},
                     {"chunks", s.chunks},
                     {"stored_bytes", s.storedBytes},
                     {"protocol", s.protocolName},
                     {"devices", objectOf(s.devicesJson)},
                     {"filter_settings", objectOf(s.filterJson)},
                     {"notes", s.notes},
                     {"setting", s.setting},
                     {"pain_score", s.painScore ? QJsonValue(*s.painScore) : QJsonValue()},
                     {"patient_comment", s.patientComment},
                     {"home_summary", objectOf(s.homeSummaryJson)},
                     {"analysis", s.analysis},
                     {"analysis_note", s.analysisNote}};
}

// The status as a person reads it: a complete session whose analysis is not stored says so.
std::string statusText(const storage::SessionInfo& s) {
  std::string text = ss(s.status);
  if (s.analysis == storage::kAnalysisPending && s.status == storage::kStatusComplete)
    text += " (analysis pending)";
  else if (s.analysis == storage::kAnalysisFailed)
    text += " (cannot be analysed)";
  return text;
}

// Estimates the session and stores its metrics, reporting on err.
storage::AnalysisResult analyse(storage::ClinicalStore& store, qint64 id,
                                const storage::AnalysisOptions& base, const std::string& command,
                                std::ostream& err) {
  storage::AnalysisOptions options = base;
  const bool reporting = store.session(id).sampleRows > static_cast<qint64>(kProgressRows);
  int nextPercent = 10;
  options.progress = [&](int p) {
    for (; reporting && p >= nextPercent && nextPercent <= 100; nextPercent += 10)
      err << "progress: " << nextPercent << "%\n";
  };
  const storage::AnalysisResult r = storage::analyseSession(store, id, options);
  describeAnalysis(r, command, err);
  return r;
}

}  // namespace

void describeAnalysis(const storage::AnalysisResult& r, const std::string& command,
                      std::ostream& err) {
  const QJsonObject& m = r.metricsJson;
  const QJsonObject reps = m["repetitions"].toObject();
  err << command << ": estimates and metrics version " << r.estimateVersion << " ("
      << (r.settings.filter == FilterKind::Ekf ? "EKF" : "UKF") << ", method "
      << methodName(r.settings.model) << ", "
      << (r.stats.opticalUsed ? "optical fused" : "no optical data fused") << ", "
      << r.settingsSource.toStdString() << " settings): " << reps["count"].toInt()
      << " repetitions (" << reps["partial"].toInt() << " partial) on "
      << ss(reps["primary_angle"].toString()) << ", SPARC "
      << (m["sparc"].isDouble() ? fixed(m["sparc"].toDouble(), 2) : std::string("-")) << ", LDLJ "
      << (m["ldlj"].isDouble() ? fixed(m["ldlj"].toDouble(), 2) : std::string("-")) << "\n";
}

namespace {

int sessionImport(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("session import", rest, withDb({{"--patient", true}, {"--protocol", true}}));
  if (a.help()) return out << kSessionHelp, 0;
  const std::string csv = a.single("recording");
  const std::string patient = a.required("--patient");
  ClinicalContext c(a, {}, true);
  const PipelinedImport imported =
      importAndAnalyse(c, csv, qs(patient), qs(a.value("--protocol").value_or("")), err);
  const qint64 id = imported.id;
  for (const std::string& w : imported.report.warnings)
    err << "warning: " << csv << ": " << w << "\n";
  if (const TimeGaps& g = imported.report.gaps; g.count > 0)
    err << "session import: the recording has " << g.count << " gap(s) in time, "
        << fixed(g.totalSeconds, 1) << " s in all; the longest, " << fixed(g.longestSeconds, 1)
        << " s, after t = " << fixed(g.longestFromT, 3) << " s (line " << g.longestLine
        << "); they are stored as they are, and the analysis restarts after each\n";
  const storage::SessionInfo s = c.store().session(id);
  err << "session import: " << s.sampleRows << " rows in " << s.chunks << " chunks, "
      << s.storedBytes << " bytes stored"
      << (s.status == storage::kStatusInterrupted
              ? std::string(" as an interrupted session (the file ends early)")
              : std::string())
      << "\n";
  // The recording is stored whatever happens next: its id is printed even when it cannot be
  // analysed, with what to do about it.
  bool analysed = true;
  if (imported.analysis) {
    describeAnalysis(*imported.analysis, "session import", err);
  } else if (imported.analysisError) {
    try {
      std::rethrow_exception(imported.analysisError);
    } catch (const storage::StorageError& e) {
      analysed = reportAnalysisFailure(id, e, err);
    } catch (const std::exception& e) {
      analysed = reportAnalysisFailure(
          id, storage::StorageError(storage::StorageError::Kind::Io, e.what()), err);
    }
  } else {
    analysed = analyseNewSession(c.store(), id, "session import", err);
  }
  out << id << "\n";
  return analysed ? 0 : 1;
}

int sessionReestimate(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("session reestimate", rest,
               withDb({{"--filter", true},
                       {"--method", true},
                       {"--no-optical", false},
                       {"--patient", true},
                       {"--jobs", true}}));
  if (a.help()) return out << kSessionHelp, 0;
  const bool batch = a.positionals().size() > 1 || a.flag("--patient") || a.flag("--jobs");
  std::vector<qint64> ids;
  if (batch) {
    if (a.flag("--patient") && !a.positionals().empty())
      a.fail("give session ids or --patient CODE, not both");
    for (const std::string& text : a.positionals()) ids.push_back(sessionIdFrom(a, text));
  } else {
    ids.push_back(sessionIdArgument(a));
  }
  unsigned threads = defaultBatchThreads();
  if (a.flag("--jobs")) {
    const std::uint64_t j = a.integer("--jobs", threads);
    if (j < 1 || j > 1024) a.fail("--jobs: must be between 1 and 1024");
    threads = static_cast<unsigned>(j);
  }
  storage::AnalysisOptions options;
  if (const auto f = a.value("--filter")) {
    if (*f == "ekf")
      options.filter = FilterKind::Ekf;
    else if (*f == "ukf")
      options.filter = FilterKind::Ukf;
    else
      a.fail("--filter: expected ekf or ukf, got " + inQuotes(*f));
  }
  if (const auto m = a.value("--method")) {
    try {
      options.model = parseMethod(*m);
    } catch (const std::invalid_argument&) {
      a.fail("--method: expected A, B or C, got " + inQuotes(*m));
    }
  }
  options.noOptical = a.flag("--no-optical");
  ClinicalContext c(a, {}, true, /*runPending=*/false);
  if (batch) {
    if (const auto patient = a.value("--patient")) {
      // Every session with a recording; one still being recorded is left to its recorder.
      for (const storage::SessionInfo& s : c.store().listSessions(qs(*patient)))
        if (s.status != storage::kStatusRecording) ids.push_back(s.id);
      if (ids.empty()) {
        err << "session reestimate: patient " << *patient << " has no finished sessions\n";
        return 0;
      }
    }
    return reestimateSessions(c, ids, threads, options, out, err);
  }
  const qint64 id = ids.front();
  const storage::AnalysisResult r = analyse(c.store(), id, options, "session reestimate", err);
  // What was chosen here becomes the session's filter settings: later analyses and session show
  // use them (the calibration the session was recorded with is kept).
  if (options.filter || options.model || options.noOptical)
    c.store().updateSessionFilterSettings(
        id, QString::fromUtf8(QJsonDocument(storage::filterSettingsJson(
                                                r.settings, c.store().session(id).filterJson))
                                  .toJson(QJsonDocument::Compact)));
  out << r.estimateVersion << "\n";
  return 0;
}

int sessionList(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("session list", rest, withDb({{"--patient", true}, {"--json", false}}));
  if (a.help()) return out << kSessionHelp, 0;
  const std::string patient = a.required("--patient");
  ClinicalContext c(a, {}, true);
  QJsonArray list;
  for (const storage::SessionInfo& s : c.store().listSessions(qs(patient))) {
    if (!a.flag("--json"))
      out << s.id << "\t" << ss(s.startedAt) << "\t" << statusText(s) << "\t" << s.durationS
          << " s\t" << ss(s.protocolName) << "\n";
    list.append(sessionJson(s));
  }
  if (a.flag("--json")) printJson(out, QJsonDocument(list));
  return 0;
}

// The metrics fields of `session show --json` (null when the session was never analysed).
void addMetrics(QJsonObject& o, const std::optional<QJsonObject>& m) {
  const auto field = [&](const char* key) { return m ? m->value(key) : QJsonValue(); };
  o.insert("metrics", m ? m->value("angles") : QJsonValue());
  o.insert("repetitions", field("repetitions"));
  o.insert("sparc", field("sparc"));
  o.insert("ldlj", field("ldlj"));
  // null, not absent, for metrics stored before the trunk was measured
  o.insert("trunk", m && m->contains("trunk") ? m->value("trunk") : QJsonValue());
  o.insert("estimate_version", field("estimate_version"));
}

// "trunk: flexion 18.1 deg, lateral 9.0 deg, rotation 8.9 deg, shoulder 17.6 cm" and the
// repetitions made with compensation; "-" for a value not measured. Nothing when none was.
void printTrunk(std::ostream& out, const QJsonObject& m) {
  const std::optional<TrunkCompensation> t = storage::trunkCompensationFromJson(m);
  if (!t || !storage::measured(t->session)) return;
  const auto value = [](const std::optional<double>& v, const char* unit) {
    return v ? fixed(*v, 1) + " " + unit : std::string("-");
  };
  const TrunkExtremes& x = t->session;
  out << "trunk (largest): flexion " << value(x.maxFlexionDeg, "deg") << ", lateral bending "
      << value(x.maxLateralDeg, "deg") << ", axial rotation " << value(x.maxRotationDeg, "deg")
      << ", shoulder displacement " << value(x.maxShoulderDisplacementCm, "cm") << "\n";
  if (t->repetitionsWithCompensation) {
    const QJsonValue limit = m["trunk"].toObject()["flexion_limit_deg"];
    out << "repetitions with trunk compensation: " << *t->repetitionsWithCompensation << " of "
        << t->repetitions.size();
    if (limit.isDouble()) out << " (flexion over " << fixed(limit.toDouble(), 1) << " deg)";
    out << "\n";
  }
}

// The metrics as a Markdown table and a few lines.
void printMetrics(std::ostream& out, const QJsonObject& m) {
  out << "\nmetrics (estimates version " << m["estimate_version"].toInt() << "):\n\n"
      << "| angle | min (deg) | max (deg) | ROM (deg) | peak velocity (deg/s) | mean velocity "
         "(deg/s) | movement time (s) |\n|---|---:|---:|---:|---:|---:|---:|\n";
  const QJsonObject angles = m["angles"].toObject();
  const auto cell = [](const QJsonValue& v, int decimals) {
    return v.isDouble() ? fixed(v.toDouble(), decimals) : std::string("-");
  };
  for (const ClinicalAngleInfo& info : clinicalAngleInfo()) {
    const QJsonObject a = angles[QString::fromUtf8(info.key.data(), info.key.size())].toObject();
    out << "| " << info.name << " | " << cell(a["min_deg"], 1) << " | " << cell(a["max_deg"], 1)
        << " | " << cell(a["rom_deg"], 1) << " | " << cell(a["peak_velocity_deg_s"], 1) << " | "
        << cell(a["mean_velocity_deg_s"], 1) << " | " << cell(a["movement_time_s"], 2) << " |\n";
  }
  const QJsonObject reps = m["repetitions"].toObject();
  out << "\nrepetitions: " << reps["count"].toInt() << " (" << reps["partial"].toInt()
      << " partial) on " << ss(reps["primary_angle"].toString()) << "\n";
  for (const QJsonValue& v : reps["list"].toArray()) {
    const QJsonObject r = v.toObject();
    out << "  " << fixed(r["start_s"].toDouble(), 2) << "-" << fixed(r["end_s"].toDouble(), 2)
        << " s: " << fixed(r["excursion_deg"].toDouble(), 1) << " deg"
        << (r["partial"].toBool() ? " (partial)" : "");
    const QJsonObject trunk = r["trunk"].toObject();
    if (trunk["max_flexion_deg"].isDouble())
      out << ", trunk flexion " << fixed(trunk["max_flexion_deg"].toDouble(), 1) << " deg";
    if (trunk["max_shoulder_displacement_cm"].isDouble())
      out << ", shoulder " << fixed(trunk["max_shoulder_displacement_cm"].toDouble(), 1) << " cm";
    if (trunk["compensated"].toBool()) out << " (trunk compensation)";
    out << "\n";
  }
  out << "SPARC: " << cell(m["sparc"], 2) << "\nLDLJ: " << cell(m["ldlj"], 2) << "\n";
  printTrunk(out, m);
}

int sessionShow(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("session show", rest, withDb({{"--json", false}}));
  if (a.help()) return out << kSessionHelp, 0;
  const qint64 id = sessionIdArgument(a);
  ClinicalContext c(a, {}, true);
  const storage::SessionInfo s = c.store().session(id);
  const std::optional<QJsonObject> metrics = storage::latestMetricsJson(c.store(), id);
  c.store().audit("view", "session", QString::number(id));
  if (a.flag("--json")) {
    QJsonObject o = sessionJson(s);
    addMetrics(o, metrics);
    printJson(out, QJsonDocument(o));
    return 0;
  }
  out << "session " << s.id << "\npatient: " << ss(s.patientCode) << "\nstatus: " << statusText(s)
      << "\nstarted: " << ss(s.startedAt) << "\nduration: " << s.durationS
      << " s\nsamples: " << s.imuSamples << " (rows " << s.sampleRows << ", " << s.chunks
      << " chunks, " << s.storedBytes << " bytes)\nprotocol: " << ss(s.protocolName)
      << "\ndevices: " << ss(QStringList(objectOf(s.devicesJson).keys()).join(", "))
      << "\nfilter settings: "
      << (objectOf(s.filterJson).isEmpty()
              ? std::string("none (the defaults)")
              : ss(QString::fromUtf8(
                    QJsonDocument(objectOf(s.filterJson)).toJson(QJsonDocument::Compact))))
      << "\nnotes: " << ss(s.notes) << "\nrecorded at: " << ss(s.setting) << "\n";
  if (s.setting == storage::kSettingHome)
    out << "pain score: " << (s.painScore ? std::to_string(*s.painScore) : std::string("-"))
        << "\npatient's comment: " << ss(s.patientComment) << "\n";
  if (s.analysis == storage::kAnalysisFailed)
    out << "analysis: failed: " << ss(s.analysisNote) << "\n";
  if (metrics)
    printMetrics(out, *metrics);
  else
    out << "\nmetrics: none (not analysed; see 'session reestimate')\n";
  return 0;
}

}  // namespace

bool analyseNewSession(storage::ClinicalStore& store, qint64 id, const std::string& command,
                       std::ostream& err) {
  if (store.user().role == storage::Role::Home) {
    err << command << ": not analysed (a home account does not estimate sessions); it will be "
        << "analysed when a therapist next uses ArmTrack, or with 'session reestimate " << id
        << "'\n";
    return true;
  }
  try {
    analyse(store, id, {}, command, err);
    return true;
  } catch (const storage::StorageError& e) {
    return reportAnalysisFailure(id, e, err);
  }
}

bool reportAnalysisFailure(qint64 id, const storage::StorageError& e, std::ostream& err) {
  using Kind = storage::StorageError::Kind;
  if (e.kind() == Kind::Usage || e.kind() == Kind::Corrupt) {
    // The recording itself cannot be analysed: the session says so (analysis "failed").
    err << "warning: session " << id << " is stored but cannot be analysed: " << e.what() << "\n";
    return true;
  }
  // A lock, a full disk, a lost server: nothing of the analysis was kept and it stays pending,
  // so the next command runs it again.
  err << "armtrack-cli: error: session " << id
      << " is stored, but its analysis failed: " << e.what()
      << "; it stays pending and runs again with the next command (or 'session "
      << "reestimate " << id << "')\n";
  return false;
}

void analysePendingSessions(storage::ClinicalStore& store, std::ostream& err) {
  if (store.user().role == storage::Role::Home) return;
  for (const qint64 id : store.pendingAnalyses()) {
    err << "session " << id << ": its analysis had not been done (the program that stored it "
        << "ended first); analysing it now\n";
    if (!analyseNewSession(store, id, "analysis of session " + std::to_string(id), err)) return;
  }
}

int sessionCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty()) throw UsageError("session", "missing subcommand");
  const std::string& sub = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (sub == "--help" || sub == "-h") return out << kSessionHelp, 0;
  if (sub == "import") return sessionImport(rest, out, err);
  if (sub == "reestimate") return sessionReestimate(rest, out, err);
  if (sub == "list") return sessionList(rest, out, err);
  if (sub == "show") return sessionShow(rest, out, err);
  throw UsageError("session", "unknown subcommand '" + sub + "'");
}

namespace {

int auditVerify(const Args& a, ClinicalContext& c, std::ostream& out) {
  std::optional<storage::AuditAnchor> expect;
  if (const std::optional<std::string> text = a.value("--expect")) {
    expect = storage::AuditAnchor::parse(qs(*text));
    if (!expect)
      a.fail("--expect: must be ID:HASH as 'audit --verify' printed it, got '" + *text + "'");
  }
  const storage::AuditChainReport r = c.store().verifyAuditLog(expect);
  if (a.flag("--json")) {
    printJson(out, QJsonDocument(QJsonObject{
                       {"entries", r.entries},
                       {"intact", r.intact()},
                       {"newest", r.newest ? QJsonValue(r.newest->text()) : QJsonValue()},
                       {"broken_at", r.brokenAt > 0 ? QJsonValue(r.brokenAt) : QJsonValue()},
                       {"broken_links", r.brokenLinks},
                       {"problem", r.problem},
                       {"expected", expect ? QJsonValue(expect->text()) : QJsonValue()},
                       {"expected_problem", r.anchorProblem},
                       {"triggers_problem", r.guardProblem}}));
  } else {
    out << "audit log: " << r.entries << " entries, hash chain "
        << (r.brokenAt == 0 ? "intact" : "broken") << "\n";
    if (r.newest)
      out << "newest entry (keep this line elsewhere; 'audit --verify --expect ID:HASH' checks it "
             "later): "
          << ss(r.newest->text()) << "\n";
    if (expect && r.anchorProblem.isEmpty())
      out << "entry " << expect->id << " still has the hash kept\n";
  }
  if (r.intact()) return 0;
  QStringList problems;
  if (r.brokenAt != 0)
    problems << r.problem + " (" + QString::number(r.brokenLinks) + " broken link(s))";
  if (!r.anchorProblem.isEmpty()) problems << r.anchorProblem;
  if (!r.guardProblem.isEmpty()) problems << r.guardProblem;
  throw std::runtime_error(
      "the audit log of " + ss(c.db().url().display()) +
      " was changed outside ArmTrack: " + ss(problems.join("; ")) +
      ". ArmTrack never changes or deletes an entry: keep this database as evidence and compare "
      "it with a backup ('audit --json' on both)");
}

}  // namespace

int auditCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&) {
  const Args a("audit", args, withDb({{"--json", false}, {"--verify", false}, {"--expect", true}}));
  if (a.help()) return out << kAuditHelp, 0;
  if (a.value("--expect") && !a.flag("--verify")) a.fail("--expect goes with --verify");
  ClinicalContext c(a, {}, true);
  if (a.flag("--verify")) return auditVerify(a, c, out);
  QJsonArray list;
  for (const storage::AuditEntry& e : c.store().auditLog()) {
    if (!a.flag("--json"))
      out << line(e.at) << "\t" << line(e.userName) << "\t" << line(e.action) << "\t"
          << line(e.objectType) << "\t" << line(e.objectId) << "\t" << line(e.detail) << "\n";
    list.append(QJsonObject{{"at", e.at},
                            {"user", e.userName},
                            {"action", e.action},
                            {"object_type", e.objectType},
                            {"object_id", e.objectId},
                            {"detail", e.detail}});
  }
  if (a.flag("--json")) printJson(out, QJsonDocument(list));
  return 0;
}

}  // namespace armtrack::cli
