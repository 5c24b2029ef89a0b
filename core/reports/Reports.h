// PDF reports (docs/reports.md): a session report and a progress report over a date range,
// drawn with QPainter on a QPdfWriter (A4, vector text). Qt Core + Gui, no widgets.
//
// Threads and setup: call from the thread of a QGuiApplication (fonts need one). Without a
// display, construct it with the "offscreen" platform (QT_QPA_PLATFORM=offscreen, or
// `-platform offscreen`). Text uses the "DejaVu Sans" family (Debian fonts-dejavu-core) and
// fontconfig's fallback for other scripts (fonts-wqy-microhei for Chinese).
#pragma once

#include <QString>
#include <stdexcept>
#include <string>

#include "core/reports/ReportData.h"

namespace armtrack::reports {

/// A report that could not be written. what() names the output path or the missing input and
/// says what to do.
class ReportError : public std::runtime_error {
 public:
  explicit ReportError(const std::string& what) : std::runtime_error(what) {}
};

/// Writes the session report to pdfPath. The PDF is written to a temporary file beside it and
/// renamed when complete, so a failure leaves no partial file and an earlier file at pdfPath
/// intact. Returns the number of pages. Throws ReportError when there is no QGuiApplication, the
/// angle series and metrics are empty, or the file cannot be written (the message names the
/// path and the system's reason).
int writeSessionReport(const SessionReportData& data, const QString& pdfPath);

/// Writes the progress report (range of motion per angle against date, and a table of the
/// sessions) to pdfPath, the same way. A range without sessions gives a report that says so.
/// Returns the number of pages; throws ReportError as writeSessionReport().
int writeProgressReport(const ProgressReportData& data, const QString& pdfPath);

}  // namespace armtrack::reports
