// One device as the clinical records keep it in a session's devices_json (docs/storage.md,
// "Sessions"): its plugin, the options it was created with, and its streams with their nominal
// rates. `armtrack-cli record --db` and the GUI's recordings (app/gui/services/SessionController)
// both store it, so the report's Devices section and `session show` name them alike.
#pragma once

#include <QJsonObject>
#include <QString>
#include <QVariantMap>

namespace armtrack::devices {
class Device;
}

namespace armtrack::app {

QJsonObject deviceRecord(const QString& plugin, const QVariantMap& options,
                         const devices::Device& device);

}  // namespace armtrack::app
