#include "app/gui/patients/ProgressChart.h"

#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QDate>
#include <QDateTimeAxis>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QLocale>
#include <QScatterSeries>
#include <QSignalBlocker>
#include <QStandardItemModel>
#include <QTableView>
#include <QValueAxis>
#include <algorithm>

#include "app/gui/common/AngleNames.h"
#include "app/gui/common/Forms.h"
#include "core/metrics/NormativeRanges.h"
#include "core/metrics/PatientNorms.h"

namespace armtrack::gui {

namespace {
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;
}

ProgressChart::ProgressChart(QWidget* parent)
    : QWidget(parent),
      m_angle(new QComboBox(this)),
      m_view(new QChartView(this)),
      m_table(new QStandardItemModel(this)),
      m_tableView(new QTableView(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* top = new QHBoxLayout;
  m_angleLabel = new QLabel(this);
  m_angleLabel->setBuddy(m_angle);
  m_motions = motionDirections(aaosNormativeRanges());
  for (std::size_t i = 0; i < m_motions.size(); ++i) m_angle->addItem(QString());
  top->addWidget(m_angleLabel);
  top->addWidget(m_angle);
  top->addStretch();
  layout->addLayout(top);
  auto* row = m_row = new QBoxLayout(QBoxLayout::LeftToRight);
  m_view->setRenderHint(QPainter::Antialiasing);
  // Room for the vertical axis' title ("Largest angle (°)", longer in German) and the legend.
  m_view->setMinimumSize(420, 320);
  row->addWidget(m_view, 3);
  m_tableView->setModel(m_table);
  m_tableView->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_tableView->verticalHeader()->hide();
  m_tableView->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
  m_tableView->setTabKeyNavigation(false);
  m_tableView->setMinimumHeight(160);
  row->addWidget(m_tableView, 2);
  layout->addLayout(row, 1);
  connect(m_angle, &QComboBox::currentIndexChanged, this, &ProgressChart::redraw);
  retranslateUi();
}

void ProgressChart::retranslateUi() {
  m_angleLabel->setText(tr("&Motion:"));
  for (std::size_t i = 0; i < m_motions.size(); ++i)
    m_angle->setItemText(static_cast<int>(i), nameOf(m_motions[i]));
  if (m_hasTrunk)
    m_angle->setItemText(static_cast<int>(m_motions.size()), tr("Trunk flexion (compensation)"));
  m_angle->setAccessibleName(tr("Motion shown in the progress chart"));
  m_view->setAccessibleName(tr("Progress chart"));
  m_view->setAccessibleDescription(
      tr("The largest angle reached per session in the chosen motion, against date; the table "
         "beside it holds the same values."));
  m_tableView->setAccessibleName(tr("Progress values"));
  redraw();  // titles, series, axes and the table's header in the new words and number format
}

void ProgressChart::resizeEvent(QResizeEvent* event) {
  // Narrow (a small screen): the table below the chart, so the chart keeps the width its legend
  // and date labels need.
  m_row->setDirection(width() < kBesideWidth ? QBoxLayout::TopToBottom : QBoxLayout::LeftToRight);
  QWidget::resizeEvent(event);
}

void ProgressChart::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

void ProgressChart::setSessions(std::vector<SessionExtremes> sessions) {
  std::sort(sessions.begin(), sessions.end(),
            [](const auto& a, const auto& b) { return a.startedAt < b.startedAt; });
  m_sessions = std::move(sessions);
  fillChooser();
  redraw();
}

void ProgressChart::fillChooser() {
  const bool has = std::any_of(m_sessions.begin(), m_sessions.end(), [](const SessionExtremes& s) {
    return s.trunkFlexionDeg.has_value();
  });
  if (has == m_hasTrunk) return;
  const QSignalBlocker block(m_angle);
  m_hasTrunk = has;
  if (has)
    m_angle->addItem(tr("Trunk flexion (compensation)"));
  else
    m_angle->removeItem(static_cast<int>(m_motions.size()));
  if (m_angle->currentIndex() < 0) m_angle->setCurrentIndex(0);
}

void ProgressChart::showTrunk() {
  if (m_hasTrunk) m_angle->setCurrentIndex(static_cast<int>(m_motions.size()));
}

bool ProgressChart::trunkShown() const {
  return m_hasTrunk && m_angle->currentIndex() == static_cast<int>(m_motions.size());
}

void ProgressChart::setPatient(const QString& birthDate, const QString& sex) {
  m_birth = parseIsoDate(birthDate.toStdString());
  m_sex = sexFromCode(sex.toStdString());
  redraw();
}

void ProgressChart::setRadians(bool radians) {
  m_radians = radians;
  redraw();
}

QString ProgressChart::nameOf(const Motion& m) {
  // Named here rather than by the angle's name, which names the whole axis in some languages
  // ("Pronation/Supination"): each entry is one direction.
  switch (m.angle * 2 + (m.opposite ? 1 : 0)) {
    case 0:
      return tr("Shoulder flexion");
    case 1:
      return tr("Shoulder extension");
    case 2:
      return tr("Shoulder abduction");
    case 4:
      return tr("Shoulder internal rotation");
    case 5:
      return tr("Shoulder external rotation");
    case 6:
      return tr("Elbow flexion");
    case 8:
      return tr("Forearm pronation");
    case 9:
      return tr("Forearm supination");
    default:
      return tr("%1, opposite direction").arg(angleName(m.angle));
  }
}

void ProgressChart::setAngle(int index) {
  setMotion(index, false);
}

void ProgressChart::setMotion(int index, bool opposite) {
  const int angle = std::clamp(index, 0, kNumClinicalAngles - 1);
  int chosen = -1;
  for (std::size_t i = 0; i < m_motions.size(); ++i)
    if (m_motions[i].angle == angle && (chosen < 0 || m_motions[i].opposite == opposite))
      chosen = static_cast<int>(i);
  m_angle->setCurrentIndex(chosen);
}

ProgressChart::Motion ProgressChart::current() const {
  const int i = m_angle->currentIndex();
  return i >= 0 && i < static_cast<int>(m_motions.size()) ? m_motions[static_cast<std::size_t>(i)]
                                                          : Motion{};
}

int ProgressChart::angle() const {
  return current().angle;
}

bool ProgressChart::opposite() const {
  return current().opposite;
}

QString ProgressChart::motionName() const {
  return trunkShown() ? tr("Trunk flexion (compensation)") : nameOf(current());
}

int ProgressChart::points() const {
  return m_points;
}

QChart* ProgressChart::chart() const {
  return m_view->chart();
}

void ProgressChart::redraw() {
  if (trunkShown()) {
    redrawTrunk();
    return;
  }
  const Motion motion = current();
  const int a = motion.angle;
  // The patient's normal range on the newest session's day (today without one), as the
  // reports choose it; each session's "% of normal" against its own day's.
  const auto dayOf = [](const QString& iso) { return parseIsoDate(iso.toStdString()); };
  const QDate today = QDate::currentDate();
  const std::optional<CivilDate> newest =
      m_sessions.empty()
          ? std::optional<CivilDate>(CivilDate{today.year(), today.month(), today.day()})
          : dayOf(m_sessions.back().startedAt);
  const NormativeRange normal = patientNorms(m_birth, newest.value_or(CivilDate{}), m_sex)
                                    .ranges[static_cast<std::size_t>(a)];
  // Drawn in the unit of the settings: "deg" values are radians * scale.
  const double scale = m_radians ? 1.0 : kRadToDeg;
  const QString unit = m_radians ? tr("rad") : tr("\u00b0");
  // The largest angle in the chosen direction (flexion, not flexion + extension) against that
  // motion's normal range from the neutral position.
  const double normalRad = motionNormalRad(normal, motion.opposite);
  const double normalDeg = normalRad * scale;
  const std::string_view source =
      normSourceShortName(motion.opposite ? normal.minSource : normal.maxSource);

  auto* chart = new QChart;
  chart->setLocale(QLocale());
  chart->setLocalizeNumbers(true);
  chart->setTitle(nameOf(motion));
  chart->legend()->setAlignment(Qt::AlignBottom);
  chart->setBackgroundRoundness(0);
  chart->setTheme(palette().color(QPalette::Window).lightness() < 128 ? QChart::ChartThemeDark
                                                                      : QChart::ChartThemeLight);

  m_table->clear();
  m_table->setHorizontalHeaderLabels({tr("Date"), tr("Largest (%1)").arg(unit), tr("Of normal")});
  auto* line = new QLineSeries;
  line->setName(tr("Largest angle reached"));
  auto* dots = new QScatterSeries;
  dots->setMarkerSize(9);
  dots->setName(tr("Sessions"));
  QDateTime first, last;
  double highest = normalDeg, lowest = 0;
  m_points = 0;
  for (const SessionExtremes& s : m_sessions) {
    const auto i = static_cast<std::size_t>(a);
    const std::optional<double> peak =
        largestInDirection(s.minRad[i], s.maxRad[i], motion.opposite);
    if (!peak) continue;
    const QDateTime when = QDateTime::fromString(s.startedAt, Qt::ISODateWithMs);
    if (!when.isValid()) continue;
    const double deg = *peak * scale;
    line->append(static_cast<qreal>(when.toMSecsSinceEpoch()), deg);
    dots->append(static_cast<qreal>(when.toMSecsSinceEpoch()), deg);
    if (!first.isValid()) first = when;
    last = when;
    highest = std::max(highest, deg);
    lowest = std::min(lowest, deg);  // below 0: the session never reached the neutral position
    ++m_points;
    m_table->appendRow(
        {new QStandardItem(QLocale().toString(when.toLocalTime().date(), QLocale::ShortFormat)),
         new QStandardItem(QLocale().toString(deg, 'f', m_radians ? 3 : 1)),
         new QStandardItem(
             tr("%L1 %").arg(sessionPercentOfNormal(m_birth, m_sex, dayOf(s.startedAt), a,
                                                    s.minRad[i], s.maxRad[i], motion.opposite)
                                 .value_or(0),
                             0, 'f', 0))});
  }
  if (m_points == 0) {
    chart->setTitle(tr("%1: no analysed session yet").arg(nameOf(motion)));
    first = QDateTime::currentDateTimeUtc().addDays(-28);
    last = QDateTime::currentDateTimeUtc();
  }
  // A day either side, so single points and the shading's ends are visible.
  const QDateTime from = first.addDays(-1), to = last.addDays(1);
  auto* normalTop = new QLineSeries;
  auto* normalBottom = new QLineSeries;
  for (const QDateTime& t : {from, to}) {
    normalTop->append(static_cast<qreal>(t.toMSecsSinceEpoch()), normalDeg);
    normalBottom->append(static_cast<qreal>(t.toMSecsSinceEpoch()), 0);
  }
  auto* normalArea = new QAreaSeries(normalTop, normalBottom);
  normalArea->setName(
      tr("Normal (%1) %L2 %3")
          .arg(QString::fromUtf8(source.data(), static_cast<qsizetype>(source.size())))
          .arg(normalDeg, 0, 'f', m_radians ? 2 : 0)
          .arg(unit));
  QColor shade = palette().color(QPalette::Highlight);
  shade.setAlpha(45);
  normalArea->setBrush(shade);
  QPen edge(palette().color(QPalette::Highlight));
  edge.setStyle(Qt::DashLine);
  edge.setWidthF(1.5);
  normalArea->setPen(edge);
  chart->addSeries(normalArea);
  chart->addSeries(line);
  chart->addSeries(dots);

  auto* x = new QDateTimeAxis;
  x->setFormat(tr("d MMM", "the date axis' labels, a QDateTime format: day and short month"));
  x->setRange(from, to);
  x->setTickCount(std::clamp(m_points + 1, 3, 6));
  auto* y = new QValueAxis;
  y->setTitleText(tr("Largest angle (%1)").arg(unit));
  const double spanDeg = (highest - lowest) / scale * kRadToDeg;
  const double step = (spanDeg > 200 ? 45 : 30) / kRadToDeg * scale;  // 30 or 45 deg
  y->setRange(std::floor(lowest * 1.05 / step) * step, std::ceil(highest * 1.05 / step) * step);
  showChart(chart, x, y, step);
}

// The largest trunk flexion per session: how far the patient leaned to reach, which therapy means
// to reduce (no normal range: ideally none at all).
// Puts the axes on the chart (y ticked every step from 0, in the unit shown), attaches every
// series to them and shows the chart in place of the old one.
void ProgressChart::showChart(QChart* chart, QAbstractAxis* x, QValueAxis* y, double step) {
  y->setTickType(QValueAxis::TicksDynamic);
  y->setTickAnchor(0);
  y->setTickInterval(step);
  y->setLabelFormat(m_radians ? QStringLiteral("%.2f") : QStringLiteral("%.0f"));
  chart->addAxis(x, Qt::AlignBottom);
  chart->addAxis(y, Qt::AlignLeft);
  for (QAbstractSeries* s : chart->series()) {
    s->attachAxis(x);
    s->attachAxis(y);
  }
  QChart* old = m_view->chart();
  m_view->setChart(chart);
  delete old;
}

void ProgressChart::redrawTrunk() {
  const double scale = m_radians ? 1.0 / kRadToDeg : 1.0;  // from degrees
  const QString unit = m_radians ? tr("rad") : tr("\u00b0");
  auto* chart = new QChart;
  chart->setLocale(QLocale());
  chart->setLocalizeNumbers(true);
  chart->setTitle(tr("Trunk flexion (compensation)"));
  chart->legend()->setAlignment(Qt::AlignBottom);
  chart->setBackgroundRoundness(0);
  chart->setTheme(palette().color(QPalette::Window).lightness() < 128 ? QChart::ChartThemeDark
                                                                      : QChart::ChartThemeLight);
  m_table->clear();
  m_table->setHorizontalHeaderLabels({tr("Date"), tr("Largest trunk flexion (%1)").arg(unit)});
  auto* line = new QLineSeries;
  line->setName(tr("Largest trunk flexion"));
  auto* dots = new QScatterSeries;
  dots->setMarkerSize(9);
  dots->setName(tr("Sessions"));
  QDateTime first, last;
  double highest = 10 * scale;
  m_points = 0;
  for (const SessionExtremes& s : m_sessions) {
    if (!s.trunkFlexionDeg) continue;
    const QDateTime when = QDateTime::fromString(s.startedAt, Qt::ISODateWithMs);
    if (!when.isValid()) continue;
    const double v = *s.trunkFlexionDeg * scale;
    line->append(static_cast<qreal>(when.toMSecsSinceEpoch()), v);
    dots->append(static_cast<qreal>(when.toMSecsSinceEpoch()), v);
    if (!first.isValid()) first = when;
    last = when;
    highest = std::max(highest, v);
    ++m_points;
    m_table->appendRow(
        {new QStandardItem(QLocale().toString(when.toLocalTime().date(), QLocale::ShortFormat)),
         new QStandardItem(QLocale().toString(v, 'f', m_radians ? 3 : 1))});
  }
  const QDateTime from = first.addDays(-1), to = last.addDays(1);
  chart->addSeries(line);
  chart->addSeries(dots);
  auto* x = new QDateTimeAxis;
  x->setFormat(tr("d MMM", "the date axis' labels, a QDateTime format: day and short month"));
  x->setRange(from, to);
  x->setTickCount(std::clamp(m_points + 1, 3, 6));
  auto* y = new QValueAxis;
  y->setTitleText(tr("Largest trunk flexion (%1)").arg(unit));
  const double step = 5 * scale;  // 5 deg
  y->setRange(0, std::ceil(highest * 1.1 / step) * step);
  showChart(chart, x, y, step);
}

}  // namespace armtrack::gui
