// The programme from the clinic (GET /api/v1/programme) written into the home install's own
// records, so the home window shows it without a connection: the protocols it needs, and the
// patient's programme replaced by the clinic's when they differ.
#pragma once

#include <QJsonObject>

#include "core/storage/ClinicalStore.h"

namespace armtrack::sync {

/// Writes programme (the API's answer) as patientCode's programme in store (signed in as staff
/// or as a service). A patient missing from the local records is added with the code as name.
/// Returns whether anything changed. Throws StorageError (e.g. Usage for values out of range).
bool cacheProgramme(storage::ClinicalStore& store, const QString& patientCode,
                    const QJsonObject& programme);

}  // namespace armtrack::sync
