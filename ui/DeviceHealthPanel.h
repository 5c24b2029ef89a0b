// Device health during a session: per device and stream, the state in words and colour, the
// sample rate, samples lost and rejected. A stream whose device drops out, or that goes silent,
// turns red at once and back to green when data flow again (docs/gui.md).
#pragma once

#include <QAbstractTableModel>
#include <QCoreApplication>
#include <QIcon>
#include <QString>
#include <QWidget>
#include <array>
#include <optional>
#include <vector>

#include "core/devices/Stream.h"
#include "core/session/Session.h"

class QLabel;
class QTableView;

namespace armtrack::ui {

enum class HealthLevel { Idle, Ok, Warning, Down };

struct StreamHealthRow {
  QString device, stream;  ///< stream: trunkSensorName() for the sternum sensor
  /// The sternum sensor (StreamRole::TrunkImu): its name is in words of the current language,
  /// so a text made later names it with trunkSensorName() again, not with stream.
  bool trunkSensor = false;
  HealthLevel level = HealthLevel::Idle;
  QString status;  ///< in words: "streaming", "no data for 1.4 s", "reconnecting: ..."
  double rateHz = 0.0;
  std::uint64_t lost = 0;      ///< lost on the link (the device's count)
  std::uint64_t rejected = 0;  ///< refused by the session (NaN, wrong payload) and late
  /// The device's battery (0-100 %) where it reports one; a value out of range is not shown.
  std::optional<double> batteryPercent;
};

/// Turns the session's figures, sampled over time, into a level per stream. Plain logic, so the
/// rules are tested without a window.
class HealthTracker {
  Q_DECLARE_TR_FUNCTIONS(armtrack::ui::HealthTracker)

 public:
  /// A stream that delivered nothing for this long while its device streams is down (s).
  double silentAfter = 0.6;
  /// Samples lost or rejected within this many seconds make a stream a warning (s).
  double warnWindow = 3.0;

  /// Takes the newest figures; now is any monotonic time (s), e.g. stats.elapsed. The same
  /// figures again at the same time change nothing but the words (after a change of language).
  void update(const session::SessionStats& stats, double now);
  /// A state change the session signalled (its reason is kept for the status text).
  void setDeviceState(int device, DeviceState state, const QString& reason);
  const std::vector<StreamHealthRow>& rows() const { return m_rows; }
  /// "All devices are streaming", or what is wrong, in one line.
  QString summary() const;
  /// Every stream streams (false while there are none).
  bool allOk() const;

 private:
  struct Track {
    std::uint64_t received = 0, problems = 0;
    double lastData = -1.0, lastProblem = -1e9;
    bool seenData = false;
  };
  std::vector<Track> m_tracks;
  std::vector<StreamHealthRow> m_rows;
  std::vector<QString> m_reasons;     // per device
  std::vector<DeviceState> m_states;  // per device, from the signal
  double m_started = -1.0;
};

class DeviceHealthModel : public QAbstractTableModel {
  Q_OBJECT
 public:
  enum Column { Device, Stream, Status, Rate, Battery, Lost, Rejected, ColumnCount };
  /// A battery at or below this level (%) is shown in the warning colour.
  static constexpr double kLowBatteryPercent = 20.0;
  explicit DeviceHealthModel(QObject* parent = nullptr) : QAbstractTableModel(parent) {}
  int rowCount(const QModelIndex& parent = {}) const override;
  int columnCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role = Qt::DisplayRole) const override;
  QVariant headerData(int section, Qt::Orientation o, int role = Qt::DisplayRole) const override;
  /// A LanguageChange (passed on by the owning widget) refreshes the views' words.
  bool event(QEvent* event) override;
  void setRows(const std::vector<StreamHealthRow>& rows);
  void setDark(bool dark);

 private:
  /// The level's colour as an icon (a plain colour without a QGuiApplication).
  QVariant swatch(HealthLevel level) const;

  std::vector<StreamHealthRow> m_rows;
  bool m_dark = false;
  mutable std::array<QIcon, 4> m_swatches;
};

/// The colour of a level (green, amber, red, grey), readable on either palette.
QColor healthColour(HealthLevel level, bool dark);
QString healthWord(HealthLevel level);
/// "Trunk (sternum) sensor": how a trunk IMU stream is listed (its device's own stream name
/// says little to a therapist).
QString trunkSensorName();

class DeviceHealthPanel : public QWidget {
  Q_OBJECT
 public:
  explicit DeviceHealthPanel(QWidget* parent = nullptr);

  /// Call a few times a second with the session's figures (any rate; cheap).
  void setStats(const session::SessionStats& stats);
  /// Connect to Session::deviceStateChanged (queued to the GUI thread).
  void setDeviceState(int device, armtrack::DeviceState state, const QString& reason);
  void clear();

  const HealthTracker& tracker() const { return m_tracker; }
  DeviceHealthModel* model() const { return m_model; }
  QTableView* view() const { return m_view; }

 signals:
  /// Emitted when the summary changes (e.g. a device dropped out or came back).
  void summaryChanged(const QString& summary, bool allOk);

 protected:
  void changeEvent(QEvent* event) override;

 private:
  void retranslateUi();
  void publish();

  HealthTracker m_tracker;
  std::optional<session::SessionStats> m_lastStats;
  DeviceHealthModel* m_model;
  QTableView* m_view;
  QLabel* m_summary;
  QString m_lastSummary;
  double m_lastElapsed = 0.0;
};

}  // namespace armtrack::ui
