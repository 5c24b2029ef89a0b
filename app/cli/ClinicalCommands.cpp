// armtrack-cli db, user, patient and protocol: the records' administration (docs/cli.md).
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <cstdlib>

#include "app/cli/Clinical.h"
#include "app/cli/ClinicalContext.h"
#include "core/storage/TextRules.h"

namespace armtrack::cli {

namespace {

using storage::Database;

/// A stored value as one field of a line of text output: control and direction characters
/// escaped (storage::escapedForLine), so no stored name can forge a line or a field.
std::string line(const QString& value) {
  return ss(storage::escapedForLine(value));
}

constexpr std::string_view kDbHelp = R"(Usage: armtrack-cli db <init|check|migrate|backup> [options]

  db init --admin NAME      create the database and its first administrator (password from
                            ARMTRACK_PASSWORD or a prompt, at least 10 characters)
  db check --user NAME      integrity check, schema version, the audit log's hash chain, and
                            every recording decoded chunk by chunk (with its estimates); lists
                            each damaged session and what is wrong (exit status 1)
  db migrate --user NAME    bring an older schema up to date (administrators; back up first)
  db backup --out FILE --user NAME
                            a consistent copy while others keep working (administrators;
                            SQLite: VACUUM INTO; on PostgreSQL it prints the pg_dump command)

Every subcommand takes --db URL: a SQLite file (a path or sqlite:PATH), or a PostgreSQL
database, postgresql://ROLE@HOST:PORT/DATABASE (its password from ARMTRACK_DB_PASSWORD or
~/.pgpass; docs/storage.md). Default: armtrack.db in the application data folder.
)";

constexpr std::string_view kUserHelp =
    R"(Usage: armtrack-cli user <add|list|disable|enable> [options]

  user add NAME --role admin|therapist|home [--patient CODE] --user ADMIN
                            a new account; its password (at least 10 characters) comes from
                            ARMTRACK_NEW_PASSWORD (or a prompt); a home account needs its
                            patient. Names are unique without regard to case
  user list [--json] --user ADMIN
                            every account, its role and whether it is disabled
  user disable NAME --user ADMIN
                            the account may no longer sign in; its sessions and audit
                            entries keep its name (an administrator cannot disable itself)
  user enable NAME --user ADMIN
                            lets a disabled account sign in again

--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD).
)";

constexpr std::string_view kPatientHelp = R"(Usage: armtrack-cli patient <add|list> [options]

  patient add --code CODE --name NAME [--birth YYYY-MM-DD] [--sex f|m|x]
              [--side left|right|both|none] [--diagnosis TEXT] [--notes TEXT]
  patient list [--json]      (a home account sees only its own patient)
  patient programme CODE [--json]
                             the patient's home programme (as 'programme list')

--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD).
)";

constexpr std::string_view kProtocolHelp =
    R"(Usage: armtrack-cli protocol <add|edit|list|assign> [options]

  protocol add --name NAME --angle KEY --target-min DEG --target-max DEG --reps N
               [--side left|right|either] [--trunk-limit DEG|off]
  protocol edit NAME [--angle KEY] [--target-min DEG] [--target-max DEG] [--reps N]
               [--side left|right|either] [--trunk-limit DEG|off]
                             change what is given, keep the rest
  protocol list [--json]
  protocol assign NAME --patient CODE [--per-week N] [--notes TEXT]
                             put the protocol in the patient's home programme

KEY is a clinical angle such as shoulder_flexion or elbow_flexion. The trunk limit (degrees of
trunk flexion, 1-90; default off): when the patient leans further, the live screen and the home
window say "Keep your back against the chair" and count the repetitions made so.
--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD).
)";

int dbInit(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("db init", rest, withDb({{"--admin", true}}));
  if (a.help()) return out << kDbHelp, 0;
  const std::string admin = a.required("--admin");
  const std::string password = passwordFromUser("the new administrator '" + admin + "'");
  if (password.empty()) a.fail("the administrator's password is empty");
  ClinicalContext c(a, {.create = true, .migrate = false}, false);
  c.store().initialise(qs(admin), password);
  err << "db init: created " << ss(c.db().url().display()) << " (schema version "
      << c.db().schemaVersion() << ") with administrator '" << admin << "'\n";
  return 0;
}

