#include "app/server/Tls.h"

#include <QFile>
#include <QSslCertificate>
#include <QSslKey>
#include <QSslSocket>
#include <stdexcept>

namespace armtrack::server {

QSslConfiguration serverTls(const QString& certPath, const QString& keyPath) {
  if (!QSslSocket::supportsSsl())
    throw std::runtime_error(
        "TLS is not available: Qt found no TLS backend (install OpenSSL 3, libssl3)");
  const QList<QSslCertificate> chain = QSslCertificate::fromPath(certPath, QSsl::Pem);
  if (chain.isEmpty() || chain.first().isNull())
    throw std::runtime_error("--cert: no PEM certificate in '" + certPath.toStdString() + "'");
  QFile keyFile(keyPath);
  if (!keyFile.open(QIODevice::ReadOnly))
    throw std::runtime_error("--key: cannot read '" + keyPath.toStdString() +
                             "': " + keyFile.errorString().toStdString());
  const QByteArray pem = keyFile.readAll();
  QSslKey key(pem, QSsl::Rsa, QSsl::Pem);
  if (key.isNull()) key = QSslKey(pem, QSsl::Ec, QSsl::Pem);
  if (key.isNull())
    throw std::runtime_error("--key: no unencrypted PEM RSA or EC private key in '" +
                             keyPath.toStdString() + "'");
  QSslConfiguration tls = QSslConfiguration::defaultConfiguration();
  tls.setLocalCertificateChain(chain);
  tls.setPrivateKey(key);
  tls.setProtocol(QSsl::TlsV1_2OrLater);
  tls.setPeerVerifyMode(QSslSocket::VerifyNone);  // devices prove themselves by token
  return tls;
}

}  // namespace armtrack::server
