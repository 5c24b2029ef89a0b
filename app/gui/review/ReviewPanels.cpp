#include "app/gui/review/ReviewPanels.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

#include "app/gui/common/Forms.h"
#include "app/gui/common/SessionTableModel.h"
#include "app/gui/services/AppSettings.h"

#include "ui/Retranslate.h"

namespace armtrack::gui {

namespace {

QString number(const std::optional<double>& v, int decimals) {
  return v ? QLocale().toString(*v, 'f', decimals) : QStringLiteral("-");
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

bool RepetitionTableModel::hasValues(int column) const {
  return std::any_of(m_rows.begin(), m_rows.end(), [&](const RepetitionRow& r) {
    switch (column) {
      case TrunkFlexion:
        return r.trunkFlexionDeg.has_value();
      case TrunkLateral:
        return r.trunkLateralDeg.has_value();
      case TrunkRotation:
        return r.trunkRotationDeg.has_value();
      case Shoulder:
        return r.shoulderCm.has_value();
      case Compensation:
        return r.compensated.has_value();
      default:
        return true;
    }
  });
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
    return index.column() == Kind || index.column() == Compensation
               ? QVariant()
               : QVariant(Qt::AlignRight | Qt::AlignVCenter);
  if (role != Qt::DisplayRole && role != Qt::AccessibleTextRole) return {};
  const double k = m_radians ? 3.14159265358979323846 / 180 : 1.0;
  const int d = m_radians ? 3 : 1;
  const auto angle = [&](const std::optional<double>& deg, int decimals) {
    return deg ? QLocale().toString(*deg * k, 'f', decimals) : QStringLiteral("-");
  };
  switch (index.column()) {
    case Number:
      return index.row() + 1;
    case Start:
      return QLocale().toString(r.startS, 'f', 1);
    case End:
      return QLocale().toString(r.endS, 'f', 1);
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
    case TrunkFlexion:
      return r.trunkFlexionDeg ? angle(r.trunkFlexionDeg, d) : tr("not measured");
    case TrunkLateral:
      return r.trunkLateralDeg ? angle(r.trunkLateralDeg, d) : tr("not measured");
    case TrunkRotation:
      return r.trunkRotationDeg ? angle(r.trunkRotationDeg, d) : tr("not measured");
    case Shoulder:
      return r.shoulderCm ? number(r.shoulderCm, 1) : tr("not measured");
    case Compensation:
      return r.compensated ? (*r.compensated ? tr("yes") : tr("no")) : QStringLiteral("-");
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
      return m_radians ? tr("Excursion (rad)") : tr("Excursion (\u00b0)");
    case Rom:
      return m_radians ? tr("Range (rad)") : tr("Range (\u00b0)");
    case PeakVelocity:
      return m_radians ? tr("Peak velocity (rad/s)") : tr("Peak velocity (\u00b0/s)");
    case Sparc:
      return tr("SPARC");
    case Kind:
      return tr("Full or partial");
    case TrunkFlexion:
      return m_radians ? tr("Trunk flexion (rad)") : tr("Trunk flexion (\u00b0)");
    case TrunkLateral:
      return m_radians ? tr("Lateral bending (rad)") : tr("Lateral bending (\u00b0)");
    case TrunkRotation:
      return m_radians ? tr("Axial rotation (rad)") : tr("Axial rotation (\u00b0)");
    case Shoulder:
      return tr("Shoulder displacement (cm)");
    case Compensation:
      return tr("Trunk compensation");
    default:
      return {};
  }
}

bool RepetitionTableModel::event(QEvent* event) {
  ui::refreshOnLanguageChange(this, event);
  return QAbstractTableModel::event(event);
}

ReestimatePanel::ReestimatePanel(const AppSettings& settings, QWidget* parent)
    : QWidget(parent),
      m_currentLabel(new QLabel(this)),
      m_filterLabel(new QLabel(this)),
      m_methodLabel(new QLabel(this)),
      m_calibrationLabel(new QLabel(this)),
      m_filter(new QComboBox(this)),
      m_method(new QComboBox(this)),
      m_optical(new QCheckBox(this)),
      m_calibration(new QLineEdit(this)),
      m_browse(new QPushButton(this)),
      m_run(new QPushButton(this)),
      m_current(new QLabel(this)) {
  auto* form = new QFormLayout(this);
  m_current->setWordWrap(true);
  form->addRow(m_currentLabel, m_current);
  m_filter->addItem(QString(), static_cast<int>(FilterKind::Ekf));
  m_filter->addItem(QString(), static_cast<int>(FilterKind::Ukf));
  m_filterLabel->setBuddy(m_filter);
  form->addRow(m_filterLabel, m_filter);
  m_method->addItem(QString(), static_cast<int>(MeasurementModel::AccelGyro));
  m_method->addItem(QString(), static_cast<int>(MeasurementModel::AugmentedBodyAccel));
  m_method->addItem(QString(), static_cast<int>(MeasurementModel::InclinometerGyro));
  m_methodLabel->setBuddy(m_method);
  form->addRow(m_methodLabel, m_method);
  m_optical->setChecked(true);
  form->addRow(QString(), m_optical);
  auto* calibration = new QHBoxLayout;
  calibration->addWidget(m_calibration, 1);
  calibration->addWidget(m_browse);
  m_calibrationLabel->setBuddy(m_calibration);
  form->addRow(m_calibrationLabel, calibration);
  form->addRow(QString(), m_run);
  retranslateUi();
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

void ReestimatePanel::retranslateUi() {
  m_currentLabel->setText(tr("Shown:"));
  m_filter->setItemText(0, tr("EKF (extended Kalman filter)"));
  m_filter->setItemText(1, tr("UKF (unscented Kalman filter)"));
  m_filter->setAccessibleName(tr("Filter"));
  m_filterLabel->setText(tr("&Filter:"));
  m_method->setItemText(0, tr("A: body acceleration modelled"));
  m_method->setItemText(1, tr("B: body acceleration as states"));
  m_method->setItemText(2, tr("C: no compensation"));
  m_method->setAccessibleName(tr("Method"));
  m_methodLabel->setText(tr("&Method:"));
  m_optical->setText(tr("Fuse the &optical data (Kinect, webcam)"));
  m_calibration->setPlaceholderText(tr("none (a file from armtrack-cli calibrate)"));
  m_calibration->setAccessibleName(tr("Calibration file"));
  m_browse->setText(tr("B&rowse..."));
  m_calibrationLabel->setText(tr("&Calibration:"));
  m_run->setText(tr("Re-&estimate"));
}

void ReestimatePanel::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
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
  const auto button = [&](auto&& onClick) {
    auto* b = new QPushButton(this);
    connect(b, &QPushButton::clicked, this, onClick);
    row->addWidget(b);
    m_buttons.push_back(b);
  };
  using clinical::ExportFormat;
  button([this] { emit reportRequested(); });
  button([this] { emit exportRequested(ExportFormat::Csv); });
  button([this] { emit exportRequested(ExportFormat::Mot); });
  button([this] { emit exportRequested(ExportFormat::Bids); });
  button([this] { emit exportRequested(ExportFormat::Recording); });
  row->addStretch();
  layout->addLayout(row);
  m_result->setWordWrap(true);
  m_result->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
  layout->addWidget(m_result);
  layout->addStretch();
  retranslateUi();
}

void OutputsPanel::retranslateUi() {
  const std::pair<QString, QString> texts[] = {
      {tr("&PDF report..."), tr("The session report: details, metrics, plots, repetitions")},
      {tr("C&SV..."), tr("Angles (deg) with their uncertainty, and a metrics table")},
      {tr("Open&Sim .mot..."), tr("The clinical angles as an OpenSim motion file")},
      {tr("&BIDS..."), tr("A BIDS motion data set: IMUs, optical data and angles")},
      {tr("Rec&ording..."), tr("The raw recording in the open format, bit for bit")}};
  for (std::size_t i = 0; i < m_buttons.size(); ++i) {
    m_buttons[i]->setText(texts[i].first);
    m_buttons[i]->setToolTip(texts[i].second);
  }
  m_result->setAccessibleName(tr("Last output"));
}

void OutputsPanel::changeEvent(QEvent* event) {
  if (isLanguageChange(event)) retranslateUi();
  QWidget::changeEvent(event);
}

void OutputsPanel::setBusy(bool busy) {
  for (QPushButton* b : m_buttons) b->setEnabled(!busy);
}

void OutputsPanel::setResult(const QString& text) {
  m_result->setText(text);
}

}  // namespace armtrack::gui
