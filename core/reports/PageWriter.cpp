#include "core/reports/PageWriter.h"

#include "core/reports/ReportText.h"

#include <QFontMetricsF>
#include <QLocale>
#include <QTextLayout>
#include <QTextOption>
#include <algorithm>

namespace armtrack::reports {
namespace {

// Page geometry (mm) of an A4 portrait page, 210 x 297.
constexpr double kSideMarginMm = 18;
constexpr double kHeadTopMm = 10;      // baseline area of the running head
constexpr double kTextTopMm = 22;      // text starts below the running head's rule
constexpr double kTextBottomMm = 279;  // text ends above the footer
constexpr double kFootMm = 284;        // footer line
constexpr double kCellPadMm = 1.0;

QFont font(double points, bool bold = false) {
  // DejaVu Sans (Debian fonts-dejavu-core) covers Latin, Greek and Cyrillic; fontconfig supplies
  // other scripts (e.g. WenQuanYi Micro Hei for Chinese) through Qt's font merging.
  QFont f(QStringLiteral("DejaVu Sans"));
  f.setPointSizeF(points);
  f.setBold(bold);
  f.setStyleHint(QFont::SansSerif);
  // No ligatures for scripts that do not need shaping: an "fl" ligature would extract as U+FB02
  // and "Shoulder flexion" could not be found by searching the PDF.
  f.setStyleStrategy(QFont::PreferNoShaping);
  return f;
}

bool isVowel(QChar c) {
  static const QString vowels =
      QStringLiteral("aeiouy\u00e4\u00f6\u00fc\u00e1\u00e9\u00ed\u00f3\u00fa");
  return vowels.contains(c.toLower());
}
bool isConsonant(QChar c) {
  return c.isLetter() && !isVowel(c);
}

// Whether a break before word[i] looks like one between syllables: between two consonants before
// a vowel ("Geschwin-digkeit", "Patientenken-nung", "Bewegungs-zeit") or before a single consonant
// between vowels ("Bewe-gungszeit"), with two letters at least on either side.
bool syllableBreak(const QString& word, int i) {
  if (i < 2 || i + 2 > word.size()) return false;
  const QChar before = word[i - 1], at = word[i], after = word[i + 1];
  // Not inside "ch" or "ck" ("versc-hiebung").
  if (before.toLower() == QLatin1Char('c') &&
      (at.toLower() == QLatin1Char('h') || at.toLower() == QLatin1Char('k')))
    return false;
  if (isConsonant(before) && isConsonant(at)) return isVowel(after);
  return isVowel(before) && isConsonant(at) && isVowel(after);
}

// The length of the head of word to break after so that it fits width: the longest ending in a
// '/' or '-' of its own when one fits (ownMark is set then), else the longest that ends between
// syllables (syllableBreak), else the longest, a hyphen added to either; at least one character.
int headThatFits(const QString& word, const QFontMetricsF& fm, double width, bool& ownMark) {
  int markCut = 0, syllableCut = 0, cut = 0;
  for (int i = 1; i < word.size(); ++i) {
    const QString head = word.left(i);
    const bool mark = head.back() == QLatin1Char('/') || head.back() == QLatin1Char('-');
    if (fm.horizontalAdvance(mark ? head : head + QLatin1Char('-')) > width) break;
    cut = i;
    if (mark) markCut = i;
    if (syllableBreak(word, i)) syllableCut = i;
  }
  ownMark = markCut > 0;
  if (ownMark) return markCut;
  return syllableCut > 0 ? syllableCut : std::max(cut, 1);
}

}  // namespace

QString fitToWidth(const QString& text, const QFontMetricsF& fm, double width) {
  if (!(width > 0)) return text;
  // A little room to spare: the painter's layout may measure a line a hair wider than fm does,
  // and would then break it again at a '/' of its own ("(deg/" and "s)").
  const double room = width * 0.995;
  const auto fits = [&](const QString& s) { return fm.horizontalAdvance(s) <= room; };
  QStringList out;
  for (const QString& paragraph : text.split(QLatin1Char('\n'))) {
    QString line;
    for (const QString& word : paragraph.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
      if (!line.isEmpty() && fits(line + QLatin1Char(' ') + word)) {
        line += QLatin1Char(' ') + word;
        continue;
      }
      if (!line.isEmpty()) out << line;
      // A word wider than the cell: broken into lines of its own, its last piece going on.
      QString rest = word;
      while (rest.size() > 1 && !fits(rest)) {
        bool ownMark = false;
        const int cut = headThatFits(rest, fm, room, ownMark);
        out << (ownMark || cut == 1 ? rest.left(cut) : rest.left(cut) + QLatin1Char('-'));
        rest = rest.mid(cut);
      }
      line = rest;
    }
    out << line;
  }
  return out.join(QLatin1Char('\n'));
}

PageWriter::PageWriter(QPdfWriter& writer, QPainter& painter, QString runningHead, QString footer,
                       int totalPages)
    : m_writer(writer),
      m_painter(painter),
      m_runningHead(std::move(runningHead)),
      m_footer(std::move(footer)),
      m_total(totalPages) {
  m_fonts.body = font(9.5);
  m_fonts.small = font(7.5);
  m_fonts.bold = font(9.5, true);
  m_fonts.smallBold = font(7.5, true);
  m_fonts.heading = font(13, true);
  m_fonts.title = font(18, true);
  m_left = mm(kSideMarginMm);
  m_right = mm(210 - kSideMarginMm);
  m_top = mm(kTextTopMm);
  m_bottom = mm(kTextBottomMm);
  startPage();
}

double PageWriter::mm(double millimetres) const {
  return millimetres * m_writer.resolution() / 25.4;
}

void PageWriter::startPage() {
  ++m_page;
  m_y = m_top;
  m_painter.save();
  m_painter.setPen(QPen(QColor(90, 90, 90), mm(0.2)));
  m_painter.setFont(m_fonts.small);
  const QRectF head(m_left, mm(kHeadTopMm), textWidth(), mm(6));
  const QFontMetricsF fm(m_fonts.small, &m_writer);
  const QString brand = QStringLiteral("ArmTrack");
  // An absurdly long name is cut with an ellipsis rather than run into the brand.
  const double room = textWidth() - fm.horizontalAdvance(brand) - mm(5);
  m_painter.drawText(head, Qt::AlignLeft | Qt::AlignVCenter,
                     fm.elidedText(m_runningHead, Qt::ElideMiddle, room));
  m_painter.drawText(head, Qt::AlignRight | Qt::AlignVCenter, brand);
  m_painter.drawLine(QPointF(m_left, mm(kHeadTopMm + 7)), QPointF(m_right, mm(kHeadTopMm + 7)));
  m_painter.drawLine(QPointF(m_left, mm(kFootMm - 1.5)), QPointF(m_right, mm(kFootMm - 1.5)));
  const QRectF foot(m_left, mm(kFootMm), textWidth(), mm(6));
  const QString number = m_total > 0 ? Text::tr("Page %1 of %2").arg(m_page).arg(m_total)
                                     : Text::tr("Page %1").arg(m_page);
  m_painter.drawText(
      foot, Qt::AlignLeft | Qt::AlignVCenter,
      fm.elidedText(m_footer, Qt::ElideMiddle, textWidth() - fm.horizontalAdvance(number) - mm(5)));
  m_painter.drawText(foot, Qt::AlignRight | Qt::AlignVCenter, number);
  m_painter.restore();
}

void PageWriter::newPage() {
  m_writer.newPage();
  startPage();
}

void PageWriter::ensureSpace(double height) {
  if (m_y + height > m_bottom && m_y > m_top) newPage();
}

void PageWriter::spaceMm(double millimetres) {
  m_y = std::min(m_y + mm(millimetres), m_bottom);
}

void PageWriter::title(const QString& text) {
  const QFontMetricsF fm(m_fonts.title, &m_writer);
  ensureSpace(fm.height());
  m_painter.setFont(m_fonts.title);
  m_painter.setPen(Qt::black);
  m_painter.drawText(QRectF(m_left, m_y, textWidth(), fm.height()),
                     Qt::AlignLeft | Qt::AlignVCenter, text);
  m_y += fm.height() + mm(2);
}

void PageWriter::heading(const QString& text, double keepMm) {
  const QFontMetricsF fm(m_fonts.heading, &m_writer);
  spaceMm(4);
  ensureSpace(fm.height() + mm(2) + mm(keepMm));
  m_painter.setFont(m_fonts.heading);
  m_painter.setPen(QColor(20, 50, 110));
  m_painter.drawText(QRectF(m_left, m_y, textWidth(), fm.height()),
                     Qt::AlignLeft | Qt::AlignVCenter, text);
  m_y += fm.height() + mm(0.8);
  m_painter.setPen(QPen(QColor(20, 50, 110), mm(0.3)));
  m_painter.drawLine(QPointF(m_left, m_y), QPointF(m_right, m_y));
  m_y += mm(2);
}

void PageWriter::paragraph(const QString& text, const QFont& f) {
  const QFontMetricsF fm(f, &m_writer);
  QTextOption option;
  option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
  m_painter.setPen(Qt::black);
  const QStringList paragraphs = text.split(QLatin1Char('\n'));
  for (const QString& p : paragraphs) {
    if (p.trimmed().isEmpty()) {
      m_y += fm.lineSpacing() * 0.5;
      continue;
    }
    QTextLayout layout(p, f, &m_writer);
    layout.setTextOption(option);
    layout.beginLayout();
    double h = 0;
    for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
      line.setLineWidth(textWidth());
      line.setPosition(QPointF(0, h));
      h += line.height();
    }
    layout.endLayout();
    // Line by line, so a long text continues on the next page instead of being clipped.
    for (int i = 0; i < layout.lineCount(); ++i) {
      const QTextLine line = layout.lineAt(i);
      ensureSpace(line.height());
      line.draw(&m_painter, QPointF(m_left, m_y - line.y()));
      m_y += line.height();
    }
    m_y += fm.lineSpacing() * 0.3;
  }
}

