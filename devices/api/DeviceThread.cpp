#include "devices/api/DeviceThread.h"

#include <utility>

namespace armtrack::devices {

DeviceThread::DeviceThread(std::unique_ptr<Device> device, QString name)
    : m_device(std::move(device)), m_name(std::move(name)) {}

DeviceThread::~DeviceThread() {
  stop();
}

void DeviceThread::start(SampleInput& input) {
  if (m_thread) return;
  Device* dev = m_device.get();
  SampleInput* in = &input;
  // Direct connections: the input is called in the device's thread, as the contract says.
  m_connections.push_back(QObject::connect(
      dev, &Device::samplesReady, dev, [in](const SampleBatch& b) { in->samplesArrived(b); },
      Qt::DirectConnection));
  m_connections.push_back(QObject::connect(
      dev, &Device::stateChanged, dev,
      [in](DeviceState s, const QString& reason) { in->stateChanged(s, reason.toStdString()); },
      Qt::DirectConnection));
  m_connections.push_back(QObject::connect(
      dev, &Device::problem, dev,
      [in](const QString& message) { in->problemReported(message.toStdString()); },
      Qt::DirectConnection));
  m_thread = new QThread;
  m_thread->setObjectName(QStringLiteral("device ") + m_name);
  dev->moveToThread(m_thread);
  m_thread->start();
  QMetaObject::invokeMethod(dev, &Device::start, Qt::QueuedConnection);
}

std::string DeviceThread::stop() {
  if (!m_thread) return {};
  Device* dev = m_device.get();
  QThread* home = QThread::currentThread();
  // Stop in the device's own thread, then hand the object back so it can be destroyed here.
  QMetaObject::invokeMethod(
      dev,
      [dev, home] {
        dev->stop();
        dev->moveToThread(home);
      },
      Qt::BlockingQueuedConnection);
  std::string problem;
  m_thread->quit();
  if (m_thread->wait(10000)) {
    delete m_thread;
  } else {
    // Destroying a QThread that still runs aborts the program: leave it to end on its own and
    // delete it then (deleteLater is safe to call twice).
    problem = "its thread did not end in 10 s";
    QThread* t = m_thread;
    QObject::connect(t, &QThread::finished, t, &QObject::deleteLater);
    if (t->isFinished()) t->deleteLater();
  }
  m_thread = nullptr;
  for (const QMetaObject::Connection& c : m_connections) QObject::disconnect(c);
  m_connections.clear();
  return problem;
}

}  // namespace armtrack::devices
