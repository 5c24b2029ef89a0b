// The "estimate" command: the core engine (core/estimation/RecordingEstimator.h) streaming a
// recording file row by row through the filter and its rows to a CSV, one recording or a batch
// of them on every core, and the report of its error statistics against the true angles.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "app/cli/Args.h"
#include "app/cli/CsvOutput.h"
#include "core/calibration/Calibration.h"
#include "core/estimation/ArmFilter.h"
#include "core/estimation/RecordingEstimator.h"
#include "core/io/Recording.h"

namespace armtrack::cli {

// The engine lives in core/estimation/RecordingEstimator.h; these names keep the CLI's callers
// and tests as they were.
using armtrack::EstimateOptions;
using armtrack::EstimateProgress;
using armtrack::EstimateStats;
using armtrack::kEstimateHeader;
using armtrack::kProgressRows;
using armtrack::WindowError;

/// armtrack-cli estimate (docs/cli.md): one recording, or several with --out-dir in parallel.
int estimateCommand(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

/// --filter ekf|ukf (default ekf); UsageError otherwise.
FilterKind parseFilter(const Args& a);

/// Filter parameters: geometry and gravity from the sidecar, the rest from options.
EstimatorParams makeParams(const RecordingMeta& meta, const EstimateOptions& options);

/// Runs the filter over a recording in memory (armtrack::estimateRecording). Each sample that
/// carries IMU data and gets an estimate yields one output row (kEstimateHeader, written to
/// writer when given) and, when it carries true angles, one error sample. progress is called
/// with 10, 20, ..., 100 for recordings of more than kProgressRows rows.
EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                CsvOutput* writer, const EstimateProgress& progress = {});

/// Called every few thousand rows of a file with the rows and bytes read so far and the file's
/// size (0 when unknown), and once more at the end with the bytes read as the size.
using FileProgress =
    std::function<void(std::uint64_t rows, std::uint64_t bytesRead, std::uint64_t fileSize)>;

/// Streams the rest of reader's rows through a StreamingEstimator: each row is read, corrected
/// by calibration (when given), filtered and its estimate written to writer (when given), so
/// memory does not grow with the recording. Rows equal those of estimateRecording on the whole
/// recording, byte for byte. Throws RecordingError for a malformed row (the writer is then left
/// uncommitted). A cancel flag that reads true stops the run (stats.cancelled). With overlap,
/// reading and writing run in two more threads beside the filter's (the caller's), a few batches
/// of rows apart, with the same rows, progress and errors; without it, all in the caller's thread
/// (when the other cores are busy anyway).
EstimateStats estimateStream(RecordingReader& reader, const EstimatorParams& params,
                             const Calibration* calibration, CsvOutput* writer,
                             const FileProgress& progress = {},
                             const std::atomic<bool>* cancel = nullptr, bool overlap = true);

/// The diagnostic lines after a run (standard error for one recording): what the filter refused,
/// restarts and recoveries, rows without an estimate, gated optical data, and why there are no
/// error statistics.
void writeDiagnostics(std::ostream& err, const EstimateStats& stats, const EstimatorParams& params);

/// Markdown report of the errors (empty when there is no truth) and, when no optical data was
/// fused, the heading note and the first-vs-last 10 s comparison.
std::string formatReport(const EstimateStats& stats);

}  // namespace armtrack::cli
