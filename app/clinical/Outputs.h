// What armtrack-cli and the GUI both make from the clinical records: the data of a session or
// progress report, the range of motion per session, and a session's exports. Each call reads
// the records as the signed-in user and writes the audit log like the command line always has.
// Same thread as the store; the GUI runs them in its job thread (app/gui/services).
#pragma once

#include <QJsonObject>
#include <QString>
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/metrics/RangeOfMotion.h"
#include "core/reports/ReportData.h"
#include "core/storage/ClinicalStore.h"

namespace armtrack::clinical {

/// One field in degrees of the five clinical angles in a stored metrics JSON (docs/storage.md,
/// "Metrics": "min_deg", "max_deg", "rom_deg", ...), in rad and clinicalAngleInfo() order; empty
/// where not measured.
std::array<std::optional<double>, kNumClinicalAngles> angleFieldOf(const QJsonObject& metrics,
                                                                   const char* fieldDeg);
/// The ranges of motion (rad): angleFieldOf(metrics, "rom_deg").
std::array<std::optional<double>, kNumClinicalAngles> romOf(const QJsonObject& metrics);

/// A session report's data: the session's newest analysis, the patient, the protocol, the
/// therapist (not for home accounts), earlier analysed sessions of the same arm, and the other
/// arm's latest. Throws StorageError as storage::sessionAngles.
reports::SessionReportData sessionReportData(storage::ClinicalStore& store, qint64 sessionId);

/// A progress report's data: the patient's sessions from `from` to `to` (YYYY-MM-DD, inclusive;
/// an empty bound is open), each with its range of motion and repetitions from its newest
/// metrics (none when never analysed). therapistName is the signed-in staff member.
reports::ProgressReportData progressReportData(storage::ClinicalStore& store,
                                               const QString& patientCode, const QString& from = {},
                                               const QString& to = {});

/// Writes the session report to pdf and audits it; returns the number of pages. Refused before
/// anything is written when pdf is one of the open database's files (Database::refuseOwnFile:
/// StorageError(Usage)) or the database is read-only (the audit entry cannot be written: Io).
int writeSessionReport(storage::ClinicalStore& store, qint64 sessionId, const QString& pdf);
/// Writes the progress report to pdf and audits it; returns the number of pages. Refused as
/// writeSessionReport.
int writeProgressReport(storage::ClinicalStore& store, const reports::ProgressReportData& data,
                        const QString& pdf);

enum class ExportFormat { Recording, Csv, Mot, Bids };
/// "recording", "csv", "mot" or "bids"; nothing for anything else.
std::optional<ExportFormat> parseExportFormat(const std::string& name);
std::string exportFormatName(ExportFormat format);

/// What an export wrote.
struct ExportSummary {
  std::string what;  ///< e.g. "12000 rows to out.csv and its metrics to ..."
  std::vector<std::filesystem::path> files;  ///< the main files (or the BIDS motion folder)
  std::vector<std::string> notes;            ///< what was left out and why (BIDS)
};

/// Exports session sessionId (recording: bit for bit as stored; csv, mot, bids: its newest
/// analysis) to target and audits it. Refused before anything is written when any file it would
/// write (the recording's sidecar and the CSV's metrics file included, each file of a BIDS
/// export) is one of the open database's files (StorageError(Usage)), or the database is
/// read-only (Io: the audit entry cannot be written). For recording, csv and mot the caller
/// checks beforehand whether target exists (overwrite or not); a BIDS export checks its files
/// itself and replaces existing ones only with overwrite. The BIDS subject is
/// bidsSubjectLabel(patient code), never another patient's (docs/exports.md). Throws
/// StorageError, ExportError, RecordingError.
ExportSummary exportSession(storage::ClinicalStore& store, qint64 sessionId, ExportFormat format,
                            const std::filesystem::path& target, bool overwrite = false);

}  // namespace armtrack::clinical
