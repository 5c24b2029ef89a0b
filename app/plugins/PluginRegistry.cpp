#include "app/plugins/PluginRegistry.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonObject>
#include <QLibrary>
#include <QLoggingCategory>

Q_LOGGING_CATEGORY(lcPlugins, "armtrack.plugins")

namespace armtrack::app {

QStringList PluginRegistry::defaultFolders() {
  QStringList folders;
  const QString env = qEnvironmentVariable("ARMTRACK_PLUGIN_PATH");
  for (const QString& f : env.split(u':', Qt::SkipEmptyParts)) folders << f;
  const QString exe = QCoreApplication::applicationDirPath();
  folders << QDir(exe).absoluteFilePath(QStringLiteral("../plugins"))
          << QDir::cleanPath(QDir(exe).absoluteFilePath(QStringLiteral(ARMTRACK_BIN_TO_PLUGINS)));
  return folders;
}

void PluginRegistry::load(const QStringList& foldersOrFiles) {
  for (const QString& entry : foldersOrFiles) {
    const QFileInfo info(entry);
    if (info.isDir()) {
      const QDir dir(info.absoluteFilePath());
      for (const QString& f : dir.entryList(QDir::Files, QDir::Name))
        if (QLibrary::isLibrary(f)) loadFile(dir.absoluteFilePath(f));
    } else if (info.isFile()) {
      loadFile(info.absoluteFilePath());
    }
  }
}

void PluginRegistry::loadFile(const QString& path) {
  PluginRecord rec;
  rec.file = path;
  auto refuse = [&](const QString& why) {
    rec.refusal = why;
    qCWarning(lcPlugins).noquote() << "refused plugin" << path << ":" << why;
    m_records.push_back(rec);
  };
  for (const PluginRecord& r : m_records)
    if (r.file == path) return;  // already looked at
  auto loader = std::make_unique<QPluginLoader>(path);
  const QJsonObject meta = loader->metaData();
  if (meta.isEmpty()) return refuse(QStringLiteral("not a Qt plugin"));
  const QString iid = meta.value(QStringLiteral("IID")).toString();
  if (!iid.startsWith(QStringLiteral("org.armtrack.DevicePlugin/")))
    return refuse(QStringLiteral("not an ArmTrack device plugin (interface %1)").arg(iid));
  if (iid != QStringLiteral(ARMTRACK_DEVICE_PLUGIN_IID))
    return refuse(QStringLiteral("built for device interface %1, this ArmTrack has %2; "
                                 "rebuild the plugin against this version")
                      .arg(iid, QStringLiteral(ARMTRACK_DEVICE_PLUGIN_IID)));
  QObject* instance = loader->instance();
  if (!instance) return refuse(QStringLiteral("cannot be loaded: %1").arg(loader->errorString()));
  auto* plugin = qobject_cast<devices::DevicePlugin*>(instance);
  if (!plugin) return refuse(QStringLiteral("does not implement the device interface"));
  if (plugin->apiVersion() != devices::kDeviceApiVersion)
    return refuse(QStringLiteral("built for device API %1, this ArmTrack has %2")
                      .arg(plugin->apiVersion())
                      .arg(devices::kDeviceApiVersion));
  rec.name = plugin->name();
  if (this->plugin(rec.name))
    return refuse(QStringLiteral("a plugin named '%1' is already loaded").arg(rec.name));
  rec.loaded = true;
  m_records.push_back(rec);
  m_plugins.emplace_back(rec.name, plugin);
  m_loaders.push_back(std::move(loader));
}

devices::DevicePlugin* PluginRegistry::plugin(const QString& name) const {
  for (const auto& [n, p] : m_plugins)
    if (n == name) return p;
  return nullptr;
}

QStringList PluginRegistry::names() const {
  QStringList out;
  for (const auto& [n, p] : m_plugins) out << n;
  return out;
}

}  // namespace armtrack::app