void PageWriter::keyValues(const std::vector<std::pair<QString, QString>>& items, bool twoPerRow) {
  Table t;
  t.widths =
      twoPerRow ? std::vector<double>{0.19, 0.31, 0.19, 0.31} : std::vector<double>{0.19, 0.81};
  t.rightAligned = std::vector<bool>(t.widths.size(), false);
  t.boldColumns =
      twoPerRow ? std::vector<bool>{true, false, true, false} : std::vector<bool>{true, false};
  t.rules = false;
  const std::size_t step = twoPerRow ? 2 : 1;
  for (std::size_t i = 0; i < items.size(); i += step) {
    QStringList row{items[i].first, items[i].second};
    if (twoPerRow)
      row << (i + 1 < items.size() ? items[i + 1].first : QString())
          << (i + 1 < items.size() ? items[i + 1].second : QString());
    t.rows.push_back(row);
  }
  table(t);
}

const QFont& PageWriter::cellFont(const Table& t, bool bold) const {
  if (t.small) return bold ? m_fonts.smallBold : m_fonts.small;
  return bold ? m_fonts.bold : m_fonts.body;
}

double PageWriter::cellWidth(const Table& t, int column) const {
  return t.widths[static_cast<std::size_t>(column)] * textWidth() - 2 * mm(kCellPadMm);
}