int dbCheck(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("db check", rest, withDb({}));
  if (a.help()) return out << kDbHelp, 0;
  ClinicalContext c(a, {}, true, /*runPending=*/false);
  const QString verdict = c.db().integrityCheck();
  if (verdict != "ok") throw std::runtime_error("integrity check failed: " + ss(verdict));
  const storage::AuditChainReport audit = storage::verifyAuditChain(c.db());
  const storage::RecordsCheckReport records = c.store().checkRecords();
  const std::string where = ss(c.db().url().display());
  std::string recorded;
  if (!records.beingRecorded.empty()) {
    recorded = "; being recorded now, not checked:";
    for (const qint64 id : records.beingRecorded) recorded += " " + std::to_string(id);
  }
  if (audit.intact() && records.damaged.empty()) {
    out << "ok: " << where << ", schema version " << c.db().schemaVersion() << ", "
        << c.store().interruptedOnOpen() << " interrupted recording(s) marked\n"
        << "audit log: " << audit.entries << " entries, hash chain intact\n"
        << "recordings: " << records.sessionsChecked << " session(s) checked, none damaged"
        << recorded << "\n";
    return 0;
  }
  // Every problem on standard output, one a line; the error line sums them up.
  std::vector<std::string> found;
  if (audit.brokenAt != 0) {
    out << "audit log: " << ss(audit.problem) << " (" << audit.brokenLinks << " broken link(s) in "
        << audit.entries << " entries)\n";
    found.push_back("the audit log was changed outside ArmTrack (first at entry " +
                    std::to_string(audit.brokenAt) +
                    "): keep this database as evidence and compare it with a backup");
  }
  if (!audit.guardProblem.isEmpty()) {
    out << "audit log: " << ss(audit.guardProblem) << "\n";
    found.push_back(
        "the audit log's append-only triggers were removed outside ArmTrack: keep "
        "this database as evidence and compare it with a backup, which has them");
  }
  if (!records.damaged.empty()) {
    std::string ids;
    for (const storage::SessionDamage& d : records.damaged) {
      for (const QString& problem : d.problems)
        out << "session " << d.sessionId << ": damaged: " << ss(problem) << "\n";
      ids += (ids.empty() ? "" : ", ") + std::to_string(d.sessionId);
    }
    found.push_back(std::to_string(records.damaged.size()) + " damaged session(s) (" + ids +
                    ") of " + std::to_string(records.sessionsChecked) +
                    " checked: restore a backup made before the damage" + recorded);
  }
  std::string summary;
  for (const std::string& f : found) summary += (summary.empty() ? "" : "; ") + f;
  throw std::runtime_error("db check: " + where + ": " + summary +
                           " (each problem is listed on standard output)");
}

int dbMigrate(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("db migrate", rest, withDb({}));
  if (a.help()) return out << kDbHelp, 0;
  ClinicalContext c(a, {.create = false, .migrate = true}, true);
  c.store().confirmMigration(c.db().migrationsApplied());  // administrators; audited
  out << "schema version " << c.db().schemaVersion() << " (" << c.db().migrationsApplied()
      << " step(s) applied)\n";
  return 0;
}

int dbBackup(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("db backup", rest, withDb({{"--out", true}}));
  if (a.help()) return out << kDbHelp, 0;
  const std::string target = a.required("--out");
  ClinicalContext c(a, {}, true, /*runPending=*/false);
  c.store().backup(qs(target));  // administrators; audited
  err << "db backup: wrote " << target << "\n";
  return 0;
}

int userAdd(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("user add", rest, withDb({{"--role", true}, {"--patient", true}}));
  if (a.help()) return out << kUserHelp, 0;
  const std::string name = a.single("account name");
  const auto role = storage::parseRole(qs(a.required("--role")));
  if (!role) a.fail("--role: must be admin, therapist or home");
  ClinicalContext c(a, {}, true);
  std::string password;
  if (const char* env = std::getenv("ARMTRACK_NEW_PASSWORD"))
    password = env;
  else
    password = passwordFromUser("the new account '" + name + "' (ARMTRACK_NEW_PASSWORD)");
  c.store().addUser(qs(name), *role, password, qs(a.value("--patient").value_or("")));
  err << "user add: " << name << " (" << ss(storage::roleName(*role)) << ")\n";
  return 0;
}

