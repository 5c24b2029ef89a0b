// armtrack-cli run in this process (app/cli/Cli.h): its exit status and what it wrote to standard
// output and standard error, for the CLI tests.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "app/cli/Cli.h"

namespace armtrack::test {

struct CliResult {
  int code;
  std::string out, err;
};

/// Runs armtrack-cli with args (the program name left out).
inline CliResult cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = armtrack::cli::runCli(args, out, err);
  return {code, out.str(), err.str()};
}

}  // namespace armtrack::test
