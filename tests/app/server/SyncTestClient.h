// A small HTTPS client for the sync server's tests: one request per call on a fresh TLS
// connection that trusts the test's own certificate, waiting in a local event loop so the
// in-process server keeps running. It can cut the connection after a number of body bytes.
#pragma once

#include <QByteArray>
#include <QEventLoop>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSslCertificate>
#include <QSslConfiguration>
#include <QSslSocket>
#include <QTimer>

namespace armtrack::server::test {

struct Reply {
  int status = 0;  ///< 0: no answer (the connection was closed or cut)
  QByteArray body;
  QJsonObject json() const { return QJsonDocument::fromJson(body).object(); }
};

class SyncTestClient {
 public:
  SyncTestClient(quint16 port, QSslCertificate ca) : m_port(port), m_ca(std::move(ca)) {}
  QByteArray token;             ///< sent as a bearer token when set
  int answerTimeoutMs = 60000;  ///< how long to wait for an answer once the request is sent

  /// Sends the request; with cutAfter >= 0 the connection is aborted after the headers and that
  /// many bytes of the body, and no answer is awaited.
  Reply send(const QByteArray& method, const QByteArray& path, const QByteArray& body = {},
             QList<QPair<QByteArray, QByteArray>> headers = {}, qsizetype cutAfter = -1) {
    QSslSocket socket;
    QSslConfiguration tls = QSslConfiguration::defaultConfiguration();
    tls.setCaCertificates({m_ca});
    socket.setSslConfiguration(tls);
    QEventLoop loop;
    Reply reply;
    QByteArray in;
    QTimer timeout;
    timeout.setSingleShot(true);
    QObject::connect(&timeout, &QTimer::timeout, &loop, &QEventLoop::quit);
    QObject::connect(&socket, &QSslSocket::encrypted, &loop, &QEventLoop::quit);
    QObject::connect(&socket, &QSslSocket::disconnected, &loop, &QEventLoop::quit);
    QObject::connect(&socket, &QSslSocket::errorOccurred, &loop, &QEventLoop::quit);
    socket.connectToHostEncrypted("localhost", m_port);
    timeout.start(10000);
    loop.exec();
    if (!socket.isEncrypted()) return reply;
    QByteArray request = method + ' ' + path + " HTTP/1.1\r\nHost: localhost\r\n";
    if (!token.isEmpty()) request += "Authorization: Bearer " + token + "\r\n";
    for (const auto& [k, v] : headers) request += k + ": " + v + "\r\n";
    bool explicitLength = false;
    for (const auto& h : headers) explicitLength |= h.first.toLower() == "content-length";
    if (!explicitLength) request += "Content-Length: " + QByteArray::number(body.size()) + "\r\n";
    request += "\r\n";
    if (cutAfter >= 0) {
      socket.write(request + body.left(cutAfter));
      socket.flush();
      QTimer::singleShot(100, &loop, &QEventLoop::quit);  // let the bytes reach the server
      loop.exec();
      socket.abort();
      return reply;
    }
    socket.write(request + body);
    QObject::connect(&socket, &QSslSocket::readyRead, &loop, [&] {
      in += socket.readAll();
      const qsizetype end = in.indexOf("\r\n\r\n");
      if (end < 0) return;
      const qsizetype at = in.toLower().indexOf("content-length:");
      const qsizetype eol = in.indexOf("\r\n", at);
      const qsizetype length = in.mid(at + 15, eol - at - 15).trimmed().toLongLong();
      if (in.size() - end - 4 >= length) {
        reply.status = in.mid(9, 3).toInt();
        reply.body = in.mid(end + 4, length);
        loop.quit();
      }
    });
    timeout.start(answerTimeoutMs);
    loop.exec();
    return reply;
  }

 private:
  quint16 m_port;
  QSslCertificate m_ca;
};

}  // namespace armtrack::server::test
