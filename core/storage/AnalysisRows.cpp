#include "core/storage/AnalysisRows.h"

#include <QJsonDocument>

#include "core/kinematics/ClinicalAngles.h"

namespace armtrack::storage::detail {

using Kind = StorageError::Kind;

std::string sessionText(qint64 id) {
  return "session " + std::to_string(id);
}

QString angleKey(int index) {
  const std::string_view k = clinicalAngleInfo()[static_cast<std::size_t>(index)].key;
  return QString::fromUtf8(k.data(), static_cast<qsizetype>(k.size()));
}

ClinicalMetricsParams metricsParams(ClinicalStore& store, const SessionInfo& info,
                                    const ArmGeometry& geometry,
                                    std::optional<Protocol>& protocol) {
  ClinicalMetricsParams mp;
  mp.geometry = geometry;
  // Without a protocol, the angle the live counter counted on too (repetitionAngle).
  mp.repetitions.primaryAngle = repetitionAngle(std::nullopt);
  if (info.protocolName.isEmpty()) return mp;
  mp.repetitions.primaryAngle.reset();
  protocol = store.protocol(info.protocolName);
  const auto& keys = clinicalAngleInfo();
  for (std::size_t a = 0; a < keys.size(); ++a)
    if (angleKey(static_cast<int>(a)) == protocol->angleKey)
      mp.repetitions.primaryAngle = static_cast<int>(a);
  if (!mp.repetitions.primaryAngle)
    throw StorageError(Kind::Usage, "protocol '" + protocol->name.toStdString() +
                                        "' has an unknown angle '" +
                                        protocol->angleKey.toStdString() + "'");
  if (protocol->targetMaxDeg > protocol->targetMinDeg)
    mp.repetitions.target =
        TargetRange{protocol->targetMinDeg * kDegToRad, protocol->targetMaxDeg * kDegToRad};
  return mp;
}

QJsonObject merged(const QJsonObject& summary, const QJsonObject& angles) {
  QJsonObject o = summary;
  o.insert("angles", angles);
  return o;
}

std::optional<QJsonObject> parseObject(const QString& json) {
  const QJsonDocument doc = QJsonDocument::fromJson(json.toUtf8());
  if (!doc.isObject()) return std::nullopt;
  return doc.object();
}

}  // namespace armtrack::storage::detail
