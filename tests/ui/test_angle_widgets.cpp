// The plot panel, readouts and repetition counter on screen: a 1 kHz stream appended in batches
// costs a bounded number of redraws and points; the window scrolls; NaN and absurd values, tiny
// sizes and review mode with a cursor, an overlay, a target and events all hold up.
#include <QHeaderView>
#include <QLocale>
#include <QTableView>
#include <cmath>
#include <limits>
#include <numbers>

#include <QLegendMarker>
#include <QLineSeries>

#include "core/metrics/RepetitionCounter.h"
#include "core/session/Session.h"
#include "tests/support/GuiTestMain.h"
#include "ui/AnglePlotPanel.h"
#include "ui/AngleReadouts.h"
#include "ui/RepetitionCounterWidget.h"

using namespace armtrack;
using namespace armtrack::ui;

namespace {
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

AngleSample sampleAt(double t) {
  AngleSample s;
  s.t = t;
  s.deg = {60 + 50 * std::sin(t), 20 + 10 * std::sin(0.7 * t), -10 + 5 * std::cos(t),
           70 + 40 * std::sin(1.3 * t), 5 * std::sin(2 * t)};
  s.sigmaDeg = {4, 3, 12, 0.5, 0.8};
  return s;
}

/// Paints the widget now and returns it as the screen shows it.
QImage settledShot(QWidget* w) {
  w->repaint();
  for (QWidget* child : w->findChildren<QWidget*>()) child->repaint();
  QCoreApplication::processEvents();
  return test::grabFromScreen(w);
}

std::vector<AngleSample> batch(double from, double to, double rate) {
  std::vector<AngleSample> rows;
  for (double t = from; t < to - 1e-12; t += 1.0 / rate) rows.push_back(sampleAt(t));
  return rows;
}
}  // namespace

class TestAngleWidgets : public QObject {
  Q_OBJECT

 private slots:
  void degreesNeverShowANegativeZero() {
    const QLocale before;
    QLocale::setDefault(QLocale::c());
    QCOMPARE(formatDegrees(-0.4, 0), QStringLiteral("0\u00b0"));
    QCOMPARE(formatDegrees(-0.04, 1), QStringLiteral("0.0\u00b0"));
    QCOMPARE(formatDegrees(-0.06, 1), QStringLiteral("-0.1\u00b0"));
    QCOMPARE(formatDegrees(-0.6, 0), QStringLiteral("-1\u00b0"));
    QCOMPARE(formatDegrees(12.34), QStringLiteral("12.3\u00b0"));
    QLocale::setDefault(before);
  }

  void liveStreamIsDecimatedAndScrolls() {
    AnglePlotPanel panel;
    panel.resize(900, 700);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setWindowSeconds(20);
    panel.setTarget(0, 30, 110);
    // 25 s of a 1 kHz stream in 750 batches, as fast as they come: appending stores only.
    const std::uint64_t redrawsBefore = panel.redraws();
    for (int b = 0; b < 750; ++b) panel.append(batch(b / 30.0, (b + 1) / 30.0, 1000));
    QVERIFY(panel.redraws() - redrawsBefore <= 2);
    panel.refresh();
    const auto [t0, t1] = panel.timeSpan();
    QCOMPARE(t1, panel.trace().lastTime());
    QVERIFY(std::abs((t1 - t0) - 20.0) < 1e-9);
    QVERIFY(panel.trace().firstTime() > t1 - 21.5);  // the trace keeps the window only
    for (int a = 0; a < kAngleCount; ++a) {
      const int columns = panel.chart(a)->columnsDrawn();
      const double plotWidth = panel.chart(a)->chart()->plotArea().width();
      QVERIFY(columns >= plotWidth / 2 * 0.8 && columns <= plotWidth / 2 * 1.2);
      // Live columns are anchored to time: the window touches columns + 1 of them, and the
      // one before it carries the line to the left edge.
      QVERIFY2(panel.chart(a)->pointsDrawn() <= 2 * (columns + 2),
               qPrintable(QString::number(panel.chart(a)->pointsDrawn())));
      QVERIFY(panel.chart(a)->pointsDrawn() > columns / 2);
    }
    // The table shows the newest values and the window's range.
    const AngleSample& last = panel.trace().samples().back();
    for (int a = 0; a < kAngleCount; ++a) QCOMPARE(panel.tableModel()->value(a), last.deg[a]);
    const QString target =
        panel.tableModel()->data(panel.tableModel()->index(0, AngleTableModel::Target)).toString();
    QVERIFY2(target.contains(QStringLiteral("30")) && target.contains(QStringLiteral("110")),
             qPrintable(target));
    // The y axis covers the angle and the target band.
    const auto [ylo, yhi] = panel.chart(0)->yRange();
    QVERIFY(ylo <= 10 && yhi >= 110);
    test::saveScreenshot(settledShot(&panel), QStringLiteral("angle_plots_live"));
    // Refreshing from the panel's own timer: at most ~30 a second.
    const std::uint64_t r0 = panel.redraws();
    QElapsedTimer clock;
    clock.start();
    double t = 25.0;
    while (clock.elapsed() < 1000) {
      panel.append(batch(t, t + 0.001, 1000));
      t += 0.001;
      QCoreApplication::processEvents();
    }
    const std::uint64_t perSecond = panel.redraws() - r0;
    QVERIFY2(perSecond >= 10 && perSecond <= 36, qPrintable(QString::number(perSecond)));
  }

