#include "app/gui/ReviewPanels.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include "app/gui/SessionTableModel.h"
#include "app/gui/services/AppSettings.h"

namespace armtrack::gui {

namespace {

QString number(const std::optional<double>& v, int decimals) {
  return v ? QString::number(*v, 'f', decimals) : QStringLiteral("-");
}

}  // namespace

void RepetitionTableModel::setRows(std::vector<RepetitionRow> rows) {
  beginResetModel();
  m_rows = std::move(rows);
  endResetModel();
}

void RepetitionTableModel::setRadians(bool radians) {
  beginResetModel();
  m_radians = radians;
  endResetModel();
}

int RepetitionTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int RepetitionTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant RepetitionTableModel::data(const QModelIndex& index, int role) const {
  if (index.row() < 0 || index.row() >= rowCount()) return {};
  const RepetitionRow& r = m_rows[static_cast<std::size_t>(index.row())];
  if (role == StartRole) return r.startS;
  if (role == Qt::TextAlignmentRole)
    return index.column() == Kind ? QVariant() : QVariant(Qt::AlignRight | Qt::AlignVCenter);
  if (role != Qt::DisplayRole && role != Qt::AccessibleTextRole) return {};
  const double k = m_radians ? 3.14159265358979323846 / 180 : 1.0;
  const int d = m_radians ? 3 : 1;
  const auto angle = [&](const std::optional<double>& deg, int decimals) {
    return deg ? QString::number(*deg * k, 'f', decimals) : QStringLiteral("-");
  };
  switch (index.column()) {
    case Number:
      return index.row() + 1;
    case Start:
      return QString::number(r.startS, 'f', 1);
    case End:
      return QString::number(r.endS, 'f', 1);
    case Excursion:
      return angle(r.excursionDeg, d);
    case Rom:
      return angle(r.romDeg, d);
    case PeakVelocity:
      return angle(r.peakVelocityDegS, m_radians ? 2 : 0);
    case Sparc:
      return number(r.sparc, 2);
    case Kind:
      return r.partial ? tr("partial") : tr("full");
    default:
      return {};
  }
}

QVariant RepetitionTableModel::headerData(int section, Qt::Orientation o, int role) const {
  if (o != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Number:
      return tr("#");
    case Start:
      return tr("Start (s)");
    case End:
      return tr("End (s)");
    case Excursion:
      return m_radians ? tr("Excursion (rad)") : tr("Excursion (deg)");
    case Rom:
      return m_radians ? tr("Range (rad)") : tr("Range (deg)");
    case PeakVelocity:
      return m_radians ? tr("Peak velocity (rad/s)") : tr("Peak velocity (deg/s)");
    case Sparc:
      return tr("SPARC");
    case Kind:
      return tr("Full or partial");
    default:
      return {};
  }
}

ReestimatePanel::ReestimatePanel(const AppSettings& settings, QWidget* parent)
    : QWidget(parent),
      m_filter(new QComboBox(this)),
      m_method(new QComboBox(this)),
      m_optical(new QCheckBox(tr("Fuse the &optical data (Kinect, webcam)"), this)),
      m_calibration(new QLineEdit(this)),
      m_browse(new QPushButton(tr("B&rowse..."), this)),
      m_run(new QPushButton(tr("Re-&estimate"), this)),
      m_current(new QLabel(this)) {
  auto* form = new QFormLayout(this);
  m_current->setWordWrap(true);
  form->addRow(tr("Shown:"), m_current);
  m_filter->addItem(tr("EKF (extended Kalman filter)"), static_cast<int>(FilterKind::Ekf));
  m_filter->addItem(tr("UKF (unscented Kalman filter)"), static_cast<int>(FilterKind::Ukf));
  m_filter->setAccessibleName(tr("Filter"));
  form->addRow(tr("&Filter:"), m_filter);
  m_method->addItem(tr("A: body acceleration modelled"),
                    static_cast<int>(MeasurementModel::AccelGyro));
  m_method->addItem(tr("B: body acceleration as states"),
                    static_cast<int>(MeasurementModel::AugmentedBodyAccel));
  m_method->addItem(tr("C: no compensation"), static_cast<int>(MeasurementModel::InclinometerGyro));
  m_method->setAccessibleName(tr("Method"));
  form->addRow(tr("&Method:"), m_method);
  m_optical->setChecked(true);
  form->addRow(QString(), m_optical);
  auto* calibration = new QHBoxLayout;
  m_calibration->setPlaceholderText(tr("none (a file from armtrack-cli calibrate)"));
  m_calibration->setAccessibleName(tr("Calibration file"));
  calibration->addWidget(m_calibration, 1);
  calibration->addWidget(m_browse);
  form->addRow(tr("&Calibration:"), calibration);
  form->addRow(QString(), m_run);
  m_filter->setCurrentIndex(settings.filter == QLatin1String("ukf") ? 1 : 0);
  m_method->setCurrentIndex(settings.method == QLatin1String("B")   ? 1
                            : settings.method == QLatin1String("C") ? 2
                                                                    : 0);
  connect(m_browse, &QPushButton::clicked, this, [this] {
    const QString f = QFileDialog::getOpenFileName(this, tr("Calibration file"), QString(),
                                                   tr("Calibrations (*.json)"));
    if (!f.isEmpty()) m_calibration->setText(f);
  });
  connect(m_run, &QPushButton::clicked, this, [this] { emit reestimateRequested(choice()); });
}

ReestimateChoice ReestimatePanel::choice() const {
  ReestimateChoice c;
  c.filter = static_cast<FilterKind>(m_filter->currentData().toInt());
  c.model = static_cast<MeasurementModel>(m_method->currentData().toInt());
  c.optical = m_optical->isChecked();
  c.calibrationFile = m_calibration->text().trimmed();
  return c;
}

void ReestimatePanel::setChoice(const ReestimateChoice& c) {
  m_filter->setCurrentIndex(m_filter->findData(static_cast<int>(c.filter)));
  m_method->setCurrentIndex(m_method->findData(static_cast<int>(c.model)));
  m_optical->setChecked(c.optical);
  m_calibration->setText(c.calibrationFile);
}

void ReestimatePanel::setBusy(bool busy) {
  for (QWidget* w : std::initializer_list<QWidget*>{m_filter, m_method, m_optical, m_calibration,
                                                    m_browse, m_run})
    w->setEnabled(!busy);
}

void ReestimatePanel::setCurrent(const QString& text) {
  m_current->setText(text);
}

OutputsPanel::OutputsPanel(QWidget* parent) : QWidget(parent), m_result(new QLabel(this)) {
  auto* layout = new QVBoxLayout(this);
  auto* row = new QHBoxLayout;
  const auto button = [&](const QString& text, const QString& tip, auto&& onClick) {
    auto* b = new QPushButton(text, this);
    b->setToolTip(tip);
    connect(b, &QPushButton::clicked, this, onClick);
    row->addWidget(b);
    m_buttons.push_back(b);
  };
  using clinical::ExportFormat;
  button(tr("&PDF report..."), tr("The session report: details, metrics, plots, repetitions"),
         [this] { emit reportRequested(); });
  button(tr("C&SV..."), tr("Angles (deg) with their uncertainty, and a metrics table"),
         [this] { emit exportRequested(ExportFormat::Csv); });
  button(tr("Open&Sim .mot..."), tr("The clinical angles as an OpenSim motion file"),
         [this] { emit exportRequested(ExportFormat::Mot); });
  button(tr("&BIDS..."), tr("A BIDS motion data set: IMUs, optical data and angles"),
         [this] { emit exportRequested(ExportFormat::Bids); });
  button(tr("Rec&ording..."), tr("The raw recording in the open format, bit for bit"),
         [this] { emit exportRequested(ExportFormat::Recording); });
  row->addStretch();
  layout->addLayout(row);
  m_result->setWordWrap(true);
  m_result->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  m_result->setAccessibleName(tr("Last output"));
  layout->addWidget(m_result);
  layout->addStretch();
}

void OutputsPanel::setBusy(bool busy) {
  for (QPushButton* b : m_buttons) b->setEnabled(!busy);
}

void OutputsPanel::setResult(const QString& text) {
  m_result->setText(text);
}

}  // namespace armtrack::gui
