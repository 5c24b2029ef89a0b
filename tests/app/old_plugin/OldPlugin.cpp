// A plugin built for another version of the device interface: the registry must refuse it.
#include <QObject>
#include <QtPlugin>

class OldDevicePlugin : public QObject {
  Q_OBJECT
  Q_PLUGIN_METADATA(IID "org.armtrack.DevicePlugin/0" FILE "old.json")
};

#include "OldPlugin.moc"