  void nanAndAbsurdValues() {
    AnglePlotPanel panel;
    panel.resize(600, 500);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    std::vector<AngleSample> rows = batch(0, 5, 200);
    for (std::size_t i = 0; i < rows.size(); i += 10) rows[i].deg[2] = kNan;
    rows[300].deg[0] = 1e38;
    rows[301].deg[0] = -std::numeric_limits<double>::infinity();
    rows[302].sigmaDeg[1] = std::numeric_limits<double>::infinity();
    rows[303].sigmaDeg[1] = 1e6;
    AngleSample lastNan = sampleAt(5.0);
    lastNan.deg[4] = kNan;
    rows.push_back(lastNan);
    AngleSample outOfOrder = sampleAt(1.0);
    rows.push_back(outOfOrder);
    panel.append(rows);
    panel.refresh();
    QCOMPARE(panel.trace().refused(), std::size_t{1});
    const auto [lo, hi] = panel.chart(0)->yRange();
    QVERIFY(lo >= -400 && hi <= 400);
    const auto [lo1, hi1] = panel.chart(1)->yRange();
    QVERIFY2(hi1 - lo1 < 200, qPrintable(QStringLiteral("%1 %2").arg(lo1).arg(hi1)));
    const QString shown =
        panel.tableModel()->data(panel.tableModel()->index(4, AngleTableModel::Value)).toString();
    QCOMPARE(shown, QStringLiteral("\u2013"));
  }

  void tinySizes() {
    AnglePlotPanel panel;
    panel.show();
    panel.append(batch(0, 3, 500));
    for (const QSize s : {QSize(1, 1), QSize(30, 5), QSize(5, 400), QSize(2000, 30)}) {
      panel.resize(s);
      QCoreApplication::processEvents();
      panel.refresh();
    }
    AngleReadouts readouts;
    readouts.show();
    readouts.resize(3, 3);
    const AngleSample s = sampleAt(1.0);
    readouts.setSample(&s);
    readouts.refresh();
    QCoreApplication::processEvents();
    QVERIFY(!readouts.valueText(0).isEmpty());
  }

  void trunkAnglesGetTheirOwnPlotWithALegend() {
    AnglePlotPanel panel;
    panel.resize(900, 900);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    // Rows without trunk angles (no sternum sensor): no trunk plot.
    panel.append(batch(0, 2, 100));
    panel.refresh();
    QVERIFY(panel.trunkChart()->isHidden());
    // Rows from the session with a trunk estimate: 20 deg of flexion, -6 of lateral bending, 9 of
    // axial rotation (rad in the session, degrees on the plot).
    std::vector<AngleSample> rows;
    for (int i = 0; i < 300; ++i) {
      session::EstimateRow r;
      r.t = 2.0 + i * 0.01;
      r.trunk = Eigen::Vector3d(20, -6, 9) * std::numbers::pi / 180.0;
      r.trunkStd = Eigen::Vector3d(0.5, 0.5, 1.0) * std::numbers::pi / 180.0;
      rows.push_back(angleSample(r));
    }
    QCOMPARE(rows.back().trunkDeg[0], 20.0);
    panel.append(rows);
    panel.refresh();
    TrunkChart* chart = panel.trunkChart();
    QVERIFY(chart->isVisible());
    const double expected[3] = {20, -6, 9};
    QSet<QRgb> colours;
    for (int a = 0; a < kTrunkAngleCount; ++a) {
      QLineSeries* line = chart->series(a);
      QVERIFY(line->count() > 0);
      for (const QPointF& p : line->points()) QVERIFY(std::abs(p.y() - expected[a]) < 1e-9);
      QCOMPARE(line->name(), TrunkChart::angleName(a));
      QVERIFY(!line->name().isEmpty());
      colours.insert(line->pen().color().rgb());
      // In the legend, by name.
      const auto markers = chart->chart()->legend()->markers(line);
      QCOMPARE(markers.size(), 1);
      QVERIFY(markers.front()->isVisible());
    }
    QCOMPARE(colours.size(), 3);
    QVERIFY(chart->chart()->legend()->isVisible());
    QVERIFY(chart->yRange().second >= 20.0 && chart->yRange().first <= -6.0);
    // Absurd trunk angles do not wreck the axis; a new session forgets the trunk.
    session::EstimateRow wild;
    wild.t = 6.0;
    wild.trunk = Eigen::Vector3d(1e9, kNan, -1e9);
    panel.append({angleSample(wild)});
    panel.refresh();
    QVERIFY(chart->yRange().second <= 90.0 && chart->yRange().first >= -90.0);
    panel.clear();
    QVERIFY(panel.trunkChart()->isHidden());
    // Review: a stored analysis without trunk angles shows no trunk plot; with them, it does.
    panel.setSession(batch(0, 5, 50));
    QVERIFY(panel.trunkChart()->isHidden());
    panel.setSession(rows);
    panel.setCursor(2.5);
    panel.refresh();
    QVERIFY(panel.trunkChart()->isVisible());
    QCOMPARE(panel.trunkTrace().samples().size(), rows.size());
  }

