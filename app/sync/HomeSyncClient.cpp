#include "app/sync/HomeSyncClient.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QNetworkReply>
#include <QNetworkRequest>
#include <QSslConfiguration>
#include <QTimer>

#include "app/sync/ProgrammeCache.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/Database.h"

namespace armtrack::sync {

HomeSyncClient::HomeSyncClient(storage::DatabaseUrl records, QString folder, Options options,
                               QObject* parent)
    : QObject(parent), m_url(std::move(records)), m_folder(std::move(folder)), m_options(options) {
  qRegisterMetaType<armtrack::sync::SyncStatus>();
  qRegisterMetaType<armtrack::sync::SyncProblem>();
  // Each request on a connection of its own: a connection opened before the server changed
  // (or before a pinned check) is never reused for the next one.
  m_net.setAutoDeleteReplies(true);
}

HomeSyncClient::~HomeSyncClient() = default;

SyncState& HomeSyncClient::state() {
  if (!m_state) {
    m_state = std::make_unique<SyncState>(m_folder);
    m_device = m_state->device();
    m_pinned = QSslCertificate(m_device.certificate, QSsl::Pem);
    m_status.enrolled = m_device.enrolled();
    m_status.server = m_device.serverUrl;
  }
  return *m_state;
}

storage::ClinicalStore& HomeSyncClient::store() {
  if (!m_store) {
    m_db = std::make_unique<storage::Database>(m_url, storage::Database::Options{});
    m_store = std::make_unique<storage::ClinicalStore>(*m_db);
    m_store->signInAsService("armtrack-home-sync");
  }
  return *m_store;
}

void HomeSyncClient::request(const QByteArray& verb, const QString& path, const QByteArray& body,
                             const QList<QPair<QByteArray, QByteArray>>& headers, bool pinning,
                             Done done, const QString& base) {
  QNetworkRequest req(QUrl((pinning ? m_device.serverUrl : base) + path));
  req.setAttribute(QNetworkRequest::Http2AllowedAttribute, false);
  req.setTransferTimeout(m_options.timeoutMs);
  req.setHeader(QNetworkRequest::ContentTypeHeader, "application/json");
  if (pinning && !m_device.token.isEmpty())
    req.setRawHeader("Authorization", "Bearer " + m_device.token);
  for (const auto& [k, v] : headers) req.setRawHeader(k, v);
  QSslConfiguration tls = QSslConfiguration::defaultConfiguration();
  tls.setProtocol(QSsl::TlsV1_2OrLater);
  req.setSslConfiguration(tls);
  QNetworkReply* reply = m_net.sendCustomRequest(req, verb, body);
  auto pinFailed = std::make_shared<bool>(false);
  // The certificate is the pinned one or nothing: the system's CAs neither add nor take away.
  // At enrolment (pinning false) any certificate is taken, and kept.
  connect(reply, &QNetworkReply::sslErrors, reply, [this, reply, pinning](const auto& errors) {
    const QSslCertificate seen = reply->sslConfiguration().peerCertificate();
    if (!pinning || (!m_pinned.isNull() && seen == m_pinned)) reply->ignoreSslErrors(errors);
  });
  connect(reply, &QNetworkReply::encrypted, reply, [this, reply, pinning, pinFailed] {
    if (pinning && reply->sslConfiguration().peerCertificate() != m_pinned) {
      *pinFailed = true;
      reply->abort();
    }
  });
  connect(
      reply, &QNetworkReply::finished, this,
      [this, reply, pinning, pinFailed, done = std::move(done)] {
        Answer a;
        a.status = reply->attribute(QNetworkRequest::HttpStatusCodeAttribute).toInt();
        a.body = reply->readAll();
        a.peer = reply->sslConfiguration().peerCertificate();
        if (*pinFailed || (pinning && reply->error() == QNetworkReply::SslHandshakeFailedError)) {
          a.status = 0;
          a.problem = SyncProblem::CertificateChanged;
          a.error = "the server's certificate is not the one pinned at enrolment";
        } else if (a.status == 0) {
          a.problem = SyncProblem::Offline;
          a.error = reply->errorString();
        } else if (a.status == 401) {
          a.problem = SyncProblem::Refused;
        } else if (a.status >= 400) {
          a.problem = SyncProblem::ServerError;
        }
        if (a.status >= 400)
          a.error = QJsonDocument::fromJson(a.body).object().value("error").toString(
              QString::number(a.status));
        try {
          done(a);
        } catch (const std::exception& e) {  // the state file or the local records failed
          finish(SyncProblem::LocalError, QString::fromLocal8Bit(e.what()));
        }
      });
}

void HomeSyncClient::enrol(const QString& server, const QString& code, const QString& label) {
  // Refusals before any request are told after this call too, as the others are.
  const auto refuse = [this](SyncProblem problem, const QString& detail) {
    QTimer::singleShot(0, this,
                       [this, problem, detail] { emit enrolFinished(false, problem, detail); });
  };
  try {
    state();
  } catch (const std::exception& e) {
    return refuse(SyncProblem::LocalError, QString::fromLocal8Bit(e.what()));
  }
  // "sync.clinic.example:8443" is read as https://sync.clinic.example:8443; http:// becomes
  // https:// (TLS only).
  QString typed = server.trimmed();
  if (typed.startsWith("http://", Qt::CaseInsensitive)) typed = "https://" + typed.mid(7);
  if (!typed.contains("://")) typed.prepend("https://");
  QUrl url(typed, QUrl::StrictMode);
  if (!url.isValid() || url.host().isEmpty() || url.scheme() != "https") {
    return refuse(SyncProblem::Offline, "not a server address: " + server);
  }
  url.setPath({});
  const QString serverUrl = url.toString(QUrl::RemoveUserInfo | QUrl::StripTrailingSlash);
  const QByteArray body = QJsonDocument(QJsonObject{{"code", code.trimmed()}, {"label", label}})
                              .toJson(QJsonDocument::Compact);
  request(
      "POST", "/api/v1/enrol", body, {}, false,
      [this, serverUrl](const Answer& a) {
        const QJsonObject o = QJsonDocument::fromJson(a.body).object();
        if (a.status != 201 || a.peer.isNull() || o.value("token").toString().isEmpty()) {
          // A failed enrolment keeps what was there.
          emit enrolFinished(false,
                             a.problem == SyncProblem::None ? SyncProblem::ServerError : a.problem,
                             a.error);
          return;
        }
        DeviceState d;
        d.serverUrl = serverUrl;
        d.certificate = a.peer.toPem();
        d.token = o.value("token").toString().toLatin1();
        d.device = o.value("device").toInteger();
        d.patient = o.value("patient").toString();
        try {
          state().saveDevice(d);
        } catch (const std::exception& e) {
          emit enrolFinished(false, SyncProblem::LocalError, QString::fromLocal8Bit(e.what()));
          return;
        }
        m_device = d;
        m_pinned = a.peer;
        m_status.enrolled = true;
        m_status.server = d.serverUrl;
        m_status.problem = SyncProblem::None;
        m_status.lastContact = QDateTime::currentDateTimeUtc();
        emit enrolFinished(true, SyncProblem::None, QString());
        emit statusChanged(m_status);
      },
      serverUrl);
}

void HomeSyncClient::finish(SyncProblem problem, const QString& detail) {
  m_queue.clear();
  m_status.busy = false;
  m_status.problem = problem;
  m_status.detail = detail;
  countWaiting();
  emit statusChanged(m_status);
  emit synced(m_status);
  m_status.programmeChanged = false;  // told once
}

void HomeSyncClient::stopOn(const Answer& a, const QString& what) {
  finish(a.problem == SyncProblem::None ? SyncProblem::ServerError : a.problem,
         what + ": " + a.error);
}

void HomeSyncClient::refresh() {
  try {
    state();
    countWaiting();
  } catch (const std::exception& e) {
    m_status.problem = SyncProblem::LocalError;
    m_status.detail = QString::fromLocal8Bit(e.what());
  }
  emit statusChanged(m_status);
}

void HomeSyncClient::sync() {
  if (m_status.busy) return;
  try {
    state();
  } catch (const std::exception& e) {
    const QString why = QString::fromLocal8Bit(e.what());
    QTimer::singleShot(0, this, [this, why] { finish(SyncProblem::LocalError, why); });
    return;
  }
  if (!m_device.enrolled()) {  // told after this call, as every other end is
    QTimer::singleShot(0, this, [this] { finish(SyncProblem::NotEnrolled, {}); });
    return;
  }
  m_status.busy = true;
  emit statusChanged(m_status);
  request("GET", "/api/v1/programme", {}, {}, true, [this](const Answer& a) {
    if (a.status != 200) return stopOn(a, "programme");
    m_status.lastContact = QDateTime::currentDateTimeUtc();
    try {
      m_status.programmeChanged =
          cacheProgramme(store(), m_device.patient, QJsonDocument::fromJson(a.body).object());
      const std::vector<qint64> waiting = waitingSessions();
      m_queue.assign(waiting.begin(), waiting.end());
    } catch (const std::exception& e) {
      return finish(SyncProblem::LocalError, QString::fromLocal8Bit(e.what()));
    }
    uploadNext();
  });
}

}  // namespace armtrack::sync
