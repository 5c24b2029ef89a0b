#include "ui/DeviceHealthPanel.h"

#include <QEvent>
#include <QFontMetrics>
#include <QGuiApplication>
#include <QHeaderView>
#include <QIcon>
#include <QLabel>
#include <QLocale>
#include <QPixmap>
#include <QTableView>
#include <QVBoxLayout>
#include <algorithm>

#include "ui/Retranslate.h"

namespace armtrack::ui {

QColor healthColour(HealthLevel level, bool dark) {
  switch (level) {
    case HealthLevel::Ok:
      return dark ? QColor(0x5c, 0xd0, 0x7a) : QColor(0x1e, 0x8e, 0x3e);
    case HealthLevel::Warning:
      return dark ? QColor(0xff, 0xc1, 0x4d) : QColor(0xb3, 0x6b, 0x00);
    case HealthLevel::Down:
      return dark ? QColor(0xff, 0x6b, 0x6b) : QColor(0xc6, 0x28, 0x28);
    case HealthLevel::Idle:
      break;
  }
  return dark ? QColor(0x9a, 0x9a, 0x9a) : QColor(0x75, 0x75, 0x75);
}

QString healthWord(HealthLevel level) {
  switch (level) {
    case HealthLevel::Ok:
      return DeviceHealthModel::tr("OK");
    case HealthLevel::Warning:
      return DeviceHealthModel::tr("warning");
    case HealthLevel::Down:
      return DeviceHealthModel::tr("down");
    case HealthLevel::Idle:
      break;
  }
  return DeviceHealthModel::tr("idle");
}

QString trunkSensorName() {
  return HealthTracker::tr("Trunk (sternum) sensor");
}

// --- HealthTracker ---------------------------------------------------------------------------

void HealthTracker::setDeviceState(int device, DeviceState state, const QString& reason) {
  if (device < 0) return;
  const auto d = static_cast<std::size_t>(device);
  if (m_states.size() <= d) {
    m_states.resize(d + 1, DeviceState::Disconnected);
    m_reasons.resize(d + 1);
  }
  m_states[d] = state;
  m_reasons[d] = reason;
}

void HealthTracker::update(const session::SessionStats& stats, double now) {
  if (m_started < 0.0) m_started = now;
  const std::size_t n = stats.streams.size();
  m_tracks.resize(n);
  m_rows.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const session::StreamStats& s = stats.streams[i];
    Track& t = m_tracks[i];
    StreamHealthRow& r = m_rows[i];
    r.device = QString::fromStdString(s.device);
    // The sternum sensor by what it is, as the arm sensors are known by their place.
    r.trunkSensor = s.role == StreamRole::TrunkImu;
    r.stream = r.trunkSensor ? trunkSensorName() : QString::fromStdString(s.stream);
    r.rateHz = s.rateHz;
    r.lost = s.deviceDropped;
    r.rejected = s.rejected + s.late;
    r.batteryPercent = s.batteryPercent && *s.batteryPercent >= 0 && *s.batteryPercent <= 100
                           ? s.batteryPercent
                           : std::nullopt;
    if (s.received > t.received || (s.received > 0 && !t.seenData)) {
      t.lastData = now;
      t.seenData = true;
    }
    t.received = s.received;
    const std::uint64_t problems = s.deviceDropped + s.rejected + s.late + s.deviceCorrupt;
    if (problems > t.problems) t.lastProblem = now;
    t.problems = problems;

    // The device's state: from the signal when there was one, else from the figures.
    int device = -1;
    for (std::size_t d = 0; d < stats.deviceLabels.size(); ++d)
      if (stats.deviceLabels[d] == s.device) device = static_cast<int>(d);
    DeviceState state = DeviceState::Streaming;
    QString reason;
    if (device >= 0) {
      const auto d = static_cast<std::size_t>(device);
      if (d < stats.deviceStates.size()) state = stats.deviceStates[d];
      if (d < m_states.size()) reason = m_reasons[d];
    }
    const double silent = t.seenData ? now - t.lastData : now - m_started;
    if (state == DeviceState::Error) {
      r.level = HealthLevel::Down;
      r.status = reason.isEmpty() ? tr("error") : tr("error: %1").arg(reason);
    } else if (state == DeviceState::Disconnected) {
      r.level = t.seenData ? HealthLevel::Down : HealthLevel::Idle;
      r.status = tr("disconnected");
    } else if (state == DeviceState::Connecting) {
      r.level = t.seenData ? HealthLevel::Down : HealthLevel::Warning;
      r.status = t.seenData
                     ? (reason.isEmpty() ? tr("reconnecting") : tr("reconnecting: %1").arg(reason))
                     : tr("connecting");
    } else if (silent > silentAfter && (t.seenData || silent > 5 * silentAfter)) {
      r.level = HealthLevel::Down;
      r.status = tr("no data for %L1 s").arg(silent, 0, 'f', 1);
    } else if (!t.seenData) {
      r.level = HealthLevel::Warning;
      r.status = tr("waiting for data");
    } else if (now - t.lastProblem < warnWindow) {
      r.level = HealthLevel::Warning;
      r.status = tr("streaming, losing samples");
    } else {
      r.level = HealthLevel::Ok;
      r.status = tr("streaming");
    }
  }
}

