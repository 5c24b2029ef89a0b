// What the sync tests share besides their fixtures: a self-signed certificate for localhost made
// with openssl (the server's, or a second one a pinned client must refuse), and a file's SHA-256
// to compare a recording at home and at the clinic.
#pragma once

#include <QCryptographicHash>
#include <QFile>
#include <QProcess>
#include <QString>
#include <QTemporaryDir>
#include <utility>

namespace armtrack::test {

/// The certificate and key (PEM) written as NAME.crt and NAME.key in dir; empty paths when openssl
/// failed.
inline std::pair<QString, QString> makeCertificate(const QTemporaryDir& dir,
                                                   const QString& name = QStringLiteral("server")) {
  const QString cert = dir.filePath(name + ".crt"), key = dir.filePath(name + ".key");
  QProcess p;
  p.start(QStringLiteral("openssl"),
          {"req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", key, "-out", cert, "-days",
           "1", "-subj", "/CN=localhost", "-addext", "subjectAltName=DNS:localhost,IP:127.0.0.1"});
  if (!p.waitForFinished(60000) || p.exitCode() != 0) return {};
  return {cert, key};
}

/// The file's SHA-256 in lower-case hex; empty when it cannot be read.
inline QString fileSha256(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {};
  QCryptographicHash h(QCryptographicHash::Sha256);
  h.addData(&f);
  return QString::fromLatin1(h.result().toHex());
}

}  // namespace armtrack::test
