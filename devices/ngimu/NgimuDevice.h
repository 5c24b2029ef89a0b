// The NGIMU device: x-io's NGIMU sending OSC bundles over UDP (Wi-Fi); its "/sensors" messages
// become IMU samples. See docs/devices/ngimu.md, "Using the plugin".
#pragma once

#include <QString>
#include <QVariantMap>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "devices/api/Device.h"
#include "devices/api/ProblemLimiter.h"
#include "devices/ngimu/NgimuParser.h"

class QTimer;
class QUdpSocket;

namespace armtrack::devices::ngimu {

/// What the plugin's options select.
struct NgimuSettings {
  std::uint16_t port = 0;                     ///< local UDP port the NGIMU sends to
  StreamRole role = StreamRole::UpperArmImu;  ///< UpperArmImu or ForearmImu
  double timeoutSeconds = 3.0;                ///< s without a sample: back to Connecting
};

/// Reads `port`, `role` and `timeout`. Empty, with *error saying what to change, when an option is
/// missing, malformed or unknown. Any thread.
std::optional<NgimuSettings> readNgimuSettings(const QVariantMap& options, QString* error);

/// One NGIMU as one IMU stream. Listens on the UDP port on all addresses; Connecting until the
/// first "/sensors" message, then Streaming; no sample for `timeoutSeconds` sets Connecting ("no
/// data") and samples coming back count as a reconnect. A port already in use is an Error.
/// Device time is the bundle's time tag in seconds since 1900 (the NGIMU's clock); a bare
/// "/sensors" message without a bundle gets its arrival time instead (reported once). Battery is
/// not reported: the parser ignores "/battery". Threads: construct anywhere, then use only from
/// the device's thread (see Device).
class NgimuDevice final : public Device {
  Q_OBJECT
 public:
  explicit NgimuDevice(const NgimuSettings& settings, QObject* parent = nullptr);
  ~NgimuDevice() override;

 public slots:
  void start() override;
  void stop() override;

 private:
  void onReadyRead();
  void onSilence();
  void fail(const QString& reason);

  const NgimuSettings m_settings;
  QUdpSocket* m_socket = nullptr;  // children, created in start()
  QTimer* m_silenceTimer = nullptr;
  std::unique_ptr<ProblemLimiter> m_problems;  // one problem message per second at most
  bool m_running = false;

  NgimuParser m_parser;
  std::vector<SensorsSample> m_samples;  // reused between reads
  std::uint64_t m_errorsSeen = 0;
  bool m_streaming = false;
  bool m_everStreamed = false;  // a later Streaming counts as a reconnect
  bool m_toldNoTimetag = false;
};

}  // namespace armtrack::devices::ngimu
