#include "core/reports/PdfOutput.h"

#include <QBuffer>
#include <QFile>
#include <QGuiApplication>
#include <QPageLayout>
#include <QPageSize>
#include <QPdfWriter>
#include <string_view>

#include "core/io/AtomicFile.h"
#include "core/reports/Reports.h"

namespace armtrack::reports {
namespace {

// 300 dots per inch: the PDF's coordinates are in these units (text stays vector); the screen's
// DPI never enters.
constexpr int kResolution = 300;

std::string text(const QString& s) {
  return s.toStdString();
}

int render(QIODevice* device, const QString& documentTitle, const QString& runningHead,
           const QString& footer, int totalPages, const std::function<void(PageWriter&)>& draw) {
  QPdfWriter writer(device);
  writer.setPageLayout(QPageLayout(QPageSize(QPageSize::A4), QPageLayout::Portrait,
                                   QMarginsF(0, 0, 0, 0), QPageLayout::Millimeter));
  writer.setResolution(kResolution);
  writer.setTitle(documentTitle);
  writer.setCreator(QStringLiteral("ArmTrack"));
  QPainter painter;
  if (!painter.begin(&writer)) throw ReportError("cannot start drawing the PDF");
  painter.setRenderHint(QPainter::Antialiasing);
  PageWriter pages(writer, painter, runningHead, footer, totalPages);
  draw(pages);
  const int n = pages.pageNumber();
  painter.end();
  return n;
}

}  // namespace

int writePdf(const QString& pdfPath, const QString& documentTitle, const QString& runningHead,
             const QString& footer, const std::function<void(PageWriter&)>& draw) {
  if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance()))
    throw ReportError(
        "PDF reports need a QGuiApplication for their fonts; create one first (without a display "
        "use the offscreen platform: QT_QPA_PLATFORM=offscreen)");
  if (pdfPath.isEmpty()) throw ReportError("no output path given for the PDF report");
  // First pass into memory: the number of pages for the footers.
  QBuffer scratch;
  scratch.open(QIODevice::WriteOnly);
  const int total = render(&scratch, documentTitle, runningHead, footer, 0, draw);

  // Second pass into memory too (a report is a few MB), then through AtomicFile: a temporary
  // file made 0600 whatever the umask and renamed into place, as every export of a patient's
  // data (QSaveFile would give a new file the umask's mode).
  QBuffer pdf;
  pdf.open(QIODevice::WriteOnly);
  const int written = render(&pdf, documentTitle, runningHead, footer, total, draw);
  try {
    AtomicFile file(QFile::encodeName(pdfPath).toStdString());
    file.write(std::string_view(pdf.data().constData(), static_cast<std::size_t>(pdf.size())));
    file.commit();
  } catch (const AtomicFileError& e) {
    throw ReportError("cannot write the report to '" + text(pdfPath) + "': " + e.message() +
                      "; choose a folder you may write to (nothing was written)");
  }
  return written;
}

}  // namespace armtrack::reports
