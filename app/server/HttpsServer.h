// A small HTTP/1.1 server over TLS only (QSslServer), for armtrack-server (docs/sync.md). It
// reads a request's headers first and refuses a body over the limit (413) before reading it, so
// no client can make the server hold more than one request of at most maxBodyBytes per
// connection; bodies must come with Content-Length (no chunked transfer coding).
#pragma once

#include <QByteArray>
#include <QHash>
#include <QHostAddress>
#include <QObject>
#include <QPointer>
#include <QSslConfiguration>
#include <QString>
#include <functional>

class QSslServer;
class QSslSocket;

namespace armtrack::server {

struct HttpRequest {
  QByteArray method;                      ///< "GET", "PUT", ...
  QString path;                           ///< percent-decoded, without the query
  QHash<QByteArray, QByteArray> headers;  ///< names in lower case
  QByteArray body;
  QHostAddress peer;
  QByteArray header(const QByteArray& lowerName) const { return headers.value(lowerName); }
};

struct HttpResponse {
  int status = 200;
  QByteArray body;  ///< JSON unless contentType says otherwise
  QByteArray contentType = "application/json";
  QList<QPair<QByteArray, QByteArray>> headers;
};

class HttpsServer : public QObject {
  Q_OBJECT
 public:
  using Handler = std::function<HttpResponse(const HttpRequest&)>;
  /// Sends a request's answer; callable once, from the server's thread, at any later time (a
  /// connection closed meanwhile makes it do nothing).
  using Responder = std::function<void(const HttpResponse&)>;
  /// A handler that may answer later (SyncApi's completions run on a worker): the connection
  /// reads no further request until it has answered, so answers keep the requests' order.
  using AsyncHandler = std::function<void(const HttpRequest&, Responder)>;
  struct Limits {
    qint64 maxBodyBytes = 9 << 20;  ///< a larger Content-Length gets 413
    int maxHeaderBytes = 16 << 10;  ///< larger headers get 431
    int idleTimeoutMs = 60000;      ///< a connection quiet this long is closed
    int maxConnections = 256;       ///< more are closed at once
  };
  HttpsServer(const QSslConfiguration& tls, Limits limits, Handler handler,
              QObject* parent = nullptr);
  HttpsServer(const QSslConfiguration& tls, Limits limits, AsyncHandler handler,
              QObject* parent = nullptr);
  ~HttpsServer() override;
  bool listen(const QHostAddress& address, quint16 port);
  quint16 port() const;
  QString errorString() const;

  static QByteArray reason(int status);  ///< "OK", "Not Found", ...

 private:
  struct Connection;
  void accept();
  void readFrom(QSslSocket* socket);
  void respond(QSslSocket* socket, const HttpResponse& response, bool close);

  QSslServer* m_server;
  Limits m_limits;
  AsyncHandler m_handler;
  int m_connections = 0;
};

}  // namespace armtrack::server
