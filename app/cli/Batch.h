// Runs a batch of independent jobs (recordings to estimate, sessions to re-estimate) on a pool of
// threads, with a progress line and one outcome per job: a job that fails is reported with its
// name and error and does not stop the others.
#pragma once

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace armtrack::cli {

/// One job of a batch.
struct BatchJob {
  std::string name;          ///< how messages name it (a file name, "session 12")
  std::uint64_t weight = 1;  ///< its share of the progress (e.g. bytes); 0 counts as 1
};

/// What one job did.
struct BatchOutcome {
  bool ok = false;
  std::string error;     ///< what() of what the job threw
  double seconds = 0.0;  ///< wall-clock time of the job
};

/// Reports how far the running job is, 0 to 1. Called from the job's thread.
using BatchProgress = std::function<void(double fraction)>;
/// The work of job index; throws to fail it. Called on a pool thread, one job per thread at a
/// time, so it must touch only what belongs to its job.
using BatchWork = std::function<void(std::size_t index, const BatchProgress& progress)>;

/// Makes the work of one pool thread, on that thread, before its first job: what must belong to
/// one thread (a database connection) lives in what it returns, which is destroyed on that thread
/// after its last job. When it throws, every job that thread takes fails with its error.
using BatchWorkFactory = std::function<BatchWork()>;

struct BatchDisplay {
  std::ostream* err = nullptr;  ///< progress and failures go here (the calling thread writes)
  /// A terminal: one progress line redrawn in place (with \r) and failures on lines of their
  /// own; otherwise one line per job as it ends.
  bool terminal = false;
  std::string prefix;  ///< e.g. "estimate", at the start of every line
};

/// Runs work for every job on min(threads, jobs) threads (at least 1) and waits for all of them;
/// the calling thread draws the progress. Outcomes are in the order of jobs. Never throws for a
/// job's failure.
std::vector<BatchOutcome> runBatch(const std::vector<BatchJob>& jobs, unsigned threads,
                                   const BatchWork& work, const BatchDisplay& display);
/// The same with work made on each pool thread by makeWork.
std::vector<BatchOutcome> runBatch(const std::vector<BatchJob>& jobs, unsigned threads,
                                   const BatchWorkFactory& makeWork, const BatchDisplay& display);

/// The number of threads a batch runs on when none is asked for: every core.
unsigned defaultBatchThreads();

/// Whether err is the process's standard error and that is a terminal.
bool isTerminal(const std::ostream& err);

}  // namespace armtrack::cli
