// The device plugin interface: what every sensor source (real or virtual) gives the session.
// Depends on core types and Qt Core only; no widgets. See docs/devices/plugins.md. The stream
// types (StreamRole, StreamInfo, DeviceSample, health) are core's (core/devices/Stream.h); the
// session drives a device through DeviceThread (devices/api/DeviceThread.h).
#pragma once

#include <QObject>
#include <QString>
#include <QVariantMap>
#include <QtPlugin>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/devices/Stream.h"

namespace armtrack::devices {

/// Version of this interface. A plugin built against another version is refused by the loader.
inline constexpr int kDeviceApiVersion = 1;

/// A sensor source. It lives in its own thread (DeviceThread moves it there): start() and stop()
/// are called in that thread (queued), and samplesReady() is emitted from it. state() and health()
/// may be called from any thread. Objects a device creates for its work (timers, ports, sockets)
/// are created in start() or are children of the device, so they live in its thread.
class Device : public QObject {
  Q_OBJECT
 public:
  explicit Device(std::vector<StreamInfo> streams, QObject* parent = nullptr);
  ~Device() override;

  const std::vector<StreamInfo>& streams() const { return m_streams; }
  DeviceState state() const { return m_state.load(); }
  /// Device seconds per host second: 1 for live devices; a replay at 4x returns 4. The session
  /// runs its clocks at this rate, so device time stays the recording's time. Any thread.
  virtual double timeScale() const { return 1.0; }
  DeviceHealth health() const;

 public slots:
  /// Opens the device and starts streaming (asynchronously: watch stateChanged). Device thread.
  virtual void start() = 0;
  /// Stops streaming and closes the device; emits nothing afterwards. Device thread.
  virtual void stop() = 0;

 signals:
  void stateChanged(armtrack::DeviceState state, const QString& reason);
  /// Samples in arrival order. Emitted from the device thread; a receiver connected directly
  /// must be thread-safe.
  void samplesReady(const armtrack::SampleBatch& batch);
  /// A problem the session should report but that does not stop the device (a corrupt packet,
  /// a dropout, a sequence gap).
  void problem(const QString& message);

 protected:
  /// Changes the state and emits stateChanged() when the state or a non-empty reason differs.
  void setState(DeviceState state, const QString& reason = {});
  /// Counts the batch in the health figures and emits samplesReady(). Empty batches are ignored.
  void publish(const SampleBatch& batch);
  /// Records the message as lastProblem and emits problem().
  void reportProblem(const QString& message);
  void countDropped(int stream, std::uint64_t n);
  void countCorrupt(int stream, std::uint64_t n);
  /// n samples counted as dropped arrived after all, overtaken by newer ones (and were not
  /// published): moves them from dropped to reordered. Non-virtual, like StreamHealth::reordered
  /// at the end of its struct, so kDeviceApiVersion 1 still holds.
  void countReordered(int stream, std::uint64_t n);
  void countReconnect();
  void setBattery(std::optional<double> percent);

 private:
  struct RateWindow {
    double start = -1.0;
    std::uint64_t count = 0;
  };
  const std::vector<StreamInfo> m_streams;
  std::atomic<DeviceState> m_state{DeviceState::Disconnected};
  mutable std::mutex m_mutex;  // guards m_health and m_windows
  DeviceHealth m_health;
  std::vector<RateWindow> m_windows;
  QString m_lastReason;
};

/// A factory of devices, loaded by the application with QPluginLoader. A plugin never opens a
/// dialog; its options come as strings from the command line or the settings.
class DevicePlugin {
 public:
  virtual ~DevicePlugin() = default;
  /// The interface version the plugin was built against (kDeviceApiVersion at its build).
  virtual int apiVersion() const { return kDeviceApiVersion; }
  /// Short name used on the command line, e.g. "virtual-arm".
  virtual QString name() const = 0;
  /// One line for `armtrack-cli devices`.
  virtual QString description() const = 0;
  /// The options create() understands, one per line: "key=default  meaning".
  virtual QString optionsHelp() const = 0;
  /// Creates a device, or returns nullptr and sets *error to a message that says what to change.
  /// Unknown option keys are errors. Called in the thread that will own the device until the
  /// session moves it.
  virtual std::unique_ptr<Device> create(const QVariantMap& options, QString* error) = 0;
};

}  // namespace armtrack::devices

#define ARMTRACK_DEVICE_PLUGIN_IID "org.armtrack.DevicePlugin/1"
Q_DECLARE_INTERFACE(armtrack::devices::DevicePlugin, ARMTRACK_DEVICE_PLUGIN_IID)
Q_DECLARE_METATYPE(armtrack::DeviceState)
Q_DECLARE_METATYPE(armtrack::SampleBatch)