bool HealthTracker::allOk() const {
  return !m_rows.empty() && std::all_of(m_rows.begin(), m_rows.end(), [](const StreamHealthRow& r) {
    return r.level == HealthLevel::Ok;
  });
}

QString HealthTracker::summary() const {
  if (m_rows.empty()) return tr("No devices");
  QStringList down, warn;
  for (const StreamHealthRow& r : m_rows) {
    const QString what = r.device + QLatin1Char(' ') + r.stream + QStringLiteral(": ") + r.status;
    if (r.level == HealthLevel::Down) down << what;
    if (r.level == HealthLevel::Warning) warn << what;
  }
  if (!down.isEmpty()) return down.join(QStringLiteral("; "));
  if (!warn.isEmpty()) return warn.join(QStringLiteral("; "));
  return tr("All devices are streaming");
}

// --- DeviceHealthModel -----------------------------------------------------------------------

int DeviceHealthModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(m_rows.size());
}

int DeviceHealthModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QVariant DeviceHealthModel::data(const QModelIndex& index, int role) const {
  if (!index.isValid() || index.row() >= static_cast<int>(m_rows.size())) return {};
  const StreamHealthRow& r = m_rows[static_cast<std::size_t>(index.row())];
  if (role == Qt::DecorationRole && index.column() == Status) return swatch(r.level);
  if (role == Qt::ForegroundRole && index.column() == Status && r.level != HealthLevel::Ok)
    return healthColour(r.level, m_dark);
  if (role == Qt::TextAlignmentRole && index.column() >= Rate)
    return QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter);
  if (index.column() == Battery && r.batteryPercent && *r.batteryPercent <= kLowBatteryPercent) {
    if (role == Qt::ForegroundRole) return healthColour(HealthLevel::Warning, m_dark);
    if (role == Qt::ToolTipRole) return tr("Battery low: charge the device after the session");
  }
  if (index.column() == Battery && !r.batteryPercent && role == Qt::ToolTipRole)
    return tr("The device does not report its battery");
  if (role != Qt::DisplayRole && role != Qt::AccessibleTextRole) return {};
  switch (index.column()) {
    case Device:
      return r.device;
    case Stream:
      return r.stream;
    case Status:
      // The level in words too, so colour is not the only sign.
      return r.level == HealthLevel::Ok ? r.status
                                        : healthWord(r.level) + QStringLiteral(": ") + r.status;
    case Rate:
      return tr("%L1 Hz").arg(r.rateHz, 0, 'f', r.rateHz < 100 ? 1 : 0);
    case Battery:
      if (!r.batteryPercent)
        return role == Qt::AccessibleTextRole ? tr("not reported") : QStringLiteral("\u2013");
      return *r.batteryPercent <= kLowBatteryPercent && role == Qt::AccessibleTextRole
                 ? tr("%L1 %, low").arg(*r.batteryPercent, 0, 'f', 0)
                 : tr("%L1 %").arg(*r.batteryPercent, 0, 'f', 0);
    case Lost:
      return QLocale().toString(static_cast<qulonglong>(r.lost));
    case Rejected:
      return QLocale().toString(static_cast<qulonglong>(r.rejected));
    default:
      return {};
  }
}

QVariant DeviceHealthModel::headerData(int section, Qt::Orientation o, int role) const {
  if (role != Qt::DisplayRole || o != Qt::Horizontal) return {};
  switch (section) {
    case Device:
      return tr("Device");
    case Stream:
      return tr("Stream");
    case Status:
      return tr("Status");
    case Rate:
      return tr("Rate");
    case Battery:
      return tr("Battery");
    case Lost:
      return tr("Lost");
    case Rejected:
      return tr("Rejected");
    default:
      return {};
  }
}

bool DeviceHealthModel::event(QEvent* event) {
  refreshOnLanguageChange(this, event);
  return QAbstractTableModel::event(event);
}

void DeviceHealthModel::setRows(const std::vector<StreamHealthRow>& rows) {
  if (rows.size() != m_rows.size()) {
    beginResetModel();
    m_rows = rows;
    endResetModel();
    return;
  }
  m_rows = rows;
  if (!m_rows.empty())
    emit dataChanged(index(0, 0), index(static_cast<int>(m_rows.size()) - 1, ColumnCount - 1));
}

