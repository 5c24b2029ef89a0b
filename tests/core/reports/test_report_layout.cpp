// The reports' tables fit their columns in every language: a word wider than its column (German
// compounds such as "Spitzengeschwindigkeit" or "Patientenkennung") is broken with a hyphen
// instead of running out of the cell and being cut. Checked on every cell of the German session
// report with a trunk section, measured with the fonts and widths the report draws with.
#include <QFontMetricsF>

#include "ReportTestSupport.h"
#include "app/i18n/Language.h"
#include "core/reports/PageWriter.h"
#include "core/reports/Reports.h"

namespace armtrack::reports {
namespace {

using namespace test;

/// The lines of a cell's text as drawn: as given, its words (the painter wraps at spaces); as
/// PageWriter draws it, fitToWidth's lines.
QStringList linesOf(const QString& text, bool raw) {
  QStringList lines;
  for (const QString& line : text.split(QLatin1Char('\n')))
    lines << (raw ? line.split(QLatin1Char(' '), Qt::SkipEmptyParts) : QStringList{line});
  return lines;
}

struct Overflow {
  QString cell, word;
};

/// Every line of every cell of the tables drawn while `draw` runs that is wider than its cell,
/// as the cell's text is given (raw = true: its words, which the painter cannot break) or as
/// PageWriter draws it.
std::vector<Overflow> overflows(const std::function<void()>& draw, bool raw,
                                std::size_t* cells = nullptr) {
  std::vector<Overflow> out;
  std::size_t seen = 0;
  PageWriter::tableObserver() = [&](const PageWriter& w, const Table& t) {
    const auto check = [&](const QStringList& row, bool header) {
      for (int c = 0; c < row.size() && c < static_cast<int>(t.widths.size()); ++c) {
        ++seen;
        const bool bold = header || (c < static_cast<int>(t.boldColumns.size()) &&
                                     t.boldColumns[static_cast<std::size_t>(c)]);
        const QFont& f = t.small ? (bold ? w.fonts().smallBold : w.fonts().small)
                                 : (bold ? w.fonts().bold : w.fonts().body);
        const QFontMetricsF fm(f, w.device());
        const QString text = raw ? row[c] : w.cellText(t, c, row[c], header);
        for (const QString& line : linesOf(text, raw))
          if (fm.horizontalAdvance(line) > w.cellWidth(t, c) + 1e-6) out.push_back({row[c], line});
      }
    };
    if (!t.header.isEmpty()) check(t.header, true);
    for (const QStringList& row : t.rows) check(row, false);
  };
  draw();
  PageWriter::tableObserver() = nullptr;
  if (cells) *cells = seen;
  return out;
}

class ReportLayout : public ReportTest {};

TEST_F(ReportLayout, EveryCellOfTheGermanSessionReportFitsItsColumn) {
  const SimulatedSession sim = simulateSession({110, 120, 115, 118, 60});
  SessionReportData d = sessionData(sim);
  // A trunk section with its table and values ("Schulterverschiebung").
  TrunkCompensation trunk;
  trunk.session.maxFlexionDeg = 18.0;
  trunk.session.maxLateralDeg = 9.0;
  trunk.session.maxRotationDeg = 9.0;
  trunk.session.maxShoulderDisplacementCm = 17.6;
  trunk.repetitions.assign(d.metrics.repetitions.repetitions.size(), trunk.session);
  trunk.repetitionsWithCompensation = trunk.repetitions.size();
  d.trunk = trunk;
  d.trunkFlexionLimitDeg = 10.0;
  RomSnapshot earlier;
  earlier.date = QStringLiteral("2026-11-13");
  d.earlierSessions.push_back(earlier);

  i18n::ScopedLanguage german(QStringLiteral("de"));
  const QString pdf = path("bericht.pdf");
  const auto draw = [&] { ASSERT_GT(writeSessionReport(d, pdf), 0); };
  // As given, German words run out of their cells (what the report drew before): the check
  // below sees the report's tables.
  const std::vector<Overflow> given = overflows(draw, /*raw=*/true);
  EXPECT_FALSE(given.empty());
  bool peakVelocity = false;
  for (const Overflow& o : given)
    peakVelocity = peakVelocity || o.word.startsWith(QStringLiteral("Spitzengeschwindigkeit"));
  EXPECT_TRUE(peakVelocity);
  std::size_t cells = 0;
  for (const Overflow& o : overflows(draw, /*raw=*/false, &cells))
    ADD_FAILURE() << "\"" << o.word.toStdString() << "\" of \"" << o.cell.toStdString()
                  << "\" is wider than its column";
  EXPECT_GT(cells, 100u);
}

// fitToWidth alone: text that fits is left as it is; lines break at spaces (a unit's '/' stays);
// a long word is broken after its own '/' where that fits, else with a hyphen; every line fits
// down to a column one character wide; nothing is lost but the hyphens added.
TEST_F(ReportLayout, FitToWidthBreaksOnlyWordsThatDoNotFit) {
  QFont f(QStringLiteral("DejaVu Sans"));
  f.setPointSizeF(9.5);
  const QFontMetricsF fm(f);
  const QString plain = QStringLiteral("Min (deg)");
  // (with the 0.5 % fitToWidth keeps to spare)
  EXPECT_EQ(fitToWidth(plain, fm, 1.01 * fm.horizontalAdvance(plain)), plain);
  EXPECT_EQ(fitToWidth(QString(), fm, 10), QString());
  EXPECT_EQ(fitToWidth(plain, fm, 0), plain);  // no width: nothing to fit to
  // A unit stays whole: the line breaks at the space before it, not at its '/'.
  const QString unit = QStringLiteral("Rumpfflexion (\u00b0/s)");
  EXPECT_EQ(fitToWidth(unit, fm, fm.horizontalAdvance(QStringLiteral("Rumpfflexion (\u00b0/")) + 1),
            QStringLiteral("Rumpfflexion\n(\u00b0/s)"));
  const QString slash = QStringLiteral("Pronation/Supination");
  EXPECT_EQ(fitToWidth(slash, fm, fm.horizontalAdvance(QStringLiteral("Supination")) + 1),
            QStringLiteral("Pronation/\nSupination"));
  const QString word = QStringLiteral("Spitzengeschwindigkeit (\u00b0/s)");
  for (const double width : {fm.horizontalAdvance(QStringLiteral("Spitzengeschw")), 25.0, 1.0}) {
    const QString fitted = fitToWidth(word, fm, width);
    for (const QString& line : linesOf(fitted, false))
      EXPECT_TRUE(line.size() == 1 || fm.horizontalAdvance(line) <= width)
          << line.toStdString() << " in " << width;
    QString back = fitted;
    back.replace(QStringLiteral("-\n"), QString()).replace(QLatin1Char('\n'), QString());
    EXPECT_EQ(back.remove(QLatin1Char(' ')), QString(word).remove(QLatin1Char(' ')))
        << fitted.toStdString();
  }
}

}  // namespace
}  // namespace armtrack::reports
