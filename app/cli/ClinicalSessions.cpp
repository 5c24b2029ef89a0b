// armtrack-cli session, export and audit: recordings in the records (docs/cli.md).
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <charconv>

#include "app/cli/Clinical.h"
#include "app/cli/ClinicalContext.h"
#include "app/cli/CsvOutput.h"

namespace armtrack::cli {

namespace {

constexpr std::string_view kSessionHelp =
    R"(Usage: armtrack-cli session <import|list|show> [options]

  session import REC.csv --patient CODE [--protocol NAME]
                            store a recording (CSV + sidecar) losslessly as a complete session;
                            prints the new session id
  session list --patient CODE [--json]
  session show ID [--json]  id, patient, status (complete, interrupted or recording), duration_s,
                            samples (rows with IMU data), rows, chunks, stored_bytes

--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD).
)";

constexpr std::string_view kExportHelp =
    R"(Usage: armtrack-cli export ID --format recording --out PATH [--overwrite]

Writes session ID in the open recording format (PATH and its sidecar), bit for bit as it was
imported or recorded. Every export is written to the audit log. (The csv, mot and bids formats are
not available yet.)

--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD).
)";

constexpr std::string_view kAuditHelp = R"(Usage: armtrack-cli audit [--json] --user ADMIN

The audit log: who created, changed, viewed or exported what, and when (administrators only).
--db URL as for every database command (password: ARMTRACK_PASSWORD).
)";

qint64 sessionId(const Args& a) {
  const std::string text = a.single("session id");
  qint64 id = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), id);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || id <= 0)
    a.fail("session id: expected a positive whole number, got \"" + text + "\"");
  return id;
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
                     {"notes", s.notes}};
}

int sessionImport(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("session import", rest, withDb({{"--patient", true}, {"--protocol", true}}));
  if (a.help()) return out << kSessionHelp, 0;
  const std::string csv = a.single("recording");
  const std::string patient = a.required("--patient");
  ClinicalContext c(a, {}, true);
  const qint64 id =
      c.store().importRecording(csv, qs(patient), qs(a.value("--protocol").value_or("")));
  const storage::SessionInfo s = c.store().session(id);
  err << "session import: " << s.sampleRows << " rows in " << s.chunks << " chunks, "
      << s.storedBytes << " bytes stored\n";
  out << id << "\n";
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
      out << s.id << "\t" << ss(s.startedAt) << "\t" << ss(s.status) << "\t" << s.durationS
          << " s\t" << ss(s.protocolName) << "\n";
    list.append(sessionJson(s));
  }
  if (a.flag("--json")) printJson(out, QJsonDocument(list));
  return 0;
}

int sessionShow(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("session show", rest, withDb({{"--json", false}}));
  if (a.help()) return out << kSessionHelp, 0;
  const qint64 id = sessionId(a);
  ClinicalContext c(a, {}, true);
  const storage::SessionInfo s = c.store().session(id);
  c.store().audit("view", "session", QString::number(id));
  if (a.flag("--json")) {
    printJson(out, QJsonDocument(sessionJson(s)));
    return 0;
  }
  out << "session " << s.id << "\npatient: " << ss(s.patientCode) << "\nstatus: " << ss(s.status)
      << "\nstarted: " << ss(s.startedAt) << "\nduration: " << s.durationS
      << " s\nsamples: " << s.imuSamples << " (rows " << s.sampleRows << ", " << s.chunks
      << " chunks, " << s.storedBytes << " bytes)\nprotocol: " << ss(s.protocolName)
      << "\nnotes: " << ss(s.notes) << "\n";
  return 0;
}

}  // namespace

int sessionCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  if (args.empty()) throw UsageError("session", "missing subcommand");
  const std::string& sub = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (sub == "--help" || sub == "-h") return out << kSessionHelp, 0;
  if (sub == "import") return sessionImport(rest, out, err);
  if (sub == "list") return sessionList(rest, out, err);
  if (sub == "show") return sessionShow(rest, out, err);
  throw UsageError("session", "unknown subcommand '" + sub + "'");
}

int exportCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  const Args a("export", args,
               withDb({{"--format", true}, {"--out", true}, {"--overwrite", false}}));
  if (a.help()) return out << kExportHelp, 0;
  const qint64 id = sessionId(a);
  const std::string format = a.required("--format");
  const std::string target = a.required("--out");
  if (format == "csv" || format == "mot" || format == "bids")
    throw std::runtime_error("export --format " + format +
                             " is not available yet; use --format recording");
  if (format != "recording") a.fail("--format: must be recording, csv, mot or bids");
  checkOutputPath(target, a.flag("--overwrite"), /*recording=*/true);
  ClinicalContext c(a, {}, true);
  c.store().exportRecording(id, target);
  err << "export: session " << id << " to " << target << "\n";
  return 0;
}

int auditCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream&) {
  const Args a("audit", args, withDb({{"--json", false}}));
  if (a.help()) return out << kAuditHelp, 0;
  ClinicalContext c(a, {}, true);
  QJsonArray list;
  for (const storage::AuditEntry& e : c.store().auditLog()) {
    if (!a.flag("--json"))
      out << ss(e.at) << "\t" << ss(e.userName) << "\t" << ss(e.action) << "\t" << ss(e.objectType)
          << "\t" << ss(e.objectId) << "\t" << ss(e.detail) << "\n";
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
