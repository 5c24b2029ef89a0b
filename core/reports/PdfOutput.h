// Writing a report: two passes (the first counts the pages for "Page n of N"), then a temporary
// file renamed into place. Internal to armtrack_reports.
#pragma once

#include <QString>
#include <functional>

#include "core/reports/PageWriter.h"

namespace armtrack::reports {

/// Draws the report with `draw` and writes it to pdfPath through an AtomicFile (a temporary file
/// of mode 0600 renamed into place). Returns the page count; throws ReportError naming pdfPath
/// on failure.
int writePdf(const QString& pdfPath, const QString& documentTitle, const QString& runningHead,
             const QString& footer, const std::function<void(PageWriter&)>& draw);

}  // namespace armtrack::reports
