// Starts and stops a live Session in a thread of its own, so the GUI thread never waits for a
// device to open or close, nor for the recording to be closed. The GUI drains the running
// session (takeResults, takeEvents, stats: any thread) from its timer.
#pragma once

#include <QJsonObject>
#include <QObject>
#include <QThread>
#include <memory>
#include <mutex>
#include <optional>

#include "app/gui/services/GatedRecordingSink.h"
#include "app/gui/services/LiveSessionConfig.h"
#include "core/devices/Stream.h"
#include "core/session/Session.h"

namespace armtrack::app {
class PluginRegistry;
}

namespace armtrack::app::gui {

/// What a recording of the session stores with it (RecordingTarget::setSessionSettings): the
/// devices as made (app/plugins/DeviceRecord.h, by device label), the filter, and the sensor
/// calibration's verdict when one was made.
storage::SessionSettings sessionSettings(const LiveSessionConfig& config,
                                         const QJsonObject& devices);

class SessionController : public QObject {
  Q_OBJECT
 public:
  /// registry: loaded, outlives the controller; only plugin() is called, from the control thread.
  explicit SessionController(const PluginRegistry& registry, QObject* parent = nullptr);
  /// Stops a running session, waiting for it (at most 15 s): the one wait on the GUI thread,
  /// when the screen goes away with a session still running.
  ~SessionController() override;

  /// Creates the devices and starts the session in the control thread; started() follows.
  /// gate: where rows go when recording (nullptr: the session records nothing).
  void start(const LiveSessionConfig& config, std::shared_ptr<RecordingGate> gate);
  /// Stops the running session in the control thread; stopped() follows. The session is
  /// released by the GUI first, so session() is null from now on.
  void stop();

  /// The running session (GUI thread), or nullptr.
  const std::shared_ptr<session::Session>& session() const { return m_session; }
  /// Moves the running session's new estimates and messages into the vectors (cleared first);
  /// false when no session runs. GUI thread.
  bool drainInto(std::vector<session::EstimateRow>& results, std::vector<std::string>& events);
  /// True from start() until stopped() (or a failed started()).
  bool busy() const { return m_busy; }
  /// The recording's metadata and columns, known once started (empty before).
  std::optional<std::pair<RecordingMeta, RecordingColumns>> recordingLayout() const;

 signals:
  /// error is empty when the session runs, else what is wrong and what to do.
  void started(const QString& error);
  /// The session has stopped; rows recorded and the recorder's last error (empty if none).
  void stopped(quint64 recordedRows, quint64 rowsToRecord, const QString& recorderError);
  void deviceStateChanged(int device, armtrack::DeviceState state, const QString& reason);
  void problem(const QString& message);
  /// busy() changed: true from start(), false once the devices of a stopped (or failed) session
  /// are released. Screens keep their start buttons off while it is true.
  void busyChanged(bool busy);

 private:
  void startInThread(LiveSessionConfig config, std::shared_ptr<RecordingGate> gate);
  void setBusy(bool busy);

  const PluginRegistry& m_registry;
  QThread m_thread;
  QObject* m_worker;  // lives in m_thread; context for the calls made there
  std::shared_ptr<session::Session> m_session;  // GUI thread's reference
  std::shared_ptr<session::Session> m_owned;    // control thread's reference
  bool m_busy = false;
  bool m_stopWhenStarted = false;  // stop() came while the session was starting
  mutable std::mutex m_layoutMutex;
  std::optional<std::pair<RecordingMeta, RecordingColumns>> m_layout;
};

}  // namespace armtrack::app::gui
