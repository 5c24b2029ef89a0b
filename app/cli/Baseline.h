// The baseline commands of armtrack-cli (docs/baseline.md): `baseline` (the complementary
// estimator over a recording), `simulate --pendulum` (the double pendulum's recording) and
// `study baseline` (the baseline beside the DH filter).
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace armtrack::cli {

/// armtrack-cli baseline IN.csv [--out OUT.csv] ...
int baselineCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// armtrack-cli simulate --pendulum --out REC.csv ... (args: the words after "simulate").
int simulatePendulumCommand(const std::vector<std::string>& args, std::ostream& out,
                            std::ostream& err);

/// armtrack-cli study baseline ... (args: the words after "baseline").
int baselineStudyCommand(const std::vector<std::string>& args, std::ostream& out,
                         std::ostream& err);

}  // namespace armtrack::cli