  void reviewWithCursorOverlayAndEvents() {
    AnglePlotPanel panel;
    panel.resize(900, 700);
    panel.show();
    QVERIFY(QTest::qWaitForWindowExposed(&panel));
    panel.setSession(batch(0, 60, 100));
    std::vector<AngleSample> other = batch(0, 50, 100);
    for (AngleSample& s : other)
      for (double& d : s.deg) d *= 0.7;
    panel.setOverlay(other);
    panel.addEvent(12.0, QStringLiteral("pain"));
    panel.addEvent(40.0, QStringLiteral("rest"));
    panel.setCursor(30.0);
    panel.refresh();
    QCOMPARE(panel.mode(), AnglePlotPanel::Mode::Review);
    const auto [t0, t1] = panel.timeSpan();
    QCOMPARE(t0, panel.trace().firstTime());
    QCOMPARE(t1, panel.trace().lastTime());
    QVERIFY(t1 > 59.9);
    const AngleSample* at = panel.trace().at(30.0);
    QVERIFY(at);
    QCOMPARE(panel.tableModel()->value(0), at->deg[0]);
    test::saveScreenshot(settledShot(&panel), QStringLiteral("angle_plots_review"));
    // A click on a plot asks for the cursor there.
    QSignalSpy spy(&panel, &AnglePlotPanel::cursorRequested);
    AngleChart* c = panel.chart(0);
    const QRectF area = c->chart()->plotArea();
    QTest::mouseClick(c->viewport(), Qt::LeftButton, {},
                      QPoint(static_cast<int>(area.left() + area.width() / 2),
                             static_cast<int>(area.center().y())));
    QCOMPARE(spy.count(), 1);
    QVERIFY2(std::abs(spy.at(0).at(0).toDouble() - 30.0) < 1.0,
             qPrintable(QString::number(spy.at(0).at(0).toDouble())));
  }

  // At the width the review and live screens give the panel on a 1200 px window (about 800 px),
  // every number is in view: no column is cut off behind a horizontal scroll bar. The target
  // column is there only while a target is set; the names wrap rather than the numbers hide.
  void everyColumnInViewOnANarrowPanel() {
    for (const bool target : {false, true}) {
      AnglePlotPanel panel;
      if (target) panel.setTarget(0, 90.0, 150.0);
      panel.resize(800, 450);
      panel.show();
      QVERIFY(QTest::qWaitForWindowExposed(&panel));
      const AngleSample s = sampleAt(-2.0);
      panel.append({s});
      panel.refresh();
      QTableView* table = panel.tableView();
      QCOMPARE(table->isColumnHidden(AngleTableModel::Target), !target);
      QTRY_VERIFY(table->width() > 0);
      QVERIFY2(table->horizontalHeader()->length() <= table->viewport()->width(),
               qPrintable(QStringLiteral("columns %1 px in a %2 px table")
                              .arg(table->horizontalHeader()->length())
                              .arg(table->viewport()->width())));
      QVERIFY(panel.chart(0)->width() >= 300);  // the plots keep room too
      // Setting a target later shows its column and sizes the table again.
      if (!target) {
        panel.setTarget(3, 20.0, 120.0);
        QVERIFY(!table->isColumnHidden(AngleTableModel::Target));
        QVERIFY(table->horizontalHeader()->length() <= table->viewport()->width());
        panel.clearTarget();
        QVERIFY(table->isColumnHidden(AngleTableModel::Target));
      }
    }
  }

