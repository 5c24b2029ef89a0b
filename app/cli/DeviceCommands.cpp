// armtrack-cli device: enrolment codes for home devices, and the devices themselves (docs/sync.md,
// docs/cli.md).
#include "app/cli/Clinical.h"
#include "app/cli/ClinicalContext.h"

namespace armtrack::cli {

namespace {

constexpr std::string_view kDeviceHelp =
    R"(Usage: armtrack-cli device <code|list|revoke> [options]

  device code --account NAME [--hours N]
                             a one-time enrolment code for the home account's device, valid
                             for N hours (default 72, at most 720); the home install enters it
                             once to sync with the clinic's armtrack-server (docs/sync.md)
  device list --account NAME the account's devices: number, label, enrolled, last seen, revoked
  device revoke ID           the device may no longer sync (for good)

--db URL and --user NAME as for every database command (password: ARMTRACK_PASSWORD); a
therapist or an administrator.
)";

int deviceCode(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("device code", rest, withDb({{"--account", true}, {"--hours", true}}));
  if (a.help()) return out << kDeviceHelp, 0;
  if (!a.positionals().empty()) a.fail("unexpected argument '" + a.positionals()[0] + "'");
  const std::string account = a.required("--account");
  const std::uint64_t hours = a.integer("--hours", 72);
  if (hours < 1 || hours > 720) a.fail("--hours: must be between 1 and 720");
  ClinicalContext c(a, {}, true);
  const storage::EnrolmentCode code =
      c.store().createEnrolmentCode(qs(account), static_cast<qint64>(hours) * 3600);
  out << ss(code.code) << "\n";
  err << "device code: for " << account << ", valid until " << ss(code.expiresAt)
      << " (UTC), once\n";
  return 0;
}

int deviceList(const std::vector<std::string>& rest, std::ostream& out, std::ostream&) {
  const Args a("device list", rest, withDb({{"--account", true}}));
  if (a.help()) return out << kDeviceHelp, 0;
  const std::string account = a.required("--account");
  ClinicalContext c(a, {}, true);
  for (const storage::DeviceInfo& d : c.store().listDevices(qs(account)))
    out << d.id << "\t" << ss(d.label) << "\t" << ss(d.createdAt) << "\t"
        << (d.lastSeenAt.isEmpty() ? "never" : ss(d.lastSeenAt)) << "\t"
        << (d.revokedAt.isEmpty() ? "active" : "revoked " + ss(d.revokedAt)) << "\n";
  return 0;
}

int deviceRevoke(const std::vector<std::string>& rest, std::ostream& out, std::ostream& err) {
  const Args a("device revoke", rest, withDb({}));
  if (a.help()) return out << kDeviceHelp, 0;
  if (a.positionals().size() != 1) a.fail("give the device's number (device list shows it)");
  const std::optional<double> id = parseDouble(a.positionals()[0]);
  if (!id || *id < 1 || *id != static_cast<double>(static_cast<qint64>(*id)))
    a.fail("not a device number: '" + a.positionals()[0] + "'");
  ClinicalContext c(a, {}, true);
  c.store().revokeDevice(static_cast<qint64>(*id));
  err << "device revoke: device " << static_cast<qint64>(*id) << " may no longer sync\n";
  return 0;
}

}  // namespace

int deviceCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  static const std::vector<std::pair<std::string, SubcommandFn>> table{
      {"code", deviceCode}, {"list", deviceList}, {"revoke", deviceRevoke}};
  return dispatchSubcommand("device", kDeviceHelp, args, out, err, table);
}

}  // namespace armtrack::cli
