#include "core/storage/SessionAnalysis.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonValue>
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

#include "core/kinematics/ClinicalAngles.h"
#include "core/storage/EstimateCodec.h"

#ifndef ARMTRACK_VERSION
#define ARMTRACK_VERSION "0.0.0"
#endif

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;

constexpr std::size_t kCancelCheckRows = 1024;  // rows between two looks at the cancel flag

std::string sessionText(qint64 id) {
  return "session " + std::to_string(id);
}

QString angleKey(int index) {
  const std::string_view k = clinicalAngleInfo()[static_cast<std::size_t>(index)].key;
  return QString::fromUtf8(k.data(), static_cast<qsizetype>(k.size()));
}

// The rows the metrics use: the estimates without the filter's settling time after each
// (re)start or recovery, as the error statistics leave it out (those angles may be far off while
// the arm did not move), and without a row at the time of the previous one (the metrics need
// strictly increasing times). Both stay in the stored estimates.
struct MetricRows {
  AngleSeries series;
  std::vector<ClinicalRow> sdRad;
  std::size_t dropped = 0, settling = 0;
};

MetricRows metricRows(const std::vector<double>& t, const std::vector<JointVector>& th,
                      const std::vector<JointVector>& sd, const std::vector<int>& status,
                      qint64 sessionId, bool withSd = true) {
  std::vector<double> mt;
  std::vector<JointVector> mth;
  mt.reserve(t.size());
  mth.reserve(t.size());
  MetricRows out;
  double settledFrom = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (status[i] == kStatusRestarted || status[i] == kStatusRecovered)
      settledFrom = t[i] + kStartupSeconds;
    if (t[i] < settledFrom) {
      ++out.settling;
      continue;
    }
    if (!mt.empty() && !(t[i] > mt.back())) {
      ++out.dropped;
      continue;
    }
    mt.push_back(t[i]);
    mth.push_back(th[i]);
    if (!withSd) continue;
    ClinicalRow s;  // the clinical angles are the joint angles up to sign
    for (int k = 0; k < kNumClinicalAngles; ++k) s[static_cast<std::size_t>(k)] = sd[i](k);
    out.sdRad.push_back(s);
  }
  if (mt.size() < 2)
    throw StorageError(Kind::Usage, sessionText(sessionId) + ": " + std::to_string(t.size()) +
                                        " estimates, " + std::to_string(mt.size()) +
                                        " after the filter's start-up second; at least 2 are "
                                        "needed for metrics");
  out.series = angleSeriesFromJoints(mt, mth);
  return out;
}

