// Loads one device plugin from the build tree (ARMTRACK_PLUGIN_DIR) for a test, and hosts its
// devices in a thread for a session.
#pragma once

#include <gtest/gtest.h>

#include <QPluginLoader>
#include <QString>
#include <memory>
#include <utility>

#include "devices/api/Device.h"
#include "devices/api/DeviceThread.h"

namespace armtrack::test {

/// The plugin named `name` (file armtrack-<name>.so), or nullptr with a test failure recorded.
/// The loader stays loaded for the life of the test program.
inline devices::DevicePlugin* loadPlugin(const QString& name) {
  const QString file = QStringLiteral(ARMTRACK_PLUGIN_DIR "/armtrack-%1.so").arg(name);
  auto* loader = new QPluginLoader(file);  // never unloaded: devices may outlive a test
  QObject* instance = loader->instance();
  if (!instance) {
    ADD_FAILURE() << "cannot load " << file.toStdString() << ": "
                  << loader->errorString().toStdString();
    return nullptr;
  }
  auto* plugin = qobject_cast<devices::DevicePlugin*>(instance);
  if (!plugin) ADD_FAILURE() << file.toStdString() << " is not a device plugin";
  return plugin;
}

/// The device in the thread that will host it, ready for Session::addDevice() (as armtrack-cli
/// live adds its devices).
inline std::unique_ptr<SampleSource> hosted(std::unique_ptr<devices::Device> device,
                                            const QString& name = QStringLiteral("test")) {
  return std::make_unique<devices::DeviceThread>(std::move(device), name);
}

}  // namespace armtrack::test
