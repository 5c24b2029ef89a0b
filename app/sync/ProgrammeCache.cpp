#include "app/sync/ProgrammeCache.h"

#include <QJsonArray>

namespace armtrack::sync {

namespace {

using storage::StorageError;

std::optional<double> optionalDouble(const QJsonValue& v) {
  return v.isDouble() ? std::optional<double>(v.toDouble()) : std::nullopt;
}

bool sameItem(const storage::ProgrammeItem& a, const storage::ProgrammeItem& b) {
  return a.protocolName == b.protocolName && a.sessionsPerWeek == b.sessionsPerWeek &&
         a.notes == b.notes && a.sets == b.sets && a.repetitions == b.repetitions &&
         a.targetMinDeg == b.targetMinDeg && a.targetMaxDeg == b.targetMaxDeg &&
         a.restS == b.restS && a.trunkLimitDeg == b.trunkLimitDeg;
}

bool sameProtocol(const storage::Protocol& a, const storage::Protocol& b) {
  return a.angleKey == b.angleKey && a.side == b.side && a.targetMinDeg == b.targetMinDeg &&
         a.targetMaxDeg == b.targetMaxDeg && a.repetitions == b.repetitions &&
         a.trunkLimitDeg == b.trunkLimitDeg;
}

}  // namespace

bool cacheProgramme(storage::ClinicalStore& store, const QString& patientCode,
                    const QJsonObject& programme) {
  bool changed = false;
  try {
    store.patient(patientCode);
  } catch (const StorageError& e) {
    if (e.kind() != StorageError::Kind::NotFound) throw;
    storage::Patient p;
    p.code = patientCode;
    p.name = patientCode;
    store.addPatient(p);
    changed = true;
  }
  // The clinic sends the values in effect; each exercise keeps them as its own, and its protocol
  // carries them too (so "the protocol's" trunk limit is the clinic's, off included).
  std::vector<storage::ProgrammeItem> wanted;
  for (const QJsonValue& value : programme.value("exercises").toArray()) {
    const QJsonObject o = value.toObject();
    storage::Protocol p;
    p.name = o.value("protocol").toString();
    p.angleKey = o.value("angle").toString();
    p.side = o.value("side").toString("either");
    p.targetMinDeg = o.value("target_min_deg").toDouble();
    p.targetMaxDeg = o.value("target_max_deg").toDouble();
    p.repetitions = o.value("repetitions").toInt(1);
    p.trunkLimitDeg = optionalDouble(o.value("trunk_limit_deg"));
    try {
      const storage::Protocol local = store.protocol(p.name);
      if (!sameProtocol(local, p)) {
        store.updateProtocol(p);
        changed = true;
      }
    } catch (const StorageError& e) {
      if (e.kind() != StorageError::Kind::NotFound) throw;
      store.addProtocol(p);
      changed = true;
    }
    storage::ProgrammeItem item;
    item.protocolName = p.name;
    item.sessionsPerWeek = o.value("sessions_per_week").toInt();
    item.notes = o.value("notes").toString();
    item.sets = o.value("sets").toInt(1);
    item.repetitions = p.repetitions;
    item.targetMinDeg = p.targetMinDeg;
    item.targetMaxDeg = p.targetMaxDeg;
    item.restS = o.value("rest_s").toDouble(60);
    item.trunkLimitDeg = p.trunkLimitDeg;
    wanted.push_back(item);
  }
  const std::vector<storage::ProgrammeItem> local = store.programme(patientCode);
  bool same = local.size() == wanted.size();
  for (std::size_t i = 0; same && i < local.size(); ++i) same = sameItem(local[i], wanted[i]);
  if (same) return changed;
  for (const storage::ProgrammeItem& item : local)
    store.unassignProtocol(patientCode, item.protocolName);
  for (storage::ProgrammeItem item : wanted) {
    item.position = 0;  // after the last: the clinic's order
    store.setProgrammeExercise(patientCode, item);
  }
  return true;
}

}  // namespace armtrack::sync
