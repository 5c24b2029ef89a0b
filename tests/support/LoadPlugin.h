// Loads one device plugin from the build tree (ARMTRACK_PLUGIN_DIR) for a test.
#pragma once

#include <gtest/gtest.h>

#include <QPluginLoader>
#include <QString>

#include "devices/api/Device.h"

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

}  // namespace armtrack::test
