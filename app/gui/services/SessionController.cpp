#include "app/gui/services/SessionController.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <QJsonObject>

#include "app/plugins/DeviceRecord.h"
#include "app/plugins/PluginRegistry.h"
#include "core/storage/DatabaseRecordingSink.h"
#include "devices/api/DeviceThread.h"
#include "devices/api/Options.h"

namespace armtrack::app::gui {

storage::SessionSettings sessionSettings(const LiveSessionConfig& config,
                                         const QJsonObject& devices) {
  storage::SessionSettings out;
  out.devicesJson = QString::fromUtf8(QJsonDocument(devices).toJson(QJsonDocument::Compact));
  // The live filter, which the session's analysis then uses too (as the CLI stores it), and the
  // sensor calibration's verdict for the report.
  QJsonObject filter{{QStringLiteral("filter"), config.estimator.filter == FilterKind::Ukf
                                                    ? QStringLiteral("ukf")
                                                    : QStringLiteral("ekf")}};
  if (!config.calibrationVerdict.isEmpty())
    filter.insert(QStringLiteral("sensor_calibration"),
                  QJsonObject{{QStringLiteral("verdict"), config.calibrationVerdict},
                              {QStringLiteral("reason"), config.calibrationReason}});
  out.filterJson = QString::fromUtf8(QJsonDocument(filter).toJson(QJsonDocument::Compact));
  return out;
}

SessionController::SessionController(const PluginRegistry& registry, QObject* parent)
    : QObject(parent), m_registry(registry), m_worker(new QObject) {
  qRegisterMetaType<armtrack::DeviceState>();
  m_thread.setObjectName(QStringLiteral("armtrack-session-control"));
  m_worker->moveToThread(&m_thread);
  connect(&m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
  m_thread.start();
}

SessionController::~SessionController() {
  m_session.reset();
  QMetaObject::invokeMethod(m_worker, [this] {
    if (m_owned) m_owned->stop();
    m_owned.reset();
  });
  m_thread.quit();
  m_thread.wait(15000);
}

std::optional<std::pair<RecordingMeta, RecordingColumns>> SessionController::recordingLayout()
    const {
  std::lock_guard lock(m_layoutMutex);
  return m_layout;
}

bool SessionController::drainInto(std::vector<session::EstimateRow>& results,
                                  std::vector<std::string>& events) {
  results.clear();
  events.clear();
  if (!m_session) return false;
  m_session->takeResults(results);
  m_session->takeEvents(events);
  return true;
}

void SessionController::start(const LiveSessionConfig& config,
                              std::shared_ptr<RecordingGate> gate) {
  if (m_busy) {
    emit started(tr("a session is already running; stop it first"));
    return;
  }
  setBusy(true);
  m_stopWhenStarted = false;
  {
    std::lock_guard lock(m_layoutMutex);
    m_layout.reset();
  }
  QMetaObject::invokeMethod(m_worker, [this, config, gate] { startInThread(config, gate); });
}

void SessionController::startInThread(LiveSessionConfig config,
                                      std::shared_ptr<RecordingGate> gate) {
  auto fail = [this](const QString& why) {
    QMetaObject::invokeMethod(this, [this, why] {
      setBusy(false);
      emit started(why);
    });
  };
  if (config.devices.isEmpty()) return fail(tr("no device chosen: choose at least one device"));
  session::SessionParams params;
  params.meta = config.meta;
  params.estimator = config.estimator;
  params.movementCalibration = config.movementCalibration;
  params.calibration = config.calibration;
  params.flushInterval = storage::DatabaseRecordingSink::kFlushInterval;
  if (gate && gate->target()) {
    params.openSink = [this, gate](
                          const RecordingMeta& meta,
                          const RecordingColumns& columns) -> std::unique_ptr<RecordingSink> {
      {
        std::lock_guard lock(m_layoutMutex);
        m_layout = std::make_pair(meta, columns);
      }
      return std::make_unique<GatedRecordingSink>(gate, meta, columns);
    };
  }
  auto s = std::make_shared<session::Session>(params);
  QJsonObject devicesUsed;  // stored with the session, as `armtrack-cli record --db` does
  int index = 0;
  for (const QString& spec : config.devices) {
    ++index;
    const qsizetype colon = spec.indexOf(u':');
    const QString name = spec.left(colon).trimmed();
    devices::DevicePlugin* plugin = m_registry.plugin(name);
    if (!plugin)
      return fail(tr("no device plugin \"%1\"; found: %2. Check the plugin folders in the "
                     "settings.")
                      .arg(name, m_registry.names().join(QStringLiteral(", "))));
    QString why;
    const QVariantMap options =
        devices::Options::parse(colon < 0 ? QString() : spec.mid(colon + 1));
    std::unique_ptr<devices::Device> device = plugin->create(options, &why);
    if (!device) return fail(tr("%1: %2").arg(name, why));
    const QString label = QStringLiteral("%1#%2").arg(name).arg(index);
    devicesUsed.insert(label, deviceRecord(name, options, *device));
    s->addDevice(std::make_unique<devices::DeviceThread>(std::move(device), label), label);
  }
  if (gate && gate->target())
    gate->target()->setSessionSettings(sessionSettings(config, devicesUsed));
  connect(s.get(), &session::Session::deviceStateChanged, this,
          &SessionController::deviceStateChanged, Qt::QueuedConnection);
  connect(s.get(), &session::Session::problem, this, &SessionController::problem,
          Qt::QueuedConnection);
  if (const QString why = s->start(); !why.isEmpty())
    return fail(tr("the session could not start: %1").arg(why));
  if (!gate || !gate->target()) {
    std::lock_guard lock(m_layoutMutex);
    m_layout = std::make_pair(s->meta(), RecordingColumns{});
  }
  m_owned = s;
  QMetaObject::invokeMethod(this, [this, s] {
    m_session = s;
    emit started(QString());
    if (m_stopWhenStarted) stop();
  });
}

void SessionController::stop() {
  if (!m_session) {
    m_stopWhenStarted = m_busy;  // still starting: stop as soon as it runs
    return;
  }
  m_stopWhenStarted = false;
  m_session.reset();  // the GUI lets go first, so the session ends in the control thread
  QMetaObject::invokeMethod(m_worker, [this] {
    std::shared_ptr<session::Session> s = std::move(m_owned);
    if (!s) return;
    s->stop();
    const session::SessionStats st = s->stats();
    s.reset();  // devices and threads go away here, not on the GUI thread
    QMetaObject::invokeMethod(this, [this, st] {
      setBusy(false);
      emit stopped(st.recordedRows, st.rowsToRecord, QString::fromStdString(st.recorderError));
    });
  });
}

void SessionController::setBusy(bool busy) {
  if (m_busy == busy) return;
  m_busy = busy;
  emit busyChanged(busy);
}

}  // namespace armtrack::app::gui