int userList(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("user list", rest, withDb({{"--json", false}}));
  if (a.help()) return out << kUserHelp, 0;
  ClinicalContext c(a, {}, true);
  QJsonArray list;
  for (const storage::User& u : c.store().listUsers()) {
    if (!a.flag("--json"))
      out << line(u.name) << "\t" << ss(storage::roleName(u.role))
          << (u.disabled ? "\tdisabled" : "") << "\n";
    list.append(QJsonObject{
        {"name", u.name}, {"role", storage::roleName(u.role)}, {"disabled", u.disabled}});
  }
  if (a.flag("--json")) printJson(out, QJsonDocument(list));
  return 0;
}

int userSetDisabled(const char* command, bool disabled, const std::vector<std::string>& rest,
                    std::ostream& out, std::ostream& err) {
  const Args a(command, rest, withDb({}));
  if (a.help()) return out << kUserHelp, 0;
  const std::string name = a.single("account name");
  ClinicalContext c(a, {}, true);
  c.store().setUserDisabled(qs(name), disabled);
  err << command << ": " << line(qs(name)) << "\n";
  return 0;
}

int userDisable(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  return userSetDisabled("user disable", true, rest, out, err);
}

int userEnable(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  return userSetDisabled("user enable", false, rest, out, err);
}

int patientAdd(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("patient add", rest,
               withDb({{"--code", true},
                       {"--name", true},
                       {"--birth", true},
                       {"--sex", true},
                       {"--side", true},
                       {"--diagnosis", true},
                       {"--notes", true}}));
  if (a.help()) return out << kPatientHelp, 0;
  storage::Patient p;
  p.code = qs(a.required("--code"));
  p.name = qs(a.required("--name"));
  p.birthDate = qs(a.value("--birth").value_or(""));
  p.sex = qs(a.value("--sex").value_or(""));
  p.affectedSide = qs(a.value("--side").value_or(""));
  p.diagnosis = qs(a.value("--diagnosis").value_or(""));
  p.notes = qs(a.value("--notes").value_or(""));
  ClinicalContext c(a, {}, true);
  c.store().addPatient(p);
  err << "patient add: " << ss(p.code) << "\n";
  return 0;
}

int patientList(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("patient list", rest, withDb({{"--json", false}}));
  if (a.help()) return out << kPatientHelp, 0;
  ClinicalContext c(a, {}, true);
  QJsonArray list;
  for (const storage::Patient& p : c.store().listPatients()) {
    if (!a.flag("--json"))
      out << line(p.code) << "\t" << line(p.name) << "\t" << line(p.birthDate) << "\t"
          << line(p.sex) << "\t" << line(p.affectedSide) << "\n";
    list.append(QJsonObject{{"code", p.code},
                            {"name", p.name},
                            {"birth", p.birthDate},
                            {"sex", p.sex},
                            {"side", p.affectedSide},
                            {"diagnosis", p.diagnosis}});
  }
  if (a.flag("--json")) printJson(out, QJsonDocument(list));
  return 0;
}

int patientProgramme(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("patient programme", rest, withDb({{"--json", false}}));
  if (a.help()) return out << kPatientHelp, 0;
  const std::string code = a.single("patient code");
  ClinicalContext c(a, {}, true);
  listProgramme(c.store(), qs(code), a.flag("--json"), out);
  return 0;
}

int protocolAssign(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("protocol assign", rest,
               withDb({{"--patient", true}, {"--per-week", true}, {"--notes", true}}));
  if (a.help()) return out << kProtocolHelp, 0;
  const std::string name = a.single("protocol name");
  const std::string patient = a.required("--patient");
  const auto perWeek = static_cast<int>(a.integer("--per-week", 0));
  ClinicalContext c(a, {}, true);
  c.store().assignProtocol(qs(patient), qs(name), perWeek, qs(a.value("--notes").value_or("")));
  err << "protocol assign: " << name << " to " << patient << "\n";
  return 0;
}

