// What a home install keeps of its sync (docs/sync.md, "The home install"): the clinic's server
// address, the certificate pinned at enrolment, the device token and number, and each home
// session's upload (its UUID, checksum, chunks; sent or not). A SQLite file of its own in the
// application's data folder, mode 0600: the token is a secret, and the clinical records' schema
// stays the clinic's.
#pragma once

#include <QByteArray>
#include <QDateTime>
#include <QSqlDatabase>
#include <QString>
#include <optional>

namespace armtrack::sync {

struct DeviceState {
  QString serverUrl;       ///< "https://host:port"
  QByteArray certificate;  ///< the server's certificate seen at enrolment, PEM
  QByteArray token;        ///< the device token (a bearer token)
  qint64 device = 0;       ///< the device's number at the clinic
  QString patient;         ///< the patient's code at the clinic
  bool enrolled() const { return !token.isEmpty() && !certificate.isEmpty(); }
};

/// One local session's upload.
struct UploadRecord {
  qint64 sessionId = 0;  ///< in the local records
  QString uuid;          ///< names the upload at the server until it is acknowledged
  QString sha256;        ///< of the exported CSV
  qint64 sizeBytes = 0;
  int chunks = 0;
  bool declared = false;     ///< the server has been told of it
  qint64 serverSession = 0;  ///< the clinic's session id, once acknowledged
  QDateTime sentAt;          ///< when the 200 of complete came (UTC); null before
  bool sent() const { return sentAt.isValid(); }
};

class SyncState {
 public:
  /// Opens (or creates, mode 0600) folder/homesync.sqlite on this thread. Throws
  /// std::runtime_error saying what to do when it cannot.
  explicit SyncState(const QString& folder);
  ~SyncState();
  SyncState(const SyncState&) = delete;
  SyncState& operator=(const SyncState&) = delete;

  QString folder() const { return m_folder; }
  QString filePath() const;

  DeviceState device() const;
  void saveDevice(const DeviceState& state);

  std::optional<UploadRecord> upload(qint64 sessionId) const;
  void saveUpload(const UploadRecord& record);
  void forgetUpload(qint64 sessionId);
  /// The time of the latest acknowledged upload (UTC); null when none.
  QDateTime lastSent() const;

 private:
  QString m_folder;
  QString m_connection;
  QSqlDatabase db() const;
};

}  // namespace armtrack::sync
