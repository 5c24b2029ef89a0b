// The NGIMU device: x-io's NGIMU sending OSC bundles over UDP (Wi-Fi); its "/sensors" messages
// become IMU samples. See docs/devices/ngimu.md, "Using the plugin".
#pragma once

#include <QByteArray>
#include <QString>
#include <QVariantMap>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/sync/SequenceTracker.h"
#include "devices/api/Device.h"
#include "devices/api/ProblemLimiter.h"
#include "devices/ngimu/NgimuParser.h"

class QTimer;
class QUdpSocket;

namespace armtrack::devices::ngimu {

/// What the plugin's options select.
struct NgimuSettings {
  std::uint16_t port = 0;                     ///< local UDP port the NGIMU sends to
  StreamRole role = StreamRole::UpperArmImu;  ///< UpperArmImu, ForearmImu or TrunkImu
  double timeoutSeconds = 3.0;                ///< s without a sample: back to Connecting
};

/// Reads `port`, `role` and `timeout`. Empty, with *error saying what to change, when an option is
/// missing, malformed or unknown. Any thread.
std::optional<NgimuSettings> readNgimuSettings(const QVariantMap& options, QString* error);

/// Sequence numbers for /sensors messages, which carry none, from their time tags: a message
/// advances the count by its time step over the sample period (estimated from the steps, which
/// on the NGIMU's own clock are regular), so a step of three periods means two lost messages and
/// a time tag behind the newest one a reordered (or duplicated) message. The first steps set the
/// period; a shorter step later resets it (rate changed). Plain data.
class TimetagSequence {
 public:
  /// Takes a message with time tag t (s). False when it is not to be published: older than the
  /// newest one (counted reordered, or duplicate when seen before).
  bool accept(double t);
  const SequenceTracker& tracker() const { return m_tracker; }
  double periodSeconds() const { return m_period; }

 private:
  bool m_started = false;
  double m_last = 0.0;                           // newest time tag (s)
  double m_period = 0.0;                         // s, 0 until the first step
  std::uint64_t m_seq = std::uint64_t{1} << 40;  // of the newest; high, so steps back stay > 0
  SequenceTracker m_tracker;
};

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
  std::vector<double> m_arrivals;  // arrival time of each of m_samples (s, hostNow())
  QByteArray m_datagram;           // reused between reads
  TimetagSequence m_sequence;
  std::uint64_t m_droppedSeen = 0, m_reorderedSeen = 0, m_duplicatesSeen = 0;
  std::vector<SensorsSample> m_samples;  // reused between reads
  std::uint64_t m_errorsSeen = 0;
  bool m_streaming = false;
  bool m_everStreamed = false;  // a later Streaming counts as a reconnect
  bool m_toldNoTimetag = false;
};

}  // namespace armtrack::devices::ngimu
