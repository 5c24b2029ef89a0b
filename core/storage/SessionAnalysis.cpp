#include "core/storage/SessionAnalysis.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonValue>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/kinematics/ClinicalAngles.h"
#include "core/storage/EstimateCodec.h"

#ifndef ARMTRACK_VERSION
#define ARMTRACK_VERSION "0.0.0"
#endif

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

std::string sessionText(qint64 id) {
  return "session " + std::to_string(id);
}

QString angleKey(int index) {
  const std::string_view k = clinicalAngleInfo()[static_cast<std::size_t>(index)].key;
  return QString::fromUtf8(k.data(), static_cast<qsizetype>(k.size()));
}

// The session's stored filter settings ({} = none): see docs/storage.md, "Filter settings".
EstimateOptions parseFilterSettings(const QString& json, qint64 sessionId, bool& fromSession) {
  EstimateOptions o;
  fromSession = false;
  if (json.trimmed().isEmpty()) return o;
  QJsonParseError error;
  const QJsonDocument doc = QJsonDocument::fromJson(json.toUtf8(), &error);
  if (!doc.isObject())
    throw StorageError(Kind::Corrupt, sessionText(sessionId) +
                                          ": its stored filter settings are not a JSON object");
  const QJsonObject f = doc.object();
  fromSession = !f.isEmpty();
  const auto bad = [&](const char* key, const std::string& why) {
    return StorageError(Kind::Usage,
                        sessionText(sessionId) + ": stored filter setting \"" + key + "\" " + why);
  };
  if (f.contains("filter")) {
    const QString k = f.value("filter").toString().toLower();
    if (k == "ekf")
      o.filter = FilterKind::Ekf;
    else if (k == "ukf")
      o.filter = FilterKind::Ukf;
    else
      throw bad("filter", "must be \"ekf\" or \"ukf\"");
  }
  if (f.contains("method")) {
    try {
      o.model = parseMethod(f.value("method").toString().toStdString());
    } catch (const std::invalid_argument& e) {
      throw bad("method", std::string("is not a method: ") + e.what());
    }
  }
  if (f.contains("optical")) {
    if (!f.value("optical").isBool()) throw bad("optical", "must be true or false");
    o.useOptical = f.value("optical").toBool();
  }
  if (f.contains("camera")) {
    if (!f.value("camera").isBool()) throw bad("camera", "must be true or false");
    o.useCamera = f.value("camera").toBool();
  }
  if (f.contains("joint_accel_std_deg")) {
    const double s = f.value("joint_accel_std_deg").toDouble(-1.0);
    if (!(s > 0) || !std::isfinite(s))
      throw bad("joint_accel_std_deg", "must be a positive number");
    o.jointAccelStdDeg = s;
  }
  return o;
}

QJsonValue number(double v) {
  return std::isfinite(v) ? QJsonValue(v) : QJsonValue(QJsonValue::Null);
}

QJsonObject anglesJson(const IntervalMetrics& m) {
  QJsonObject angles;
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    const AngleMetricsDeg d = inDegrees(m.angle[static_cast<std::size_t>(a)]);
    angles.insert(angleKey(a), QJsonObject{{"min_deg", number(d.minDeg)},
                                           {"max_deg", number(d.maxDeg)},
                                           {"rom_deg", number(d.romDeg)},
                                           {"peak_velocity_deg_s", number(d.peakVelocityDegPerS)},
                                           {"mean_velocity_deg_s", number(d.meanVelocityDegPerS)},
                                           {"movement_time_s", number(d.movementTimeS)}});
  }
  return angles;
}

void putSmoothness(QJsonObject& o, const char* name, const SmoothnessValue& v) {
  o.insert(name, v.ok() ? number(v.value) : QJsonValue(QJsonValue::Null));
  o.insert(QString(name) + "_status", toString(v.status));
}

