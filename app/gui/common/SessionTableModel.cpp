#include "app/gui/common/SessionTableModel.h"

#include <QDateTime>
#include <QJsonDocument>
#include <QLocale>
#include <cmath>

#include "app/gui/services/HomeRecords.h"

#include "ui/Retranslate.h"

namespace armtrack::gui {

void SessionTableModel::setSessions(std::vector<storage::SessionInfo> sessions) {
  beginResetModel();
  m_sessions = std::move(sessions);
  endResetModel();
}

const storage::SessionInfo* SessionTableModel::sessionAt(int row) const {
  return row >= 0 && row < static_cast<int>(m_sessions.size()) ? &m_sessions[row] : nullptr;
}

int SessionTableModel::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : static_cast<int>(m_sessions.size());
}

int SessionTableModel::columnCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : ColumnCount;
}

QString SessionTableModel::statusText(const QString& status) {
  if (status == QLatin1String(storage::kStatusComplete)) return tr("complete");
  if (status == QLatin1String(storage::kStatusInterrupted)) return tr("interrupted");
  if (status == QLatin1String(storage::kStatusRecording)) return tr("recording");
  return status;
}

QString SessionTableModel::settingText(const QString& setting) {
  if (setting == QLatin1String(storage::kSettingHome)) return tr("home");
  if (setting == QLatin1String(storage::kSettingClinic)) return tr("clinic");
  return setting;
}

QString SessionTableModel::patientText(const storage::SessionInfo& s) {
  if (s.setting != QLatin1String(storage::kSettingHome)) return {};
  QStringList parts;
  if (const auto r = HomeExerciseResult::fromJson(
          QJsonDocument::fromJson(s.homeSummaryJson.toUtf8()).object())) {
    parts << (r->measured
                  ? tr("%L1 of %L2 repetitions").arg(r->repetitions).arg(r->repetitionsPlanned)
                  : tr("%L1 of %L2 sets (not measured)").arg(r->setsDone).arg(r->setsPlanned));
    if (r->rangeMaxDeg)
      parts << tr("reached %L1\u00b0 of %L2\u00b0")
                   .arg(*r->rangeMaxDeg, 0, 'f', 0)
                   .arg(r->targetMaxDeg, 0, 'f', 0);
  }
  if (s.painScore) parts << tr("pain %L1/10").arg(*s.painScore);
  if (!s.patientComment.isEmpty())
    parts << QStringLiteral("\u201c%1\u201d").arg(s.patientComment.section(u'\n', 0, 0));
  return parts.join(QStringLiteral("; "));
}

QString SessionTableModel::durationText(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0) return QStringLiteral("-");
  const qint64 s = std::llround(seconds);
  if (s >= 3600)
    return QStringLiteral("%1:%2:%3")
        .arg(s / 3600)
        .arg((s / 60) % 60, 2, 10, QLatin1Char('0'))
        .arg(s % 60, 2, 10, QLatin1Char('0'));
  return QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

QString SessionTableModel::localTime(const QString& isoUtc) {
  QDateTime t = QDateTime::fromString(isoUtc, Qt::ISODateWithMs);
  if (!t.isValid()) return isoUtc;
  return QLocale().toString(t.toLocalTime(), QLocale::ShortFormat);
}

QVariant SessionTableModel::data(const QModelIndex& index, int role) const {
  const storage::SessionInfo* s = sessionAt(index.row());
  if (!s) return {};
  if (role == IdRole) return s->id;
  if (role == Qt::ToolTipRole) {  // what a narrow column cuts: the whole comment, the notes
    if (index.column() == Patient && !s->patientComment.isEmpty())
      return patientText(*s) + u'\n' + s->patientComment;
    if (index.column() == Notes && !s->notes.isEmpty()) return s->notes;
    return {};
  }
  if (role == Qt::EditRole) {  // sorting
    switch (index.column()) {
      case Started:
        return s->startedAt;
      case Duration:
        return s->durationS;
      case Samples:
        return s->imuSamples;
      default:
        break;
    }
  }
  if (role != Qt::DisplayRole && role != Qt::EditRole && role != Qt::AccessibleTextRole) return {};
  switch (index.column()) {
    case Started:
      return localTime(s->startedAt);
    case Protocol:
      return s->protocolName.isEmpty() ? tr("(none)") : s->protocolName;
    case Where:
      return settingText(s->setting);
    case Duration:
      return durationText(s->durationS);
    case Status:
      // A session stored but not yet analysed says so (it is analysed in the background).
      if (s->status == QLatin1String(storage::kStatusComplete) &&
          s->analysis == QLatin1String(storage::kAnalysisPending))
        return tr("complete, analysis pending");
      if (s->analysis == QLatin1String(storage::kAnalysisFailed))
        return tr("%1, cannot be analysed").arg(statusText(s->status));
      return statusText(s->status);
    case Samples:
      return QLocale().toString(s->imuSamples);
    case Patient:
      return patientText(*s);
    case Notes:
      return s->notes.section(u'\n', 0, 0);
    default:
      return {};
  }
}

QVariant SessionTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
  if (orientation != Qt::Horizontal || role != Qt::DisplayRole) return {};
  switch (section) {
    case Started:
      return tr("Started");
    case Protocol:
      return tr("Protocol");
    case Where:
      return tr("Where");
    case Duration:
      return tr("Duration");
    case Status:
      return tr("Status");
    case Samples:
      return tr("IMU samples");
    case Patient:
      return tr("Patient's own account");
    case Notes:
      return tr("Notes");
    default:
      return {};
  }
}

bool SessionTableModel::event(QEvent* event) {
  ui::refreshOnLanguageChange(this, event);
  return QAbstractTableModel::event(event);
}

}  // namespace armtrack::gui
