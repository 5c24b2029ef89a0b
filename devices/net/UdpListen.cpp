#include "devices/net/UdpListen.h"

#include <QLoggingCategory>
#include <QUdpSocket>
#include <QVariant>

#include "core/devices/Stream.h"

namespace armtrack::devices {

QString listenUdp(QUdpSocket& socket, std::uint16_t port, const QString& portOption,
                  const QLoggingCategory& log) {
  if (!socket.bind(QHostAddress::Any, port, QAbstractSocket::DontShareAddress)) {
    if (socket.error() == QAbstractSocket::AddressInUseError)
      return QStringLiteral(
                 "UDP port %1 is already in use (another device or program listens on it): "
                 "choose another port with %2=")
          .arg(port)
          .arg(portOption);
    return QStringLiteral("cannot listen on UDP port %1: %2").arg(port).arg(socket.errorString());
  }
  socket.setSocketOption(QAbstractSocket::ReceiveBufferSizeSocketOption, kUdpReceiveBufferBytes);
  qCInfo(log) << "listening on UDP port" << port << "receive buffer"
              << socket.socketOption(QAbstractSocket::ReceiveBufferSizeSocketOption).toInt()
              << "bytes";
  return {};
}

void readDatagrams(
    QUdpSocket& socket, QByteArray& buffer,
    const std::function<void(std::span<const char> bytes, double arrival)>& onDatagram) {
  int reads = 0;
  do {
    const qint64 size = socket.pendingDatagramSize();
    if (size > buffer.size()) buffer.resize(size);
    const qint64 got = socket.readDatagram(buffer.data(), buffer.size());
    const double arrival = hostNow();
    if (got < 0) break;
    onDatagram(std::span<const char>(buffer.constData(), static_cast<std::size_t>(got)), arrival);
  } while (++reads < kMaxDatagramsPerRead && socket.hasPendingDatagrams());
}

}  // namespace armtrack::devices