// The summary stored in metrics.per_repetition_json: everything but the per-angle table.
QJsonObject summaryJson(const SessionMetrics& m, int estimateVersion,
                        const std::optional<Protocol>& protocol, std::size_t droppedRows,
                        std::size_t settlingRows) {
  const RepetitionResult& r = m.repetitions;
  QJsonArray list;
  for (std::size_t i = 0; i < r.repetitions.size(); ++i) {
    const Repetition& rep = r.repetitions[i];
    QJsonObject o{{"start_s", rep.startS},  {"peak_s", rep.peakS},
                  {"end_s", rep.endS},      {"excursion_deg", rep.excursionRad * kRadToDeg},
                  {"partial", rep.partial}, {"angles", anglesJson(rep.metrics)}};
    if (i < m.repetitionSmoothness.size()) {
      putSmoothness(o, "sparc", m.repetitionSmoothness[i].sparc);
      putSmoothness(o, "ldlj", m.repetitionSmoothness[i].ldlj);
    }
    list.append(o);
  }
  QJsonObject reps{{"primary_angle", angleKey(r.primaryAngle)},
                   {"direction", r.negativeDirection ? "negative" : "positive"},
                   {"reference_deg", r.referenceRad * kRadToDeg},
                   {"count", static_cast<qint64>(r.repetitions.size())},
                   {"full", static_cast<qint64>(r.fullCount)},
                   {"partial", static_cast<qint64>(r.partialCount)},
                   {"truncated", static_cast<qint64>(r.truncated)},
                   {"list", list}};
  if (protocol) {
    reps.insert("protocol", protocol->name);
    reps.insert("target_min_deg", protocol->targetMinDeg);
    reps.insert("target_max_deg", protocol->targetMaxDeg);
  }
  QJsonObject s{{"format", kMetricsFormat},
                {"estimate_version", estimateVersion},
                {"duration_s", m.durationS},
                {"samples", static_cast<qint64>(m.samples)},
                {"rejected_non_finite", static_cast<qint64>(m.rejectedNonFinite)},
                {"rejected_time_order", static_cast<qint64>(droppedRows)},
                {"settling_rows", static_cast<qint64>(settlingRows)},
                {"gaps", static_cast<qint64>(m.gaps)},
                {"repetitions", reps}};
  putSmoothness(s, "sparc", m.sparc);
  putSmoothness(s, "ldlj", m.ldlj);
  return s;
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

const char* filterName(FilterKind k) {
  return k == FilterKind::Ekf ? "ekf" : "ukf";
}

}  // namespace

AnalysisResult analyseSession(ClinicalStore& store, qint64 sessionId,
                              const AnalysisOptions& options) {
  const SessionInfo info = store.session(sessionId);  // NotFound for an invisible session
  if (store.user().role == Role::Home)
    throw StorageError(Kind::AccessDenied,
                       "a home account may not analyse sessions: ask your therapist to run "
                       "'session reestimate " +
                           std::to_string(sessionId) + "'");
  AnalysisResult result;
  bool fromSession = false;
  result.settings = parseFilterSettings(info.filterJson, sessionId, fromSession);
  result.settingsSource = fromSession ? "session" : "defaults";
  if (options.filter) result.settings.filter = *options.filter;
  if (options.noOptical) result.settings.useOptical = result.settings.useCamera = false;
  const auto progress = [&](int p) {
    if (options.progress) options.progress(p);
  };
  progress(0);

  const Recording recording = store.readRecording(sessionId);
  const EstimatorParams params = estimatorParamsFor(recording.meta, result.settings);
  EstimateColumns rows;
  EstimateCallbacks callbacks;
  callbacks.row = [&](const EstimateRow& r) {
    rows.t.push_back(r.t);
    rows.th.push_back(r.th);
    rows.sd.push_back(r.sd);
    rows.status.push_back(r.status);
  };
  callbacks.progress = [&](int p) { progress(p * 9 / 10); };
  callbacks.cancel = options.cancel;
  result.stats = estimateRecording(recording, params, callbacks);
  if (result.stats.cancelled) {
    result.cancelled = true;
    return result;
  }
  if (rows.size() < 2)
    throw StorageError(Kind::Usage, sessionText(sessionId) + ": " +
                                        std::to_string(result.stats.imuRows) +
                                        " rows with IMU data gave " + std::to_string(rows.size()) +
                                        " estimates; at least 2 are needed for metrics");

  // The metrics leave out the filter's settling time after each (re)start or recovery, as the
  // error statistics do: those angles may be far off while the arm did not move. They need
  // strictly increasing times: a row at the time of the previous one is left out and counted.
  // Both stay in the stored estimates.
  std::vector<double> mt;
  std::vector<JointVector> mth;
  std::size_t dropped = 0, settling = 0;
  double settledFrom = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows.status[i] == kStatusRestarted || rows.status[i] == kStatusRecovered)
      settledFrom = rows.t[i] + kStartupSeconds;
    if (rows.t[i] < settledFrom) {
      ++settling;
      continue;
    }
    if (!mt.empty() && !(rows.t[i] > mt.back())) {
      ++dropped;
      continue;
    }
    mt.push_back(rows.t[i]);
    mth.push_back(rows.th[i]);
  }
  if (mt.size() < 2)
    throw StorageError(Kind::Usage, sessionText(sessionId) + ": " + std::to_string(rows.size()) +
                                        " estimates, " + std::to_string(mt.size()) +
                                        " after the filter's start-up second; at least 2 are "
                                        "needed for metrics");
  ClinicalMetricsParams mp;
  mp.geometry = params.geometry;
  std::optional<Protocol> protocol;
  if (!info.protocolName.isEmpty()) {
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
  }
  try {
    result.metrics = computeSessionMetrics(angleSeriesFromJoints(mt, mth), mp);
  } catch (const std::invalid_argument& e) {
    throw StorageError(Kind::Usage,
                       sessionText(sessionId) + ": metrics cannot be computed: " + e.what());
  }
  progress(92);
  if (options.cancel && options.cancel->load()) {
    result.cancelled = true;
    return result;
  }

  const EstimateStats& st = result.stats;
  const QJsonObject paramsJson{
      {"filter", filterName(result.settings.filter)},
      {"method", QString::fromStdString(methodName(result.settings.model))},
      {"optical", result.settings.useOptical},
      {"camera", result.settings.useCamera},
      {"joint_accel_std_deg", result.settings.jointAccelStdDeg
                                  ? QJsonValue(*result.settings.jointAccelStdDeg)
                                  : QJsonValue(QJsonValue::Null)},
      {"settings", result.settingsSource},
      {"optical_used", st.opticalUsed},
      {"library_version", ARMTRACK_VERSION},
      {"rows", static_cast<qint64>(rows.size())},
      {"recording_rows", static_cast<qint64>(st.rows)},
      {"imu_rows", static_cast<qint64>(st.imuRows)},
      {"predicted", static_cast<qint64>(st.predicted)},
      {"restarts", static_cast<qint64>(st.counters.restarts)},
      {"recoveries", static_cast<qint64>(st.counters.recoveries)}};
  const std::string blob = EstimateCodec::encode(rows);
  result.estimateVersion = store.saveEstimates(
      sessionId, QString::fromUtf8(QJsonDocument(paramsJson).toJson(QJsonDocument::Compact)),
      EstimateCodec::kName, QByteArray(blob.data(), static_cast<qsizetype>(blob.size())));
  const QJsonObject angles = anglesJson(result.metrics.session);
  const QJsonObject summary =
      summaryJson(result.metrics, result.estimateVersion, protocol, dropped, settling);
  result.metricsVersion = store.saveMetrics(
      sessionId, QString::fromUtf8(QJsonDocument(angles).toJson(QJsonDocument::Compact)),
      QString::fromUtf8(QJsonDocument(summary).toJson(QJsonDocument::Compact)));
  result.metricsJson = merged(summary, angles);
  store.audit("create", "session", QString::number(sessionId),
              "estimates and metrics version " + QString::number(result.estimateVersion));
  progress(100);
  return result;
}

