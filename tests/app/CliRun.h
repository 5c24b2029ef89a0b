// armtrack-cli run in this process (app/cli/Cli.h): its exit status and what it wrote to standard
// output and standard error, for the CLI tests.
#pragma once

#include <QProcess>
#include <QStringList>
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

/// Per-joint RMSE (deg), th0..th5, from the table `estimate` prints when a recording has truth.
inline std::vector<double> reportedRmse(const std::string& report) {
  std::vector<double> rmse;
  std::istringstream in(report);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| th", 0) != 0) continue;
    const auto a = line.find('|', 1), b = line.find('|', a + 1);
    rmse.push_back(std::stod(line.substr(a + 1, b - a - 1)));
  }
  return rmse;
}

/// Runs the armtrack-cli executable at program with args, as a process of its own (reports need
/// a QGuiApplication of their own, which the in-process tests' QCoreApplication rules out),
/// without a desktop session's XDG_RUNTIME_DIR, as a cron job or root on a server runs it.
inline CliResult cliProcess(const QString& program, const QStringList& args) {
  QProcess p;
  QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
  env.remove("XDG_RUNTIME_DIR");
  p.setProcessEnvironment(env);
  p.start(program, args);
  if (!p.waitForFinished(120000)) return {-1, "", "timed out"};
  return {p.exitCode(), p.readAllStandardOutput().toStdString(),
          p.readAllStandardError().toStdString()};
}

}  // namespace armtrack::test