QString PageWriter::cellText(const Table& t, int column, const QString& text, bool header) const {
  if (column < 0 || column >= static_cast<int>(t.widths.size())) return text;
  const bool bold =
      header || (column < static_cast<int>(t.boldColumns.size()) && t.boldColumns[column]);
  return fitToWidth(text, QFontMetricsF(cellFont(t, bold), &m_writer), cellWidth(t, column));
}

double PageWriter::rowHeight(const Table& t, const QStringList& cells, bool header) const {
  double h = 0;
  for (int c = 0; c < cells.size() && c < static_cast<int>(t.widths.size()); ++c) {
    const bool bold = header || (c < static_cast<int>(t.boldColumns.size()) && t.boldColumns[c]);
    const QFontMetricsF fm(cellFont(t, bold), &m_writer);
    const QRectF r =
        fm.boundingRect(QRectF(0, 0, cellWidth(t, c), 1e7), Qt::TextWordWrap | Qt::AlignLeft,
                        cellText(t, c, cells[c], header));
    h = std::max(h, r.height());
  }
  return h + 2 * mm(kCellPadMm) * 0.6;
}

void PageWriter::drawRow(const Table& t, const QStringList& cells, bool header, double height) {
  double x = m_left;
  if (header) m_painter.fillRect(QRectF(m_left, m_y, textWidth(), height), QColor(230, 234, 242));
  for (int c = 0; c < cells.size() && c < static_cast<int>(t.widths.size()); ++c) {
    const double w = t.widths[c] * textWidth();
    const bool bold = header || (c < static_cast<int>(t.boldColumns.size()) && t.boldColumns[c]);
    const bool right = c < static_cast<int>(t.rightAligned.size()) ? t.rightAligned[c] : c > 0;
    m_painter.setFont(cellFont(t, bold));
    m_painter.setPen(Qt::black);
    const QRectF cell(x + mm(kCellPadMm), m_y + mm(kCellPadMm) * 0.6, w - 2 * mm(kCellPadMm),
                      height - mm(kCellPadMm) * 0.6);
    m_painter.drawText(cell,
                       Qt::TextWordWrap | Qt::AlignTop | (right ? Qt::AlignRight : Qt::AlignLeft),
                       cellText(t, c, cells[c], header));
    x += w;
  }
  m_y += height;
  if (t.rules) {
    m_painter.setPen(QPen(QColor(190, 190, 190), mm(0.15)));
    m_painter.drawLine(QPointF(m_left, m_y), QPointF(m_right, m_y));
  }
}

std::function<void(const PageWriter&, const Table&)>& PageWriter::tableObserver() {
  static std::function<void(const PageWriter&, const Table&)> observer;
  return observer;
}

void PageWriter::table(const Table& t) {
  if (tableObserver()) tableObserver()(*this, t);
  const bool hasHeader = !t.header.isEmpty();
  const double headerH = hasHeader ? rowHeight(t, t.header, true) : 0;
  bool first = true;
  for (const QStringList& row : t.rows) {
    const double h = rowHeight(t, row, false);
    const int before = m_page;
    ensureSpace((first ? headerH : 0) + h);
    if (hasHeader && (first || m_page != before)) drawRow(t, t.header, true, headerH);
    drawRow(t, row, false, h);
    first = false;
  }
  if (t.rows.empty() && hasHeader) {
    ensureSpace(headerH);
    drawRow(t, t.header, true, headerH);
  }
  m_y += mm(1.5);
}

QRectF PageWriter::reserve(double height) {
  ensureSpace(height);
  const QRectF r(m_left, m_y, textWidth(), height);
  m_y += height;
  return r;
}

}  // namespace armtrack::reports
