// The clinical-records commands of armtrack-cli: db, user, patient, protocol, session and export
// (docs/cli.md, docs/storage.md). Each opens the database named by --db (default: armtrack.db in
// the application data folder) and, except `db init`, signs in as --user with the password from
// ARMTRACK_PASSWORD (or a prompt when standard input is a terminal).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace armtrack::cli {

/// Each takes the words after its command name. Throw UsageError for usage mistakes and
/// std::exception (storage::StorageError, RecordingError) for runtime errors.
int dbCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int userCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int patientCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int protocolCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
/// programme: ProgrammeCommands.cpp.
int programmeCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
/// device: DeviceCommands.cpp (home devices that sync, docs/sync.md).
int deviceCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int sessionCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int exportCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
/// report and export: ClinicalOutputs.cpp.
int reportCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int auditCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace armtrack::cli
