#include <iostream>
#include <string>
#include <vector>

#include "app/cli/Cli.h"

int main(int argc, char** argv) {
  std::ios::sync_with_stdio(false);
  const std::vector<std::string> args(argv + (argc > 0 ? 1 : 0), argv + argc);
  const int code = armtrack::cli::runCli(args, std::cout, std::cerr);
  std::cout.flush();
  return code;
}
