// What the UDP devices (NGIMU, skeleton tracker, line-protocol IMU) share: listening on a port
// with a large receive buffer, and reading datagrams in bounded batches, each stamped with the
// host time at which it was read.
#pragma once

#include <QByteArray>
#include <QString>
#include <cstdint>
#include <functional>
#include <span>

class QLoggingCategory;
class QUdpSocket;

namespace armtrack::devices {

/// The receive buffer asked of the kernel: it rides out bursts (a flood on the port, a busy
/// host) without losses. The kernel caps it (net.core.rmem_max on Linux); the size granted is
/// logged.
inline constexpr int kUdpReceiveBufferBytes = 4 << 20;

/// Datagrams read per readyRead(); then the event loop gets a turn.
inline constexpr int kMaxDatagramsPerRead = 512;

/// Binds socket to port on every address, not shared with another socket, asks for the receive
/// buffer and logs the size granted. Returns an empty string, or what is wrong and what to do;
/// portOption names the device option that sets the port ("port", "udp").
QString listenUdp(QUdpSocket& socket, std::uint16_t port, const QString& portOption,
                  const QLoggingCategory& log);

/// Reads at most kMaxDatagramsPerRead datagrams into buffer (grown as needed) and hands each to
/// onDatagram with hostNow() at its read. Each is stamped when read, and one call reads a
/// bounded number: under a flood the socket never runs dry, and one stamp for a read loop of
/// seconds would put samples before the time they were sent, which drags the session's clock
/// model. What is left is read at the next readyRead(), which QUdpSocket emits again once a
/// datagram has been read. The first read is tried even when nothing seems pending, since only a
/// read re-arms that signal.
void readDatagrams(
    QUdpSocket& socket, QByteArray& buffer,
    const std::function<void(std::span<const char> bytes, double arrival)>& onDatagram);

}  // namespace armtrack::devices
