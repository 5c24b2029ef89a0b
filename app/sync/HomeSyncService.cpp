#include "app/sync/HomeSyncService.h"

namespace armtrack::sync {

HomeSyncService::HomeSyncService(const storage::DatabaseUrl& records, const QString& folder,
                                 int intervalMs, QObject* parent)
    : QObject(parent), m_folder(folder) {
  m_client = new HomeSyncClient(records, folder, {});
  m_client->moveToThread(&m_thread);
  connect(&m_thread, &QThread::finished, m_client, &QObject::deleteLater);
  connect(m_client, &HomeSyncClient::statusChanged, this, [this](const SyncStatus& s) {
    m_status = s;
    emit statusChanged(s);
  });
  connect(m_client, &HomeSyncClient::enrolFinished, this,
          [this](bool ok, SyncProblem p, const QString& detail) {
            emit enrolFinished(ok, p, detail);
            if (ok) syncNow();
          });
  m_thread.setObjectName("home sync");
  m_thread.start();
  m_timer.setInterval(intervalMs);
  connect(&m_timer, &QTimer::timeout, this, &HomeSyncService::syncNow);
  m_timer.start();
  QMetaObject::invokeMethod(m_client, &HomeSyncClient::refresh, Qt::QueuedConnection);
  syncNow();
}

HomeSyncService::~HomeSyncService() {
  m_timer.stop();
  m_thread.quit();
  // A request under way is abandoned with the thread; the upload resumes next time.
  m_thread.wait();
}

void HomeSyncService::syncNow() {
  QMetaObject::invokeMethod(m_client, &HomeSyncClient::sync, Qt::QueuedConnection);
}

void HomeSyncService::sessionStored() {
  QMetaObject::invokeMethod(m_client, &HomeSyncClient::refresh, Qt::QueuedConnection);
  syncNow();
}

void HomeSyncService::enrol(const QString& server, const QString& code, const QString& label) {
  QMetaObject::invokeMethod(
      m_client, [c = m_client, server, code, label] { c->enrol(server, code, label); },
      Qt::QueuedConnection);
}

}  // namespace armtrack::sync