  void readoutsMarkUncertainAngles() {
    AngleReadouts r;
    r.show();
    AngleSample s = sampleAt(0.0);
    s.sigmaDeg = {8, 0.5, 1.0, 0.2, kNan};
    r.setSample(&s);
    r.refresh();
    QVERIFY(r.isUncertain(0));   // +-16 deg
    QVERIFY(!r.isUncertain(1));  // +-1 deg
    QVERIFY(r.isUncertain(4));   // unknown uncertainty is not trusted
    QCOMPARE(r.valueText(0), QStringLiteral("%1\u00b0").arg(s.deg[0], 0, 'f', 0));
    r.setSample(nullptr);
    r.refresh();
    QCOMPARE(r.valueText(0), QStringLiteral("\u2013"));
    QVERIFY(!r.isUncertain(0));
  }

  // The therapist reads a confidence in degrees ("±3°": two standard deviations) and, for an
  // angle not to be trusted, why; the table says the same on amber.
  void confidenceIsPlainAndSaysWhy() {
    AngleReadouts r;
    r.show();
    AngleSample s = sampleAt(0.0);
    s.sigmaDeg = {1.5, 6.0, 0.5, 6.0, 0.4};
    s.headingFromStartPose = true;
    r.setSample(&s);
    r.refresh();
    const QString deg = QStringLiteral("\u00b0");
    QCOMPARE(r.noteText(0), QStringLiteral("\u00b13") + deg);
    QVERIFY(!r.isUncertain(0));
    QCOMPARE(r.noteText(1),
             QStringLiteral("\u00b112") + deg + QStringLiteral(", heading from the start pose"));
    QVERIFY(r.isUncertain(1));
    QCOMPARE(r.noteText(3), QStringLiteral("\u00b112") + deg + QStringLiteral(", uncertain"));
    QVERIFY(!r.noteText(4).contains(QStringLiteral("\u03c3")));
    // Rounded up to whole degrees and never "±0°": a confidence of a tenth of a degree is not an
    // exact angle.
    QCOMPARE(confidenceText(0.05), QStringLiteral("\u00b11") + deg);
    QCOMPARE(confidenceText(0.0), QStringLiteral("\u00b11") + deg);
    QCOMPARE(confidenceText(1.2), QStringLiteral("\u00b13") + deg);
    QCOMPARE(confidenceText(kNan), QStringLiteral("\u2013"));
    AngleTableModel m;
    QCOMPARE(m.headerData(AngleTableModel::Uncertainty, Qt::Horizontal).toString(),
             QStringLiteral("Confidence"));
    const std::array<double, kAngleCount> none{kNan, kNan, kNan, kNan, kNan};
    m.setValues(&s, none, none);
    QCOMPARE(m.index(0, AngleTableModel::Uncertainty).data().toString(),
             QStringLiteral("\u00b13") + deg);
    QVERIFY(!m.index(0, AngleTableModel::Value).data(Qt::BackgroundRole).isValid());
    QCOMPARE(m.index(1, AngleTableModel::Uncertainty).data().toString(),
             QStringLiteral("\u00b112") + deg + QStringLiteral(" heading"));
    QVERIFY(m.index(1, AngleTableModel::Value).data(Qt::BackgroundRole).isValid());
    QCOMPARE(m.index(1, AngleTableModel::Value).data(Qt::ToolTipRole).toString(),
             QStringLiteral("heading from the start pose"));
    // A lost sensor: every angle is only predicted.
    s.predicted = true;
    s.headingFromStartPose = false;
    s.sigmaDeg = {0.5, 0.5, 0.5, 0.5, 0.5};
    m.setValues(&s, none, none);
    r.setSample(&s);
    r.refresh();
    for (int a = 0; a < kAngleCount; ++a) {
      QCOMPARE(m.index(a, AngleTableModel::Uncertainty).data().toString(),
               QStringLiteral("sensor lost"));
      QVERIFY(r.isUncertain(a));
      QVERIFY(r.noteText(a).endsWith(QStringLiteral("sensor lost")));
    }
  }

  void repetitionCounterShowsTheCount() {
    RepetitionParams p;
    p.primaryAngle = 0;
    p.target = TargetRange{0.0, 90 * std::numbers::pi / 180};
    RepetitionCounter counter(p);
    RepetitionCounterWidget w;
    w.setTarget(3);
    w.show();
    for (int k = 0; k < 3000; ++k) {  // three 0-90 deg excursions of 10 s at 100 Hz
      const double t = k * 0.01;
      counter.add(t,
                  (1 - std::cos(t * 2 * std::numbers::pi / 10)) / 2 * 90 * std::numbers::pi / 180);
    }
    counter.add(30.5, 0.0);
    w.showCount(counter);
    QCOMPARE(counter.count(), std::size_t{3});
    QVERIFY2(w.text().startsWith(QStringLiteral("3 of 3")), qPrintable(w.text()));
    QVERIFY(w.text().contains(QStringLiteral("target reached")));
  }
};

ARMTRACK_GUI_TEST_MAIN(TestAngleWidgets)
#include "test_angle_widgets.moc"
