// The thread that hosts a device: adapts a Qt plugin Device to core's SampleSource, so the
// session (core/session) drives devices without knowing Qt plugins or QThreads.
#pragma once

#include <QMetaObject>
#include <QString>
#include <QThread>
#include <memory>
#include <string>
#include <vector>

#include "core/devices/SampleSource.h"
#include "devices/api/Device.h"

namespace armtrack::devices {

/// Owns a Device and, while started, a QThread it lives in. start() connects the device's signals
/// straight to the input (they are called in the device's thread), moves the device into a new
/// thread and starts it there; stop() stops it in that thread, hands it back to the caller's
/// thread and ends the thread with a bounded wait (never terminate()).
class DeviceThread final : public SampleSource {
 public:
  /// device must not be null. name labels the thread ("device <name>").
  DeviceThread(std::unique_ptr<Device> device, QString name);
  ~DeviceThread() override;  ///< stops

  const std::vector<StreamInfo>& streams() const override { return m_device->streams(); }
  double timeScale() const override { return m_device->timeScale(); }
  DeviceState state() const override { return m_device->state(); }
  DeviceHealth health() const override { return m_device->health(); }

  void start(SampleInput& input) override;
  /// Returns "its thread did not end in 10 s" when the device's thread outlives the wait; the
  /// thread is then deleted when it ends.
  std::string stop() override;

  Device& device() { return *m_device; }

 private:
  std::unique_ptr<Device> m_device;
  QString m_name;
  QThread* m_thread = nullptr;
  std::vector<QMetaObject::Connection> m_connections;
};

}  // namespace armtrack::devices
