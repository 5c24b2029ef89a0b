// The "estimate" command: the core engine (core/estimation/RecordingEstimator.h) streaming its rows
// to a CSV, and the report of its error statistics against the recording's true angles.
#pragma once

#include <string>

#include "app/cli/CsvOutput.h"
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

/// Filter parameters: geometry and gravity from the sidecar, the rest from options.
EstimatorParams makeParams(const RecordingMeta& meta, const EstimateOptions& options);

/// Runs the filter sample by sample (armtrack::estimateRecording). Each sample that carries IMU
/// data and gets an estimate yields one output row (kEstimateHeader, written to writer when
/// given) and, when it carries true angles, one error sample. progress is called with 10, 20,
/// ..., 100 for recordings of more than kProgressRows rows.
EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                CsvOutput* writer, const EstimateProgress& progress = {});

/// Markdown report of the errors (empty when there is no truth) and, when no optical data was
/// fused, the heading note and the first-vs-last 10 s comparison.
std::string formatReport(const EstimateStats& stats);

}  // namespace armtrack::cli
