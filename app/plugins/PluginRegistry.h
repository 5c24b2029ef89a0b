// Finds and loads the device plugins (QPluginLoader), refusing incompatible ones with a reason.
#pragma once

#include <QPluginLoader>
#include <QString>
#include <QStringList>
#include <memory>
#include <vector>

#include "devices/api/Device.h"

namespace armtrack::app {

/// A plugin file the registry looked at.
struct PluginRecord {
  QString file;
  QString name;            ///< plugin name when loaded
  bool loaded = false;
  QString refusal;         ///< why it was not loaded (empty when loaded)
};

/// Loads every plugin in the search folders. Main thread only.
class PluginRegistry {
 public:
  /// The default folders: $ARMTRACK_PLUGIN_PATH (':'-separated), <exe>/../plugins (build tree)
  /// and the install's plugin folder as seen from the program's, e.g.
  /// <exe>/../lib/x86_64-linux-gnu/armtrack/plugins (docs/packaging.md).
  static QStringList defaultFolders();

  /// Scans the folders (and single files) in order. A second plugin with a name already loaded is
  /// refused. Each refusal is also logged (category armtrack.plugins).
  void load(const QStringList& foldersOrFiles);

  const std::vector<PluginRecord>& records() const { return m_records; }
  /// The plugin with that name, or nullptr.
  devices::DevicePlugin* plugin(const QString& name) const;
  QStringList names() const;

 private:
  void loadFile(const QString& path);

  std::vector<PluginRecord> m_records;
  std::vector<std::unique_ptr<QPluginLoader>> m_loaders;
  std::vector<std::pair<QString, devices::DevicePlugin*>> m_plugins;
};

}  // namespace armtrack::app