int protocolAdd(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("protocol add", rest,
               withDb({{"--name", true},
                       {"--angle", true},
                       {"--target-min", true},
                       {"--target-max", true},
                       {"--reps", true},
                       {"--side", true},
                       {"--trunk-limit", true}}));
  if (a.help()) return out << kProtocolHelp, 0;
  storage::Protocol p;
  p.name = qs(a.required("--name"));
  p.angleKey = qs(a.required("--angle"));
  p.targetMinDeg = a.number("--target-min").value_or(0);
  p.targetMaxDeg = a.number("--target-max").value_or(0);
  if (!a.number("--target-min") || !a.number("--target-max"))
    a.fail("--target-min and --target-max are required (deg)");
  p.repetitions = static_cast<int>(a.integer("--reps", 0));
  p.side = qs(a.value("--side").value_or("either"));
  p.trunkLimitDeg = trunkLimitArg(a, "off").value_or(std::nullopt);
  ClinicalContext c(a, {}, true);
  c.store().addProtocol(p);
  err << "protocol add: " << ss(p.name) << "\n";
  return 0;
}

int protocolEdit(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("protocol edit", rest,
               withDb({{"--angle", true},
                       {"--target-min", true},
                       {"--target-max", true},
                       {"--reps", true},
                       {"--side", true},
                       {"--trunk-limit", true}}));
  if (a.help()) return out << kProtocolHelp, 0;
  const std::string name = a.single("protocol name");
  const auto trunk = trunkLimitArg(a, "off");
  ClinicalContext c(a, {}, true);
  storage::Protocol p = c.store().protocol(qs(name));
  if (const auto v = a.value("--angle")) p.angleKey = qs(*v);
  p.targetMinDeg = a.number("--target-min", p.targetMinDeg);
  p.targetMaxDeg = a.number("--target-max", p.targetMaxDeg);
  if (a.value("--reps")) p.repetitions = static_cast<int>(a.integer("--reps", 0));
  if (const auto v = a.value("--side")) p.side = qs(*v);
  if (trunk) p.trunkLimitDeg = *trunk;
  c.store().updateProtocol(p);
  err << "protocol edit: " << ss(p.name) << "\n";
  return 0;
}

int protocolList(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("protocol list", rest, withDb({{"--json", false}}));
  if (a.help()) return out << kProtocolHelp, 0;
  ClinicalContext c(a, {}, true);
  QJsonArray list;
  for (const storage::Protocol& p : c.store().listProtocols()) {
    if (!a.flag("--json")) {
      out << line(p.name) << "\t" << ss(p.angleKey) << "\t" << p.targetMinDeg << "\t"
          << p.targetMaxDeg << "\t" << p.repetitions << "\t" << ss(p.side);
      if (p.trunkLimitDeg) out << "\ttrunk limit " << *p.trunkLimitDeg << " deg";
      out << "\n";
    }
    list.append(QJsonObject{
        {"name", p.name},
        {"angle", p.angleKey},
        {"target_min_deg", p.targetMinDeg},
        {"target_max_deg", p.targetMaxDeg},
        {"repetitions", p.repetitions},
        {"side", p.side},
        {"trunk_limit_deg", p.trunkLimitDeg ? QJsonValue(*p.trunkLimitDeg) : QJsonValue()}});
  }
  if (a.flag("--json")) printJson(out, QJsonDocument(list));
  return 0;
}

}  // namespace

int dbCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  static const std::vector<std::pair<std::string, SubcommandFn>> table{
      {"init", dbInit}, {"check", dbCheck}, {"migrate", dbMigrate}, {"backup", dbBackup}};
  return dispatchSubcommand("db", kDbHelp, args, out, err, table);
}

int userCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  static const std::vector<std::pair<std::string, SubcommandFn>> table{
      {"add", userAdd}, {"list", userList}, {"disable", userDisable}, {"enable", userEnable}};
  return dispatchSubcommand("user", kUserHelp, args, out, err, table);
}

int patientCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  static const std::vector<std::pair<std::string, SubcommandFn>> table{
      {"add", patientAdd}, {"list", patientList}, {"programme", patientProgramme}};
  return dispatchSubcommand("patient", kPatientHelp, args, out, err, table);
}

int protocolCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  static const std::vector<std::pair<std::string, SubcommandFn>> table{{"add", protocolAdd},
                                                                       {"edit", protocolEdit},
                                                                       {"list", protocolList},
                                                                       {"assign", protocolAssign}};
  return dispatchSubcommand("protocol", kProtocolHelp, args, out, err, table);
}

}  // namespace armtrack::cli
