// `session reestimate` of several stored sessions at once, in parallel (docs/cli.md).
#pragma once

#include <ostream>
#include <vector>

#include "app/cli/Args.h"
#include "app/cli/ClinicalContext.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::cli {

/// Re-estimates the sessions ids on `threads` threads, each with its own connection to c's
/// database signed in as c's user, with options (overrides become each session's filter settings,
/// as for one session). A progress line (or a line per session when err is not a terminal) goes
/// to err, a summary table to out. A session that fails is reported with its error and does not
/// stop the others. Returns 1 when any failed, else 0.
int reestimateSessions(ClinicalContext& c, const std::vector<qint64>& ids, unsigned threads,
                       const storage::AnalysisOptions& options, std::ostream& out,
                       std::ostream& err);

}  // namespace armtrack::cli
