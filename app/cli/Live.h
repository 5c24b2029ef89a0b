// armtrack-cli devices / record / live: live sessions from device plugins (docs/cli.md).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace armtrack::cli {

int devicesCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int recordCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int liveCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace armtrack::cli
