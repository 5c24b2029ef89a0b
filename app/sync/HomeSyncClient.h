// The home install's sync client (docs/sync.md, "The home install"): enrols with the clinic's
// armtrack-server and pins the certificate it sees then; later fetches the programme into the
// local records and uploads the home sessions not yet acknowledged (declare, chunks, complete;
// after a dropped connection it asks the server what is missing). A session counts as sent only
// after the 200 of complete. Asynchronous (QNetworkAccessManager) on the thread it lives on;
// the local records are opened on that thread too, so it belongs on a worker thread
// (HomeSyncService) or, in tests, on the test's own.
#pragma once

#include <QDateTime>
#include <QNetworkAccessManager>
#include <QObject>
#include <QSslCertificate>
#include <QUrl>
#include <deque>
#include <functional>
#include <memory>

#include "app/sync/SyncState.h"
#include "core/storage/DatabaseUrl.h"

class QNetworkReply;

namespace armtrack::storage {
class Database;
class ClinicalStore;
}  // namespace armtrack::storage

namespace armtrack::sync {

/// Why the last attempt stopped (the home window says it in its own words).
enum class SyncProblem {
  None,
  NotEnrolled,         ///< no server yet
  Offline,             ///< the server could not be reached (sessions are kept)
  CertificateChanged,  ///< the server showed another certificate than the one pinned
  Refused,             ///< the token was refused (401: revoked), or the code at enrolment
  ServerError,         ///< the server answered with an error
  LocalError,          ///< the local records or the state file failed
};

struct SyncStatus {
  bool enrolled = false;
  bool busy = false;
  int waiting = 0;        ///< home sessions not yet acknowledged by the server
  QDateTime lastSent;     ///< UTC, the last acknowledgement; null when none
  QDateTime lastContact;  ///< UTC, the last time the server answered; null when never
  SyncProblem problem = SyncProblem::None;
  QString detail;                 ///< for the log: what failed, in English
  QString server;                 ///< the server's address
  bool programmeChanged = false;  ///< the last sync brought another programme
};

class HomeSyncClient : public QObject {
  Q_OBJECT
 public:
  struct Options {
    qint64 chunkBytes = 1 << 20;  ///< per chunk (the server takes up to 8 MiB)
    int timeoutMs = 30000;        ///< a request quiet this long is given up
  };
  /// records: the home install's own records (opened on this object's thread when needed);
  /// folder: where the state file and the outgoing copies are kept.
  HomeSyncClient(storage::DatabaseUrl records, QString folder, Options options,
                 QObject* parent = nullptr);
  ~HomeSyncClient() override;

  SyncStatus status() const { return m_status; }

 public slots:
  /// Enrols at server ("https://host:port") with a code from the therapist; the certificate
  /// the server shows now is pinned. Emits enrolFinished.
  void enrol(const QString& server, const QString& code, const QString& label);
  /// Fetches the programme and uploads what is waiting; emits synced once done or stopped.
  void sync();
  /// Recounts the sessions waiting (after the home window stored one); emits statusChanged.
  void refresh();

 signals:
  void enrolFinished(bool ok, armtrack::sync::SyncProblem problem, const QString& detail);
  void statusChanged(const armtrack::sync::SyncStatus& status);
  void synced(const armtrack::sync::SyncStatus& status);
  /// A chunk was accepted (the tests cut the connection between chunks).
  void chunkSent(qint64 sessionId, int chunk);
  /// A session was acknowledged whole.
  void sessionSent(qint64 sessionId, qint64 serverSession);

 private:
  struct Answer {
    int status = 0;  ///< 0: no answer
    QByteArray body;
    SyncProblem problem = SyncProblem::None;
    QString error;
    QSslCertificate peer;  ///< the certificate the server showed
  };
  using Done = std::function<void(const Answer&)>;
  /// A request to the enrolled server with the token, the certificate pinned (pinning), or to
  /// base without either (enrolment).
  void request(const QByteArray& verb, const QString& path, const QByteArray& body,
               const QList<QPair<QByteArray, QByteArray>>& headers, bool pinning, Done done,
               const QString& base = {});
  storage::ClinicalStore& store();
  SyncState& state();
  void finish(SyncProblem problem, const QString& detail);
  void countWaiting();
  std::vector<qint64> waitingSessions();
  void uploadNext();
  void upload(const UploadRecord& record);
  void sendChunks(UploadRecord record, std::deque<int> missing);
  void complete(UploadRecord record);
  UploadRecord prepare(qint64 sessionId);
  QString outboxPath(qint64 sessionId, const char* ext) const;
  void stopOn(const Answer& a, const QString& what);

  storage::DatabaseUrl m_url;
  QString m_folder;
  Options m_options;
  QNetworkAccessManager m_net{this};  // a child: it moves to the client's thread with it
  std::unique_ptr<SyncState> m_state;
  std::unique_ptr<storage::Database> m_db;
  std::unique_ptr<storage::ClinicalStore> m_store;
  DeviceState m_device;
  QSslCertificate m_pinned;
  SyncStatus m_status;
  std::deque<qint64> m_queue;
};

}  // namespace armtrack::sync

Q_DECLARE_METATYPE(armtrack::sync::SyncStatus)
