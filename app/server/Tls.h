// The TLS setup of armtrack-server: its certificate and key from PEM files.
#pragma once

#include <QSslConfiguration>
#include <QString>

namespace armtrack::server {

/// A server configuration with the certificate chain in certPath (PEM, the server's first) and
/// the private key in keyPath (PEM, RSA or EC, unencrypted), TLS 1.2 or newer. Throws
/// std::runtime_error saying what to do when TLS is not available or a file is unusable.
QSslConfiguration serverTls(const QString& certPath, const QString& keyPath);

}  // namespace armtrack::server
