// The Shimmer3 device: talks to a Shimmer3 (LogAndStream firmware) over its Bluetooth serial port
// and turns its data packets into IMU samples. See docs/devices/shimmer3.md, "Using the plugin".
#pragma once

#include <QSerialPort>
#include <QString>
#include <QVariantMap>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "devices/api/Device.h"
#include "devices/api/ProblemLimiter.h"
#include "devices/shimmer3/Shimmer3Parser.h"

class QTimer;

namespace armtrack::devices::shimmer3 {

/// What the plugin's options select.
struct Shimmer3Settings {
  QString port;                               ///< serial device, e.g. /dev/rfcomm0
  StreamRole role = StreamRole::UpperArmImu;  ///< UpperArmImu, ForearmImu or TrunkImu
  double retrySeconds = 1.0;                  ///< s between attempts to open the port
  double timeoutSeconds = 3.0;                ///< s without an answer or data: reopen
};

/// Reads `port`, `role`, `retry` and `timeout`. Empty, with *error saying what to change, when an
/// option is missing, malformed or unknown. Any thread.
std::optional<Shimmer3Settings> readShimmer3Settings(const QVariantMap& options, QString* error);

/// One Shimmer3 as one IMU stream. Start-up: open the port, send stop (0x20) and drop whatever
/// arrives for 0.2 s, send inquiry (0x01) and read the channel layout from the response, send start
/// (0x07); the state becomes Streaming with the first sample. A port that errors or closes, or
/// stays silent for `timeoutSeconds`, is closed and reopened every `retrySeconds` (Connecting,
/// with the reason); a missing port is waited for the same way. Error is reserved for what the
/// user must fix: no permission on the port at the first start, or a Shimmer that streams no
/// gyroscope or no accelerometer.
///
/// Device time is the parser's unwrapped 32768 Hz timestamp (s). After a reconnect the parser
/// starts again from the raw 24-bit value; the device adds the whole number of 512 s wraps that
/// best matches the host time elapsed, so the time stays continuous while the Shimmer's clock ran
/// on. Threads: construct anywhere, then use only from the device's thread (see Device).
class Shimmer3Device final : public Device {
  Q_OBJECT
 public:
  explicit Shimmer3Device(const Shimmer3Settings& settings, QObject* parent = nullptr);
  ~Shimmer3Device() override;

 public slots:
  void start() override;
  void stop() override;

 private:
  enum class Phase { Idle, WaitingToOpen, Draining, Inquiring, Starting, Streaming };

  void tryOpen();
  void onReadyRead();
  void onPortError(QSerialPort::SerialPortError error);
  void onPhaseTimeout();
  void beginInquiry();
  void linkLost(const QString& reason);
  void closePort();
  void fail(const QString& reason);
  void sendCommand(std::uint8_t command);
  void publishSamples(double arrival);
  void takeParserProblems();

  const Shimmer3Settings m_settings;
  QSerialPort* m_port = nullptr;               // child, created in start()
  QTimer* m_phaseTimer = nullptr;              // retry, drain, answer and silence timeouts
  std::unique_ptr<ProblemLimiter> m_problems;  // one problem message per second at most
  Phase m_phase = Phase::Idle;

  Shimmer3Parser m_parser;
  std::vector<Sample> m_samples;  // reused between reads
  std::uint64_t m_inquiriesBefore = 0;
  std::uint64_t m_errorsSeen = 0;
  std::uint64_t m_droppedSeen = 0;

  bool m_everStreamed = false;     // a later Streaming counts as a reconnect
  bool m_openedOnce = false;       // permission errors after the first open are transient
  bool m_needTimeBase = true;      // choose m_tickOffset at the first sample of a connection
  std::uint64_t m_tickOffset = 0;  // whole wraps added to the parser's ticks
  bool m_haveLast = false;
  double m_lastDeviceTime = 0.0;  // s
  double m_lastArrival = 0.0;     // s, hostNow()
};

}  // namespace armtrack::devices::shimmer3
