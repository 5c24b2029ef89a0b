// `session import` with its analysis beside it: the rows are estimated on a second thread, from
// a connection of its own, as the import stores them, so an hour at 1 kHz costs about the longer
// of storing and estimating rather than their sum (docs/storage.md, "Speed of an import").
#pragma once

#include <exception>
#include <optional>
#include <ostream>
#include <string>

#include "app/cli/ClinicalContext.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::cli {

struct PipelinedImport {
  qint64 id = 0;
  storage::ClinicalStore::ImportReport report;
  /// The analysis, when it ran to the end.
  std::optional<storage::AnalysisResult> analysis;
  /// Why it did not (empty when it ran, or when there was nothing to analyse: no row stored).
  std::exception_ptr analysisError;
};

/// Imports csv for the patient (and protocol) into c's database and, for staff, analyses it as it
/// is stored, telling err the progress (by the part of the file read) when the file is long.
/// Throws as ClinicalStore::importRecording when the import fails: nothing is then stored.
PipelinedImport importAndAnalyse(ClinicalContext& c, const std::string& csv,
                                 const QString& patientCode, const QString& protocolName,
                                 std::ostream& err);

}  // namespace armtrack::cli
