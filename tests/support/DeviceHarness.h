// A device run in its own thread, as the session runs it, with everything it emits collected in
// the test's thread. Shared by the device plugin tests; needs Qt6::Test and a QCoreApplication
// (tests/support/QtTestMain.cpp).
#pragma once

#include <QCoreApplication>
#include <QStringList>
#include <QTest>
#include <QThread>
#include <memory>
#include <utility>
#include <vector>

#include "devices/api/Device.h"

namespace armtrack::test {

struct DeviceHarness {
  using Device = devices::Device;

  std::unique_ptr<Device> device;
  QThread thread;
  QObject receiver;
  std::vector<DeviceSample> samples;
  std::vector<std::pair<DeviceState, QString>> states;
  QStringList problems;

  explicit DeviceHarness(std::unique_ptr<Device> d) : device(std::move(d)) {
    QObject::connect(device.get(), &Device::samplesReady, &receiver, [this](const SampleBatch& b) {
      samples.insert(samples.end(), b.begin(), b.end());
    });
    QObject::connect(device.get(), &Device::stateChanged, &receiver,
                     [this](DeviceState s, const QString& why) { states.emplace_back(s, why); });
    QObject::connect(device.get(), &Device::problem, &receiver,
                     [this](const QString& m) { problems << m; });
    device->moveToThread(&thread);
    thread.start();
    QMetaObject::invokeMethod(device.get(), &Device::start, Qt::QueuedConnection);
  }
  ~DeviceHarness() { stop(); }
  void stop() {
    if (!thread.isRunning()) return;
    QMetaObject::invokeMethod(device.get(), &Device::stop, Qt::BlockingQueuedConnection);
    thread.quit();
    thread.wait();
    QCoreApplication::processEvents();  // deliver what was queued before stop()
  }
  DeviceState state() const {
    return states.empty() ? DeviceState::Disconnected : states.back().first;
  }
  QString reason() const { return states.empty() ? QString() : states.back().second; }
  bool waitState(DeviceState s, int ms = 2000) {
    return QTest::qWaitFor([&] { return state() == s; }, ms);
  }
  bool waitSamples(std::size_t n, int ms = 2000) {
    return QTest::qWaitFor([&] { return samples.size() >= n; }, ms);
  }
};

}  // namespace armtrack::test
