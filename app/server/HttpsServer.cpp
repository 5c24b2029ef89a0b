#include "app/server/HttpsServer.h"

#include <QSslServer>
#include <QSslSocket>
#include <QTimer>
#include <QUrl>
#include <memory>

namespace armtrack::server {

/// Where a connection's request stands, kept on the socket.
struct HttpsServer::Connection : QObject {
  QByteArray buffer;
  bool inBody = false;
  bool waiting = false;  ///< a request is being answered (by an AsyncHandler, later)
  qint64 bodyLength = 0;
  HttpRequest request;
  QTimer idle;
  explicit Connection(QObject* parent) : QObject(parent) { idle.setSingleShot(true); }
};

HttpsServer::HttpsServer(const QSslConfiguration& tls, Limits limits, Handler handler,
                         QObject* parent)
    : HttpsServer(
          tls, limits,
          [handler = std::move(handler)](const HttpRequest& r, Responder done) {
            done(handler(r));
          },
          parent) {}

HttpsServer::HttpsServer(const QSslConfiguration& tls, Limits limits, AsyncHandler handler,
                         QObject* parent)
    : QObject(parent),
      m_server(new QSslServer(this)),
      m_limits(limits),
      m_handler(std::move(handler)) {
  m_server->setSslConfiguration(tls);
  m_server->setHandshakeTimeout(10000);
  connect(m_server, &QSslServer::pendingConnectionAvailable, this, &HttpsServer::accept);
}

HttpsServer::~HttpsServer() = default;

bool HttpsServer::listen(const QHostAddress& address, quint16 port) {
  return m_server->listen(address, port);
}

quint16 HttpsServer::port() const {
  return m_server->serverPort();
}

QString HttpsServer::errorString() const {
  return m_server->errorString();
}

QByteArray HttpsServer::reason(int status) {
  switch (status) {
    case 200:
      return "OK";
    case 201:
      return "Created";
    case 400:
      return "Bad Request";
    case 401:
      return "Unauthorized";
    case 404:
      return "Not Found";
    case 405:
      return "Method Not Allowed";
    case 409:
      return "Conflict";
    case 411:
      return "Length Required";
    case 413:
      return "Content Too Large";
    case 422:
      return "Unprocessable Content";
    case 429:
      return "Too Many Requests";
    case 431:
      return "Request Header Fields Too Large";
    case 501:
      return "Not Implemented";
    case 503:
      return "Service Unavailable";
    default:
      return status < 500 ? "Error" : "Internal Server Error";
  }
}

void HttpsServer::accept() {
  while (m_server->hasPendingConnections()) {
    auto* socket = qobject_cast<QSslSocket*>(m_server->nextPendingConnection());
    if (!socket) continue;
    if (m_connections >= m_limits.maxConnections) {
      socket->abort();
      socket->deleteLater();
      continue;
    }
    ++m_connections;
    auto* c = new Connection(socket);
    c->setObjectName("http-connection");
    c->request.peer = socket->peerAddress();
    connect(&c->idle, &QTimer::timeout, socket, &QSslSocket::abort);
    c->idle.start(m_limits.idleTimeoutMs);
    connect(socket, &QSslSocket::readyRead, this, [this, socket] { readFrom(socket); });
    connect(socket, &QSslSocket::disconnected, this, [this, socket] {
      --m_connections;
      socket->deleteLater();
    });
    if (socket->bytesAvailable() > 0) readFrom(socket);
  }
}

void HttpsServer::readFrom(QSslSocket* socket) {
  auto* c = socket->findChild<Connection*>("http-connection", Qt::FindDirectChildrenOnly);
  if (!c || socket->state() != QAbstractSocket::ConnectedState) return;
  c->idle.start(m_limits.idleTimeoutMs);
  c->buffer += socket->readAll();
  if (c->waiting) return;  // read on once the request before is answered
  const auto fail = [&](int status, const QByteArray& why) {
    respond(socket, {status, "{\"error\":\"" + why + "\"}", "application/json", {}}, true);
  };
  while (socket->state() == QAbstractSocket::ConnectedState) {
    if (!c->inBody) {
      const qsizetype end = c->buffer.indexOf("\r\n\r\n");
      if (end < 0) {
        if (c->buffer.size() > m_limits.maxHeaderBytes) fail(431, "request headers too large");
        return;
      }
      if (end > m_limits.maxHeaderBytes) return fail(431, "request headers too large");
      const QList<QByteArray> lines = c->buffer.left(end).split('\n');
      c->buffer.remove(0, end + 4);
      const QList<QByteArray> first = lines.value(0).trimmed().split(' ');
      if (first.size() != 3 || !first[2].startsWith("HTTP/1."))
        return fail(400, "not an HTTP/1.1 request");
      HttpRequest& r = c->request;
      r.method = first[0];
      const QUrl url(QString::fromLatin1(first[1]));
      r.path = url.path(QUrl::FullyDecoded);
      r.headers.clear();
      r.body.clear();
      for (qsizetype i = 1; i < lines.size(); ++i) {
        const qsizetype colon = lines[i].indexOf(':');
        if (colon <= 0) return fail(400, "malformed header line");
        r.headers.insert(lines[i].left(colon).trimmed().toLower(),
                         lines[i].mid(colon + 1).trimmed());
      }
      if (r.headers.contains("transfer-encoding"))
        return fail(501, "send bodies with Content-Length, not chunked transfer coding");
      bool ok = true;
      c->bodyLength =
          r.headers.contains("content-length") ? r.header("content-length").toLongLong(&ok) : 0;
      if (!ok || c->bodyLength < 0) return fail(400, "malformed Content-Length");
      if (c->bodyLength > m_limits.maxBodyBytes) return fail(413, "request body too large");
      c->inBody = true;
    }
    if (c->buffer.size() < c->bodyLength) return;  // the rest is still coming
    c->request.body = c->buffer.left(c->bodyLength);
    c->buffer.remove(0, c->bodyLength);
    c->inBody = false;
    const bool close = c->request.header("connection").toLower() == "close";
    c->waiting = true;
    c->idle.stop();  // a long answer (an analysis) is no idle client
    // 0: the handler is running, 1: it answered before returning, 2: it will answer later.
    const auto when = std::make_shared<int>(0);
    const QPointer<QSslSocket> alive(socket);
    m_handler(c->request, [this, alive, c, close, when](const HttpResponse& response) {
      if (!alive || alive->state() != QAbstractSocket::ConnectedState) return;
      c->waiting = false;
      c->idle.start(m_limits.idleTimeoutMs);
      respond(alive, response, close);
      if (*when == 0) {
        *when = 1;  // answered at once: the loop reads on
        return;
      }
      // Answered later: requests that came meanwhile wait in the buffer.
      QMetaObject::invokeMethod(
          this,
          [this, alive] {
            if (alive) readFrom(alive);
          },
          Qt::QueuedConnection);
    });
    c->request.body.clear();
    if (*when == 0) {
      *when = 2;
      return;
    }
  }
}

void HttpsServer::respond(QSslSocket* socket, const HttpResponse& response, bool close) {
  QByteArray out =
      "HTTP/1.1 " + QByteArray::number(response.status) + ' ' + reason(response.status) + "\r\n";
  out += "Content-Type: " + response.contentType + "\r\n";
  out += "Content-Length: " + QByteArray::number(response.body.size()) + "\r\n";
  out += "Cache-Control: no-store\r\nStrict-Transport-Security: max-age=31536000\r\n";
  for (const auto& [name, value] : response.headers) out += name + ": " + value + "\r\n";
  if (close) out += "Connection: close\r\n";
  out += "\r\n" + response.body;
  socket->write(out);
  if (close) socket->disconnectFromHost();
}

}  // namespace armtrack::server