std::optional<StoredAnalysis> storedAnalysis(ClinicalStore& store, qint64 sessionId, int version) {
  const std::optional<EstimateRecord> rec = store.estimates(sessionId, version);
  if (!rec) return std::nullopt;
  const std::string where =
      sessionText(sessionId) + ", estimates version " + std::to_string(rec->version) + ": ";
  if (rec->codec != EstimateCodec::kName)
    throw StorageError(Kind::Corrupt, where + "unknown codec '" + rec->codec.toStdString() +
                                          "' (written by a newer ArmTrack?)");
  const std::optional<QJsonObject> params = parseObject(rec->paramsJson);
  const double rows = params ? params->value("rows").toDouble(-1.0) : -1.0;
  if (!(rows >= 0) || rows != std::floor(rows) || rows > 1e12)
    throw StorageError(Kind::Corrupt, where + "its parameters do not say how many rows it holds" +
                                          " (run 'session reestimate')");
  EstimateColumns columns;
  try {
    columns = EstimateCodec::decode(std::string(rec->data.constData(), rec->data.size()),
                                    static_cast<std::uint64_t>(rows));
  } catch (const std::exception& e) {
    throw StorageError(Kind::Corrupt, where + e.what() + " (run 'session reestimate')");
  }
  StoredAnalysis a;
  a.sessionId = sessionId;
  a.version = rec->version;
  a.createdAt = rec->createdAt;
  a.paramsJson = rec->paramsJson;
  a.t = std::move(columns.t);
  a.joints = std::move(columns.th);
  a.sd = std::move(columns.sd);
  a.status = std::move(columns.status);
  a.clinical = angleSeriesFromJoints(a.t, a.joints);
  if (const auto m = store.latestMetrics(sessionId)) {
    const std::optional<QJsonObject> angles = parseObject(m->first);
    const std::optional<QJsonObject> summary = parseObject(m->second);
    if (angles && summary && summary->value("estimate_version").toInt() == a.version)
      a.metrics = merged(*summary, *angles);
  }
  return a;
}

std::optional<StoredAnalysis> latestAnalysis(ClinicalStore& store, qint64 sessionId) {
  return storedAnalysis(store, sessionId, 0);
}

std::optional<QJsonObject> latestMetricsJson(ClinicalStore& store, qint64 sessionId) {
  const auto m = store.latestMetrics(sessionId);
  if (!m) return std::nullopt;
  const std::optional<QJsonObject> angles = parseObject(m->first);
  const std::optional<QJsonObject> summary = parseObject(m->second);
  if (!angles || !summary)
    throw StorageError(Kind::Corrupt, sessionText(sessionId) +
                                          ": its stored metrics are not JSON objects (run "
                                          "'session reestimate')");
  return merged(*summary, *angles);
}

}  // namespace armtrack::storage
