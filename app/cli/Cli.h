// armtrack-cli: simulate recordings, estimate joint angles, run the paper's studies
// (docs/cli.md). The whole tool is runCli, so tests can drive it in-process.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace armtrack::cli {

/// Runs the tool on args (argv without the program name). Results go to out; diagnostics,
/// warnings, progress and errors to err. Returns 0 on success, 1 on a runtime or input error,
/// 2 on a usage error. Never throws.
int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace armtrack::cli
