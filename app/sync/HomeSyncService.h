// The home sync for the home window: a HomeSyncClient on a worker thread of its own (the GUI
// thread never waits for the network or the disk), started at once and then on a timer while
// enrolled. The window reads status() and listens to statusChanged.
#pragma once

#include <QObject>
#include <QThread>
#include <QTimer>

#include "app/sync/HomeSyncClient.h"

namespace armtrack::sync {

class HomeSyncService : public QObject {
  Q_OBJECT
 public:
  /// records: the home install's records; folder: the state file's and outbox's folder.
  HomeSyncService(const storage::DatabaseUrl& records, const QString& folder,
                  int intervalMs = 5 * 60 * 1000, QObject* parent = nullptr);
  ~HomeSyncService() override;

  SyncStatus status() const { return m_status; }
  QString folder() const { return m_folder; }

 public slots:
  void syncNow();
  /// After the home window stored a session: counts it among those waiting, and sends it.
  void sessionStored();
  void enrol(const QString& server, const QString& code, const QString& label);

 signals:
  void statusChanged(const armtrack::sync::SyncStatus& status);
  void enrolFinished(bool ok, armtrack::sync::SyncProblem problem, const QString& detail);

 private:
  QString m_folder;
  QThread m_thread;
  HomeSyncClient* m_client;  // lives on m_thread, deleted when it ends
  QTimer m_timer;
  SyncStatus m_status;
};

}  // namespace armtrack::sync