// Metrics parameters for a session: the wrist path from its geometry, repetitions on its
// protocol's primary angle judged against the protocol's target (protocol is set then).
ClinicalMetricsParams metricsParams(ClinicalStore& store, const SessionInfo& info,
                                    const ArmGeometry& geometry,
                                    std::optional<Protocol>& protocol) {
  ClinicalMetricsParams mp;
  mp.geometry = geometry;
  if (info.protocolName.isEmpty()) return mp;
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
  if (store.user().role == Role::Home)                // audited, as every refusal
    store.deny("analyse sessions",
               "a home account may not analyse sessions: ask your therapist to run "
               "'session reestimate " +
                   std::to_string(sessionId) + "'");
  AnalysisResult result;
  bool fromSession = false;
  result.settings = parseFilterSettings(info.filterJson, sessionId, fromSession);
  result.settingsSource = fromSession ? "session" : "defaults";
  if (options.filter) result.settings.filter = *options.filter;
  if (options.model) result.settings.model = *options.model;
  if (options.noOptical) result.settings.useOptical = result.settings.useCamera = false;
  const auto progress = [&](int p) {
    if (options.progress) options.progress(p);
  };
  progress(0);

  EstimatorParams params;
  EstimateColumns rows;
  {
    // The chunks are decoded as the filter goes: the recording (352 bytes a row as samples) is
    // never in memory whole (docs/storage.md, "Memory of an analysis").
    RecordingMeta meta = store.recordingMeta(sessionId);
    if (options.calibration) {
      try {
        applyCalibration(*options.calibration, meta);  // the calibrated geometry
      } catch (const std::invalid_argument& e) {
        throw StorageError(Kind::Usage,
                           sessionText(sessionId) + ": the calibration does not fit: " + e.what());
      }
    }
    params = estimatorParamsFor(meta, result.settings);
    const auto n = static_cast<std::size_t>(std::max<qint64>(info.sampleRows, 0));
    const auto imuRows = static_cast<std::size_t>(std::max<qint64>(info.imuSamples, 0));
    rows.t.reserve(imuRows);
    rows.th.reserve(imuRows);
    rows.sd.reserve(imuRows);
    rows.status.reserve(imuRows);
    StreamingEstimator estimator(params);
    EstimateRow row;
    ArmSample corrected;
    std::size_t done = 0;
    int nextPercent = 10;
    std::size_t nextRow = n / 10;
    bool cancelled = false;
    const auto one = [&](const ArmSample& s) {
      if (estimator.push(s, row)) rows.append(row);
      if (++done >= nextRow) {
        progress(nextPercent * 9 / 10);
        nextPercent += 10;
        nextRow = nextPercent <= 100 ? n * static_cast<std::size_t>(nextPercent) / 100
                                     : std::numeric_limits<std::size_t>::max();
      }
    };
    store.readRecordingChunks(sessionId, [&](std::span<const ArmSample> samples) {
      for (const ArmSample& s : samples) {
        if (options.cancel && done % kCancelCheckRows == 0 && options.cancel->load()) {
          cancelled = true;
          return false;
        }
        if (options.calibration) {
          corrected = s;
          applyCalibration(*options.calibration, corrected);
          one(corrected);
        } else {
          one(s);
        }
      }
      return true;
    });
    result.stats = estimator.stats();
    result.stats.cancelled = cancelled;
  }
  if (result.stats.cancelled) {
    result.cancelled = true;
    return result;
  }
  if (rows.size() < 2)
    throw StorageError(Kind::Usage, sessionText(sessionId) + ": " +
                                        std::to_string(result.stats.imuRows) +
                                        " rows with IMU data gave " + std::to_string(rows.size()) +
                                        " estimates; at least 2 are needed for metrics");

  std::optional<Protocol> protocol;
  const ClinicalMetricsParams mp = metricsParams(store, info, params.geometry, protocol);
  const MetricRows settled =
      metricRows(rows.t, rows.th, rows.sd, rows.status, sessionId, /*withSd=*/false);
  // The estimates are compressed now and their columns released (92 bytes a row), so that the
  // metrics below do not hold them too (docs/storage.md, "Memory of an analysis").
  const std::size_t estimateRows = rows.size();
  const std::string blob = EstimateCodec::encode(rows);
  rows = {};
  try {
    result.metrics = computeSessionMetrics(settled.series, mp);
  } catch (const std::invalid_argument& e) {
    throw StorageError(Kind::Usage,
                       sessionText(sessionId) + ": metrics cannot be computed: " + e.what());
  }
  const std::size_t dropped = settled.dropped, settling = settled.settling;
  progress(92);
  if (options.cancel && options.cancel->load()) {
    result.cancelled = true;
    return result;
  }

  const EstimateStats& st = result.stats;
  QJsonObject paramsJson = filterSettingsJson(result.settings);
  if (!paramsJson.contains("joint_accel_std_deg"))
    paramsJson.insert("joint_accel_std_deg", QJsonValue(QJsonValue::Null));
  for (const auto& [key, value] : std::initializer_list<std::pair<const char*, QJsonValue>>{
           {"calibration", options.calibration.has_value()},
           {"settings", result.settingsSource},
           {"optical_used", st.opticalUsed},
           {"library_version", ARMTRACK_VERSION},
           {"rows", static_cast<qint64>(estimateRows)},
           {"recording_rows", static_cast<qint64>(st.rows)},
           {"imu_rows", static_cast<qint64>(st.imuRows)},
           {"predicted", static_cast<qint64>(st.predicted)},
           {"restarts", static_cast<qint64>(st.counters.restarts)},
           {"recoveries", static_cast<qint64>(st.counters.recoveries)}})
    paramsJson.insert(key, value);
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

QJsonObject filterSettingsJson(const EstimateOptions& settings) {
  QJsonObject o{{"filter", filterName(settings.filter)},
                {"method", QString::fromStdString(methodName(settings.model))},
                {"optical", settings.useOptical},
                {"camera", settings.useCamera}};
  if (settings.jointAccelStdDeg) o.insert("joint_accel_std_deg", *settings.jointAccelStdDeg);
  return o;
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

namespace armtrack::storage {

SessionAngles sessionAngles(ClinicalStore& store, qint64 sessionId) {
  SessionAngles out;
  out.info = store.session(sessionId);
  const std::optional<StoredAnalysis> a = latestAnalysis(store, sessionId);
  if (!a)
    throw StorageError(Kind::NotFound, sessionText(sessionId) +
                                           " has not been analysed: run 'session reestimate " +
                                           std::to_string(sessionId) + "' (therapists)");
  const RecordingMeta meta = store.recordingMeta(sessionId);
  out.side = meta.side;
  out.version = a->version;
  std::optional<Protocol> protocol;
  const ClinicalMetricsParams mp = metricsParams(store, out.info, meta.geometry, protocol);
  MetricRows rows = metricRows(a->t, a->joints, a->sd, a->status, sessionId);
  try {
    out.metrics = computeSessionMetrics(rows.series, mp);
  } catch (const std::invalid_argument& e) {
    throw StorageError(Kind::Usage,
                       sessionText(sessionId) + ": metrics cannot be computed: " + e.what());
  }
  out.series = std::move(rows.series);
  out.sdRad = std::move(rows.sdRad);
  return out;
}

}  // namespace armtrack::storage
