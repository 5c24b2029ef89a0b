// The line-protocol IMU device: a do-it-yourself IMU sending `$IMU` sentences over a serial port or
// as UDP datagrams. See docs/devices/line-protocol.md, "Using the plugin".
#pragma once

#include <QAbstractSocket>
#include <QSerialPort>
#include <QString>
#include <QVariantMap>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "devices/api/Device.h"
#include "devices/api/ProblemLimiter.h"
#include "devices/lineimu/LineImuParser.h"

class QTimer;
class QUdpSocket;

namespace armtrack::devices::lineimu {

/// What the plugin's options select: a serial port or a UDP port, never both.
struct LineImuSettings {
  QString serialPort;                         ///< e.g. /dev/ttyUSB0; empty for UDP
  int baud = 115200;                          ///< serial only (bit/s)
  std::uint16_t udpPort = 0;                  ///< local UDP port; 0 for serial
  StreamRole role = StreamRole::UpperArmImu;  ///< UpperArmImu, ForearmImu or TrunkImu
  double retrySeconds = 1.0;                  ///< s between attempts to open the serial port
  double timeoutSeconds = 3.0;                ///< s without a sample: back to Connecting
};

/// Reads `port` or `udp`, `baud`, `role`, `retry` and `timeout`. Empty, with *error saying what to
/// change, when an option is missing, malformed, unknown or contradicts another. Any thread.
std::optional<LineImuSettings> readLineImuSettings(const QVariantMap& options, QString* error);

/// One line-protocol IMU as one stream. The state is Connecting until the first good `$IMU`
/// sentence, then Streaming. Serial: a port that errors or closes is reopened every
/// `retrySeconds` (a missing port is waited for the same way); no permission at the first start
/// is an Error. UDP: the socket listens on all addresses; a port already in use is an Error.
/// Either way, no sample for `timeoutSeconds` sets Connecting ("no data"), and samples coming
/// back count as a reconnect.
///
/// Device time is the sentence's microsecond time unwrapped by the parser (s). A `$HELLO` means
/// the device restarted, and its clock with it: that is reported as a problem, and the session's
/// clock model re-locks on the new time. Threads: construct anywhere, then use only from the
/// device's thread (see Device).
class LineImuDevice final : public Device {
  Q_OBJECT
 public:
  explicit LineImuDevice(const LineImuSettings& settings, QObject* parent = nullptr);
  ~LineImuDevice() override;

 public slots:
  void start() override;
  void stop() override;

 private:
  void createObjects();
  void tryOpenSerial();
  void openUdp();
  void onSerialReadyRead();
  void onSerialError(QSerialPort::SerialPortError error);
  void onUdpReadyRead();
  void onSilence();
  void linkLost(const QString& reason);
  void fail(const QString& reason);
  void publishSamples();
  void countLosses();
  QString source() const;

  const LineImuSettings m_settings;
  QSerialPort* m_serial = nullptr;  // children, created in start()
  QUdpSocket* m_udp = nullptr;
  QTimer* m_retryTimer = nullptr;
  QTimer* m_silenceTimer = nullptr;
  std::unique_ptr<ProblemLimiter> m_problems;  // one problem message per second at most
  bool m_running = false;

  LineImuParser m_parser;
  std::vector<Sample> m_samples;   // reused between reads
  std::vector<double> m_arrivals;  // arrival time of each of m_samples (s, hostNow())
  QByteArray m_datagram;           // reused between reads
  std::uint64_t m_errorsSeen = 0;
  std::uint64_t m_droppedSeen = 0;
  std::uint64_t m_reorderedSeen = 0;
  std::uint64_t m_duplicatesSeen = 0;
  std::optional<std::uint32_t> m_lastEpoch;

  bool m_streaming = false;
  bool m_everStreamed = false;  // a later Streaming counts as a reconnect
  bool m_openedOnce = false;    // permission errors after the first open are transient
};

}  // namespace armtrack::devices::lineimu
