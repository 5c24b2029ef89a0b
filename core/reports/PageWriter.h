// Page layout for the PDF reports: a cursor that moves down A4 pages, starts a new page when a
// block does not fit, and draws the running head (patient and date) and "Page n of N" on every
// page. Internal to armtrack_reports. Lengths are device units of the QPdfWriter unless a name
// says mm.
#pragma once

#include <QFont>
#include <QFontMetricsF>
#include <QPainter>
#include <QPdfWriter>
#include <QRectF>
#include <QString>
#include <QStringList>
#include <functional>
#include <utility>
#include <vector>

namespace armtrack::reports {

struct Fonts {
  QFont body, small, bold, smallBold, heading, title;
};

/// A table drawn by PageWriter::table(): column widths as fractions of the text width; cells wrap
/// at word boundaries; the header row is repeated after a page break.
struct Table {
  QStringList header;  ///< empty = no header row
  std::vector<QStringList> rows;
  std::vector<double> widths;      ///< fractions of the text width, one per column
  std::vector<bool> rightAligned;  ///< per column; default: all but the first
  std::vector<bool> boldColumns;   ///< per column; default none
  bool rules = true;               ///< thin lines between rows
  bool small = false;              ///< the small font, for tables with many columns
};

/// text as a cell `width` wide draws it, its lines broken with '\n': words go onto a line while
/// they fit (at spaces only, so "(deg/s)" stays whole), and a word wider than the cell (a German
/// compound in a narrow column, "Spitzengeschwindigkeit") is broken into lines that fit, after a
/// '/' or '-' of its own where one fits, else between syllables where one seems to be, else where
/// it must, with a hyphen added. Every line of the result fits `width` as fm measures it, down to
/// a single character; runs of spaces become one.
QString fitToWidth(const QString& text, const QFontMetricsF& fm, double width);

class PageWriter {
 public:
  /// painter must be active on writer; the first page starts here. runningHead is printed at the
  /// top of every page, footer at the bottom left; totalPages (from a first pass, 0 = unknown)
  /// makes the page numbers "Page n of N".
  PageWriter(QPdfWriter& writer, QPainter& painter, QString runningHead, QString footer,
             int totalPages);

  double mm(double millimetres) const;
  double left() const { return m_left; }
  double textWidth() const { return m_right - m_left; }
  double y() const { return m_y; }
  int pageNumber() const { return m_page; }
  QPainter& painter() { return m_painter; }
  QPaintDevice* device() const { return &m_writer; }
  const Fonts& fonts() const { return m_fonts; }

  void newPage();
  /// Starts a new page unless `height` fits below the cursor (a block taller than a page is
  /// left to overflow handling by the caller).
  void ensureSpace(double height);
  void spaceMm(double millimetres);
  void title(const QString& text);
  /// A section heading kept on the same page as the next keepMm of content.
  void heading(const QString& text, double keepMm = 25);
  /// Wrapped text; newlines start paragraphs; flows line by line onto following pages.
  void paragraph(const QString& text, const QFont& font);
  /// label/value pairs, two pairs per row (or one, for long values).
  void keyValues(const std::vector<std::pair<QString, QString>>& items, bool twoPerRow = true);
  void table(const Table& t);
  /// The text drawn in a cell of column `column` of t (fitToWidth in its font and width).
  QString cellText(const Table& t, int column, const QString& text, bool header) const;
  /// The width a cell of column `column` of t has for its text (inside the cell's padding).
  double cellWidth(const Table& t, int column) const;
  /// Called with every table as it is drawn, when set: lets a test check a whole report's cells
  /// (tests only; set it before drawing, on the drawing thread).
  static std::function<void(const PageWriter&, const Table&)>& tableObserver();
  /// A block of the full text width and `height`, on this page if it fits, else on the next;
  /// the cursor moves below it.
  QRectF reserve(double height);

 private:
  void startPage();
  const QFont& cellFont(const Table& t, bool bold) const;
  double rowHeight(const Table& t, const QStringList& cells, bool header) const;
  void drawRow(const Table& t, const QStringList& cells, bool header, double height);

  QPdfWriter& m_writer;
  QPainter& m_painter;
  QString m_runningHead, m_footer;
  int m_total = 0;
  int m_page = 0;
  Fonts m_fonts;
  double m_left = 0, m_right = 0, m_top = 0, m_bottom = 0;  // text area
  double m_y = 0;
};

}  // namespace armtrack::reports