QVariant DeviceHealthModel::swatch(HealthLevel level) const {
  // One icon per level, made once: a bare QColor as decoration makes the item delegate create a
  // new pixmap at every paint, and those were kept (the process grew 2 MB a minute).
  const QColor c = healthColour(level, m_dark);
  if (!qobject_cast<QGuiApplication*>(QCoreApplication::instance())) return c;
  const auto i = static_cast<std::size_t>(level);
  if (m_swatches[i].isNull()) {
    QPixmap p(12, 12);
    p.fill(c);
    m_swatches[i] = QIcon(p);
  }
  return m_swatches[i];
}

void DeviceHealthModel::setDark(bool dark) {
  m_dark = dark;
  m_swatches = {};
  if (!m_rows.empty())
    emit dataChanged(index(0, 0), index(static_cast<int>(m_rows.size()) - 1, ColumnCount - 1));
}

// --- DeviceHealthPanel -----------------------------------------------------------------------

DeviceHealthPanel::DeviceHealthPanel(QWidget* parent)
    : QWidget(parent), m_model(new DeviceHealthModel(this)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  m_summary = new QLabel(this);
  m_summary->setWordWrap(true);
  m_view = new QTableView(this);
  m_view->setModel(m_model);
  m_view->verticalHeader()->hide();
  // Sized to the contents when the rows change, not at every update (that measures every cell).
  m_view->horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
  // Status too: it grows to its longest state (below), and a narrow panel scrolls sideways
  // rather than cutting "streaming" to "strea".
  m_view->horizontalHeader()->setStretchLastSection(true);
  m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
  m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
  m_view->setTabKeyNavigation(false);
  layout->addWidget(m_summary);
  layout->addWidget(m_view, 1);
  m_model->setDark(palette().color(QPalette::Window).lightness() < 128);
  retranslateUi();
}

void DeviceHealthPanel::retranslateUi() {
  setAccessibleName(tr("Device health"));
  m_summary->setAccessibleName(tr("Device health summary"));
  m_view->setAccessibleName(tr("Devices and streams"));
  // The streams' states in words of the new language, from the figures last seen.
  if (m_lastStats) m_tracker.update(*m_lastStats, m_lastElapsed);
  publish();
}

void DeviceHealthPanel::setStats(const session::SessionStats& stats) {
  m_lastElapsed = stats.elapsed;
  m_lastStats = stats;
  m_tracker.update(stats, stats.elapsed);
  publish();
}

void DeviceHealthPanel::setDeviceState(int device, armtrack::DeviceState state,
                                       const QString& reason) {
  m_tracker.setDeviceState(device, state, reason);
}

void DeviceHealthPanel::clear() {
  m_tracker = HealthTracker{};
  m_lastStats.reset();
  m_model->setRows({});
  publish();
}

void DeviceHealthPanel::publish() {
  const bool resized = m_tracker.rows().size() != static_cast<std::size_t>(m_model->rowCount());
  m_model->setRows(m_tracker.rows());
  if (resized) m_view->resizeColumnsToContents();
  // A state longer than any before ("reconnecting: ..."): the column widens to it.
  const QFontMetrics metrics(m_view->font());
  const int padding = metrics.horizontalAdvance(QStringLiteral("M"));
  int status = m_view->columnWidth(DeviceHealthModel::Status);
  for (int r = 0; r < m_model->rowCount(); ++r)
    status = std::max(status, metrics.horizontalAdvance(
                                  m_model->index(r, DeviceHealthModel::Status).data().toString()) +
                                  padding);
  if (status != m_view->columnWidth(DeviceHealthModel::Status))
    m_view->setColumnWidth(DeviceHealthModel::Status, status);
  const QString summary = m_tracker.summary();
  const bool ok = m_tracker.allOk();
  m_summary->setText(summary);
  HealthLevel worst = HealthLevel::Ok;
  for (const StreamHealthRow& r : m_tracker.rows())
    if (r.level == HealthLevel::Down ||
        (r.level == HealthLevel::Warning && worst != HealthLevel::Down))
      worst = r.level;
  QPalette p = palette();
  if (worst != HealthLevel::Ok)
    p.setColor(QPalette::WindowText,
               healthColour(worst, p.color(QPalette::Window).lightness() < 128));
  m_summary->setPalette(p);
  if (summary != m_lastSummary) {
    m_lastSummary = summary;
    emit summaryChanged(summary, ok);
  }
}

void DeviceHealthPanel::changeEvent(QEvent* event) {
  if (event->type() == QEvent::PaletteChange)
    m_model->setDark(palette().color(QPalette::Window).lightness() < 128);
  if (event->type() == QEvent::LanguageChange) retranslateUi();
  QWidget::changeEvent(event);
}

}  // namespace armtrack::ui
