// armtrack-cli programme: a patient's home programme, the exercises the home window guides
// (docs/cli.md, docs/storage.md "Home programmes").
#include <QJsonArray>
#include <QJsonObject>
#include <sstream>

#include "app/cli/Clinical.h"
#include "app/cli/ClinicalContext.h"

namespace armtrack::cli {

namespace {

constexpr std::string_view kProgrammeHelp =
    R"(Usage: armtrack-cli programme <add|list|remove> [options]

  programme add --patient CODE --protocol NAME [--sets N] [--reps N] [--target MIN:MAX]
                [--rest S] [--position N] [--per-week N] [--notes TEXT]
                [--trunk-limit DEG|protocol]
                             put an exercise in the patient's home programme (or replace the
                             one of that protocol): N sets of N repetitions (default: 1 set of
                             the protocol's repetitions), the target range of the protocol's
                             angle in degrees (default: the protocol's), S seconds of rest
                             between sets (default 60), at place N (default: after the last),
                             the trunk limit in degrees of trunk flexion, 1-90: leaning further,
                             the patient is told to keep the back against the chair (default:
                             the protocol's)
  programme list --patient CODE [--json]
                             the exercises in their order
  programme remove --patient CODE --protocol NAME

--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD). Changing a
programme takes a therapist or an administrator; a home account lists its own.
)";

// "MIN:MAX" in degrees, e.g. "30:130" or "-40:60".
std::pair<double, double> parseTarget(const Args& a, const std::string& text) {
  const std::size_t colon = text.find(':', 1);
  if (colon == std::string::npos)
    a.fail("--target: expected MIN:MAX in degrees, e.g. 30:130, got '" + text + "'");
  const auto lo = parseDouble(text.substr(0, colon));
  const auto hi = parseDouble(text.substr(colon + 1));
  if (!lo || !hi) a.fail("--target: expected MIN:MAX in degrees, e.g. 30:130, got '" + text + "'");
  return {*lo, *hi};
}

QJsonValue optionalNumber(const std::optional<double>& v) {
  return v ? QJsonValue(*v) : QJsonValue();
}

int programmeAdd(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("programme add", rest,
               withDb({{"--patient", true},
                       {"--protocol", true},
                       {"--sets", true},
                       {"--reps", true},
                       {"--target", true},
                       {"--rest", true},
                       {"--position", true},
                       {"--per-week", true},
                       {"--notes", true},
                       {"--trunk-limit", true}}));
  if (a.help()) return out << kProgrammeHelp, 0;
  if (!a.positionals().empty()) a.fail("unexpected argument '" + a.positionals()[0] + "'");
  const std::string patient = a.required("--patient");
  storage::ProgrammeItem item;
  item.protocolName = qs(a.required("--protocol"));
  // Range checks are the store's, so the CLI and the GUI refuse the same values; only the
  // integers' parsing is here (a value beyond int is refused, not wrapped).
  const auto whole = [&](const char* name, std::uint64_t fallback) {
    const std::uint64_t v = a.integer(name, fallback);
    if (v > 1'000'000) a.fail(std::string(name) + ": " + std::to_string(v) + " is too large");
    return static_cast<int>(v);
  };
  item.sets = whole("--sets", 1);
  if (a.value("--reps")) item.repetitions = whole("--reps", 0);
  if (const auto t = a.value("--target")) {
    const auto [lo, hi] = parseTarget(a, *t);
    item.targetMinDeg = lo;
    item.targetMaxDeg = hi;
  }
  item.restS = a.number("--rest", 60.0);
  item.position = whole("--position", 0);
  if (a.value("--position") && item.position == 0) a.fail("--position: places start at 1");
  item.sessionsPerWeek = whole("--per-week", 0);
  item.notes = qs(a.value("--notes").value_or(""));
  if (a.value("--trunk-limit") == "off")
    a.fail(
        "--trunk-limit: an exercise takes its protocol's limit or its own; to turn it off, "
        "turn it off in the protocol (protocol edit NAME --trunk-limit off)");
  item.trunkLimitDeg = trunkLimitArg(a, "protocol").value_or(std::nullopt);
  ClinicalContext c(a, {}, true);
  c.store().setProgrammeExercise(qs(patient), item);
  err << "programme add: " << ss(item.protocolName) << " for " << patient << "\n";
  return 0;
}

int programmeList(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("programme list", rest, withDb({{"--patient", true}, {"--json", false}}));
  if (a.help()) return out << kProgrammeHelp, 0;
  const std::string patient = a.required("--patient");
  ClinicalContext c(a, {}, true);
  listProgramme(c.store(), qs(patient), a.flag("--json"), out);
  return 0;
}

int programmeRemove(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("programme remove", rest, withDb({{"--patient", true}, {"--protocol", true}}));
  if (a.help()) return out << kProgrammeHelp, 0;
  const std::string patient = a.required("--patient");
  const std::string protocol = a.required("--protocol");
  ClinicalContext c(a, {}, true);
  c.store().unassignProtocol(qs(patient), qs(protocol));
  err << "programme remove: " << protocol << " from " << patient << "\n";
  return 0;
}

}  // namespace

std::optional<std::optional<double>> trunkLimitArg(const Args& a, std::string_view emptyWord) {
  const std::optional<std::string> text = a.value("--trunk-limit");
  if (!text) return std::nullopt;
  if (*text == emptyWord) return std::optional<double>();
  const std::optional<double> deg = parseDouble(*text);
  if (!deg)
    a.fail("--trunk-limit: expected degrees of trunk flexion (1-90, e.g. 15) or '" +
           std::string(emptyWord) + "', got '" + *text + "'");
  return deg;
}

void listProgramme(storage::ClinicalStore& store, const QString& patientCode, bool json,
                   std::ostream& out) {
  QJsonArray list;
  for (const storage::ProgrammeItem& item : store.programme(patientCode)) {
    const storage::Protocol p = store.protocol(item.protocolName);
    const int reps = storage::effectiveRepetitions(item, p);
    const auto [lo, hi] = storage::effectiveTarget(item, p);
    const std::optional<double> trunk = storage::effectiveTrunkLimit(item, p);
    if (!json) {
      std::ostringstream line;
      line << item.position << "\t" << ss(item.protocolName) << "\t" << ss(p.angleKey) << "\t"
           << item.sets << " x " << reps << "\t" << lo << " to " << hi << " deg\trest "
           << item.restS << " s\t" << item.sessionsPerWeek << "/week\t";
      if (trunk) line << "trunk limit " << *trunk << " deg\t";
      line << ss(item.notes);
      out << line.str() << "\n";
    }
    QJsonObject o{{"position", item.position},
                  {"protocol", item.protocolName},
                  {"angle", p.angleKey},
                  {"sets", item.sets},
                  {"repetitions", reps},
                  {"repetitions_from_protocol", !item.repetitions.has_value()},
                  {"target_min_deg", lo},
                  {"target_max_deg", hi},
                  {"target_from_protocol", !item.targetMinDeg.has_value()},
                  {"rest_s", item.restS},
                  {"sessions_per_week", item.sessionsPerWeek},
                  {"notes", item.notes},
                  {"trunk_limit_deg", optionalNumber(trunk)},
                  {"trunk_limit_from_protocol", !item.trunkLimitDeg.has_value()}};
    list.append(o);
  }
  if (json) printJson(out, QJsonDocument(list));
}

int programmeCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  static const std::vector<std::pair<std::string, SubcommandFn>> table{
      {"add", programmeAdd}, {"list", programmeList}, {"remove", programmeRemove}};
  return dispatchSubcommand("programme", kProgrammeHelp, args, out, err, table);
}

}  // namespace armtrack::cli
