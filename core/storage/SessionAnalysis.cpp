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
constexpr std::size_t kEstimateChunkRows = std::size_t{1} << 16;  // rows of a stored estimate chunk

std::string sessionText(qint64 id) {
  return "session " + std::to_string(id);
}

struct MetricRows {
  AngleSeries metricSeries;         // what the metrics are computed from
  std::vector<JointVector> metricJoints;  // the same rows as joint angles (rad)
  std::vector<ClinicalRow> sdRad;   // standard deviations of the series' rows, when asked for
  std::size_t dropped = 0, settling = 0;
};

QString angleKey(int index) {
  const std::string_view k = clinicalAngleInfo()[static_cast<std::size_t>(index)].key;
  return QString::fromUtf8(k.data(), static_cast<qsizetype>(k.size()));
}

// The rows the metrics use, collected as the estimates come: the filter's settling time after
// each (re)start or recovery is left out (those angles may be far off while the arm did not
// move), as the error statistics leave it out, and so is a row at or before the time of the
// previous one (the metrics need strictly increasing times); both stay in the stored estimates.
// Of the rest, the first row of each 1/kMetricsRateHz cell of time is kept: the clinical metrics
// need no more (docs/storage.md, "Memory of an analysis"), so their memory and time grow with
// the session's duration at that rate, not with the sensors' rate. allRows keeps every settled
// row in series instead (exports) while the metrics still see the thinned ones.
class MetricRowCollector {
 public:
  MetricRowCollector(bool withSd, bool allRows) : m_withSd(withSd), m_allRows(allRows) {}

  void add(double t, const JointVector& th, const JointVector& sd, int status) {
    ++m_rows;
    if (status == kStatusRestarted || status == kStatusRecovered) m_settledFrom = t + kStartupSeconds;
    if (t < m_settledFrom) {
      ++m_settling;
      return;
    }
    if (m_haveLast && !(t > m_lastT)) {
      ++m_dropped;
      return;
    }
    if (!m_haveLast) m_t0 = t;
    m_haveLast = true;
    m_lastT = t;
    const double cell = std::floor((t - m_t0) * kMetricsRateHz);
    const bool thinKeeps = !(cell <= m_lastCell);
    if (thinKeeps) {
      m_lastCell = cell;
      m_metricT.push_back(t);
      m_metricTh.push_back(th);
    }
    if (!(thinKeeps || m_allRows)) return;
    if (m_allRows) {
      m_allT.push_back(t);
      m_allTh.push_back(th);
    }
    if (!m_withSd) return;
    ClinicalRow r;  // the clinical angles are the joint angles up to sign
    for (int k = 0; k < kNumClinicalAngles; ++k) r[static_cast<std::size_t>(k)] = sd(k);
    m_sd.push_back(r);
  }

  /// The rows for the metrics, and the series (the same rows, or every settled row with
  /// allRows). Throws StorageError(Usage) when fewer than 2 rows are left.
  MetricRows finish(qint64 sessionId, AngleSeries* series = nullptr) {
    if (m_metricT.size() < 2)
      throw StorageError(Kind::Usage, sessionText(sessionId) + ": " + std::to_string(m_rows) +
                                          " estimates, " + std::to_string(m_metricT.size()) +
                                          " after the filter's start-up second; at least 2 are "
                                          "needed for metrics");
    MetricRows out;
    out.dropped = m_dropped;
    out.settling = m_settling;
    out.metricSeries = angleSeriesFromJoints(m_metricT, m_metricTh);
    out.metricJoints = std::move(m_metricTh);
    m_metricT = {};
    m_metricTh = {};
    if (series) {
      if (m_allRows) {
        *series = angleSeriesFromJoints(m_allT, m_allTh);
        m_allT = {};
        m_allTh = {};
      } else {
        *series = out.metricSeries;
      }
    }
    out.sdRad = std::move(m_sd);
    return out;
  }

 private:
  bool m_withSd, m_allRows;
  std::size_t m_rows = 0, m_dropped = 0, m_settling = 0;
  double m_settledFrom = -std::numeric_limits<double>::infinity();
  bool m_haveLast = false;
  double m_lastT = 0, m_t0 = 0;
  double m_lastCell = -1;
  std::vector<double> m_metricT, m_allT;
  std::vector<JointVector> m_metricTh, m_allTh;
  std::vector<ClinicalRow> m_sd;
};

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

namespace {

// The rows the metrics were computed from (times and joint angles) as stored beside them: the
// estimate blob's layout with zero standard deviations, which zstd reduces to nothing.
ClinicalStore::StoredSeries encodeMetricRows(const std::vector<double>& t,
                                             std::vector<JointVector>&& joints) {
  EstimateColumns c;
  c.t = t;
  c.th = std::move(joints);
  c.sd.assign(c.t.size(), JointVector::Zero());
  c.status.assign(c.t.size(), kStatusFused);
  const std::string blob = EstimateCodec::encode(c);
  return {kMetricRowsCodec, QByteArray(blob.data(), static_cast<qsizetype>(blob.size()))};
}

// A session's analysis as it runs: the estimates go to the database a chunk at a time and the
// rows the metrics use are collected, so neither the recording nor its estimates are ever in
// memory whole (docs/storage.md, "Memory of an analysis").
class AnalysisRun {
 public:
  AnalysisRun(ClinicalStore& store, qint64 sessionId)
      : m_store(store), m_draft(store.beginEstimates(sessionId, EstimateCodec::kChunkedName)) {}
  ~AnalysisRun() {
    if (m_finished) return;
    try {
      m_store.abandonEstimates(m_draft);  // a failure or a cancel: nothing half-written stays
    } catch (const std::exception&) {
      // The draft stays; the session's next analysis removes it (it belongs to this process,
      // which will be gone).
    }
  }
  AnalysisRun(const AnalysisRun&) = delete;
  AnalysisRun& operator=(const AnalysisRun&) = delete;

  void add(const EstimateRow& row) {
    m_block.append(row);
    m_metricRows.add(row.t, row.th, row.sd, row.status);
    ++m_rows;
    if (m_block.size() >= kEstimateChunkRows) flush();
  }
  void flush() {
    if (m_block.size() == 0) return;
    const std::string blob = EstimateCodec::encode(m_block);
    m_store.appendEstimateChunk(m_draft, m_seq++, static_cast<qint64>(m_block.size()),
                                QByteArray(blob.data(), static_cast<qsizetype>(blob.size())));
    m_block.t.clear();
    m_block.th.clear();
    m_block.sd.clear();
    m_block.status.clear();
  }
  std::size_t rows() const { return m_rows; }
  MetricRowCollector& metricRows() { return m_metricRows; }
  ClinicalStore::AnalysisVersions finish(
      const QString& paramsJson, const QString& perAngleJson,
      const std::function<QString(int estimateVersion)>& perRepetitionJson,
      const ClinicalStore::StoredSeries& series) {
    const ClinicalStore::AnalysisVersions v =
        m_store.finishAnalysis(m_draft, paramsJson, perAngleJson, perRepetitionJson, series);
    m_finished = true;
    return v;
  }

 private:
  ClinicalStore& m_store;
  ClinicalStore::EstimatesDraft m_draft;
  EstimateColumns m_block;
  MetricRowCollector m_metricRows{/*withSd=*/false, /*allRows=*/false};
  std::size_t m_rows = 0;
  int m_seq = 0;
  bool m_finished = false;
};

// Marks the session's analysis failed with the error's text (the recording cannot be analysed as
// it is), then throws the error on.
[[noreturn]] void failAnalysis(ClinicalStore& store, qint64 sessionId, const StorageError& e) {
  try {
    store.markAnalysisFailed(sessionId, QString::fromStdString(e.what()));
  } catch (const std::exception&) {
    // The state stays pending; the error below is what the caller needs to see.
  }
  throw e;
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

  RecordingMeta meta = store.recordingMeta(sessionId);
  if (options.calibration) {
    try {
      applyCalibration(*options.calibration, meta);  // the calibrated geometry
    } catch (const std::invalid_argument& e) {
      throw StorageError(Kind::Usage,
                         sessionText(sessionId) + ": the calibration does not fit: " + e.what());
    }
  }
  const EstimatorParams params = estimatorParamsFor(meta, result.settings);
  std::optional<Protocol> protocol;
  const ClinicalMetricsParams mp = metricsParams(store, info, params.geometry, protocol);

  AnalysisRun run(store, sessionId);
  {
    const auto n = options.expectedRows > 0
                       ? options.expectedRows
                       : static_cast<std::size_t>(std::max<qint64>(info.sampleRows, 0));
    StreamingEstimator estimator(params);
    EstimateRow row;
    ArmSample corrected;
    std::size_t done = 0;
    int nextPercent = 10;
    std::size_t nextRow = n / 10;
    bool cancelled = false;
    const auto one = [&](const ArmSample& s) {
      if (estimator.push(s, row)) run.add(row);
      if (++done >= nextRow) {
        progress(nextPercent * 9 / 10);
        nextPercent += 10;
        nextRow = nextPercent <= 100 ? n * static_cast<std::size_t>(nextPercent) / 100
                                     : std::numeric_limits<std::size_t>::max();
      }
    };
    const std::function<bool(std::span<const ArmSample>)> consume =
        [&](std::span<const ArmSample> samples) {
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
      };
    try {
      if (options.samples)
        options.samples(consume);
      else
        store.readRecordingChunks(sessionId, consume);
    } catch (const StorageError& e) {
      if (e.kind() == Kind::Corrupt) failAnalysis(store, sessionId, e);
      throw;
    }
    run.flush();
    result.stats = estimator.stats();
    result.stats.cancelled = cancelled;
  }
  if (result.stats.cancelled) {
    result.cancelled = true;
    return result;  // the run's draft is removed
  }
  const std::size_t estimateRows = run.rows();
  if (estimateRows < 2)
    failAnalysis(store, sessionId,
                 StorageError(Kind::Usage, sessionText(sessionId) + ": " +
                                               std::to_string(result.stats.imuRows) +
                                               " rows with IMU data gave " +
                                               std::to_string(estimateRows) +
                                               " estimates; at least 2 are needed for metrics"));
  std::size_t dropped = 0, settling = 0;
  ClinicalStore::StoredSeries series;
  try {
    MetricRows settled = run.metricRows().finish(sessionId);
    dropped = settled.dropped;
    settling = settled.settling;
    try {
      result.metrics = computeSessionMetrics(settled.metricSeries, mp);
    } catch (const std::invalid_argument& e) {
      throw StorageError(Kind::Usage,
                         sessionText(sessionId) + ": metrics cannot be computed: " + e.what());
    }
    series = encodeMetricRows(settled.metricSeries.t, std::move(settled.metricJoints));
  } catch (const StorageError& e) {
    failAnalysis(store, sessionId, e);
  }
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
           {"recoveries", static_cast<qint64>(st.counters.recoveries)},
           {"metrics_rate_hz", kMetricsRateHz}})
    paramsJson.insert(key, value);
  const QJsonObject angles = anglesJson(result.metrics.session);
  QJsonObject summary;
  const ClinicalStore::AnalysisVersions v =
      run.finish(QString::fromUtf8(QJsonDocument(paramsJson).toJson(QJsonDocument::Compact)),
                 QString::fromUtf8(QJsonDocument(angles).toJson(QJsonDocument::Compact)),
                 [&](int estimateVersion) {
                   summary = summaryJson(result.metrics, estimateVersion, protocol, dropped,
                                         settling);
                   return QString::fromUtf8(QJsonDocument(summary).toJson(QJsonDocument::Compact));
                 },
                 series);
  result.estimateVersion = v.estimates;
  result.metricsVersion = v.metrics;
  result.metricsJson = merged(summary, angles);
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

namespace {

// Calls rows with each block of a stored version's estimates in order (one block for a version
// stored whole, one per chunk otherwise); where names the session and version for errors.
void forEachEstimateBlock(ClinicalStore& store, const EstimateRecord& rec, const std::string& where,
                          const std::function<void(EstimateColumns&&)>& rows) {
  const auto damaged = [&](const std::string& what) {
    return StorageError(Kind::Corrupt, where + what + " (run 'session reestimate')");
  };
  if (rec.codec != EstimateCodec::kName && rec.codec != EstimateCodec::kChunkedName)
    throw StorageError(Kind::Corrupt, where + "unknown codec '" + rec.codec.toStdString() +
                                          "' (written by a newer ArmTrack?)");
  const std::optional<QJsonObject> params = parseObject(rec.paramsJson);
  const double total = params ? params->value("rows").toDouble(-1.0) : -1.0;
  if (!(total >= 0) || total != std::floor(total) || total > 1e12)
    throw damaged("its parameters do not say how many rows it holds");
  if (rec.codec == EstimateCodec::kName) {
    try {
      rows(EstimateCodec::decode(std::string(rec.data.constData(), rec.data.size()),
                                 static_cast<std::uint64_t>(total)));
    } catch (const std::runtime_error& e) {
      throw damaged(e.what());
    }
    return;
  }
  std::uint64_t seen = 0;
  int expectedSeq = 0;
  double lastT = -std::numeric_limits<double>::infinity();
  store.readEstimateChunks(rec, [&](int seq, std::uint64_t n, const QByteArray& data) {
    if (seq != expectedSeq)
      throw damaged("chunk " + std::to_string(expectedSeq) + " is missing");
    ++expectedSeq;
    EstimateColumns block;
    try {
      block = EstimateCodec::decode(std::string(data.constData(), data.size()), n);
    } catch (const std::runtime_error& e) {
      throw damaged("chunk " + std::to_string(seq) + ": " + e.what());
    }
    if (block.size() > 0 && block.t.front() < lastT)
      throw damaged("chunk " + std::to_string(seq) + " starts before the previous one ends");
    if (block.size() > 0) lastT = block.t.back();
    seen += n;
    rows(std::move(block));
  });
  if (seen != static_cast<std::uint64_t>(total))
    throw damaged("its chunks hold " + std::to_string(seen) + " rows, its parameters say " +
                  std::to_string(static_cast<std::uint64_t>(total)));
}

std::string versionText(qint64 sessionId, int version) {
  return sessionText(sessionId) + ", estimates version " + std::to_string(version) + ": ";
}

}  // namespace

std::optional<StoredAnalysis> storedAnalysis(ClinicalStore& store, qint64 sessionId, int version) {
  const std::optional<EstimateRecord> rec = store.estimates(sessionId, version);
  if (!rec) return std::nullopt;
  StoredAnalysis a;
  a.sessionId = sessionId;
  a.version = rec->version;
  a.createdAt = rec->createdAt;
  a.paramsJson = rec->paramsJson;
  forEachEstimateBlock(store, *rec, versionText(sessionId, rec->version),
                       [&](EstimateColumns&& block) {
                         if (a.t.empty()) {
                           a.t = std::move(block.t);
                           a.joints = std::move(block.th);
                           a.sd = std::move(block.sd);
                           a.status = std::move(block.status);
                           return;
                         }
                         a.t.insert(a.t.end(), block.t.begin(), block.t.end());
                         a.joints.insert(a.joints.end(), block.th.begin(), block.th.end());
                         a.sd.insert(a.sd.end(), block.sd.begin(), block.sd.end());
                         a.status.insert(a.status.end(), block.status.begin(), block.status.end());
                       });
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

SessionAngles sessionAngles(ClinicalStore& store, qint64 sessionId, SeriesRows rows) {
  SessionAngles out;
  out.info = store.session(sessionId);
  const std::optional<EstimateRecord> rec = store.estimates(sessionId, 0);
  if (!rec)
    throw StorageError(Kind::NotFound, sessionText(sessionId) +
                                           " has not been analysed: run 'session reestimate " +
                                           std::to_string(sessionId) + "' (therapists)");
  const RecordingMeta meta = store.recordingMeta(sessionId);
  out.side = meta.side;
  out.version = rec->version;
  std::optional<Protocol> protocol;
  const ClinicalMetricsParams mp = metricsParams(store, out.info, meta.geometry, protocol);
  // The rows are gathered as analyseSession gathered them, so the metrics come out the same.
  MetricRowCollector collector(/*withSd=*/true, rows == SeriesRows::All);
  forEachEstimateBlock(store, *rec, versionText(sessionId, rec->version),
                       [&](EstimateColumns&& block) {
                         for (std::size_t i = 0; i < block.size(); ++i)
                           collector.add(block.t[i], block.th[i], block.sd[i], block.status[i]);
                       });
  MetricRows settled = collector.finish(sessionId, &out.series);
  try {
    out.metrics = computeSessionMetrics(settled.metricSeries, mp);
  } catch (const std::invalid_argument& e) {
    throw StorageError(Kind::Usage,
                       sessionText(sessionId) + ": metrics cannot be computed: " + e.what());
  }
  out.sdRad = std::move(settled.sdRad);
  return out;
}

}  // namespace armtrack::storage

namespace armtrack::storage {

namespace {

double radOf(const QJsonObject& o, const char* key) {
  return o.value(key).toDouble(0.0) * kDegToRad;
}

IntervalMetrics intervalFromJson(const QJsonObject& angles) {
  IntervalMetrics m;
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    const QJsonObject o = angles.value(angleKey(a)).toObject();
    AngleMetrics& x = m.angle[static_cast<std::size_t>(a)];
    x.minRad = radOf(o, "min_deg");
    x.maxRad = radOf(o, "max_deg");
    x.romRad = radOf(o, "rom_deg");
    x.peakVelocityRadPerS = radOf(o, "peak_velocity_deg_s");
    x.meanVelocityRadPerS = radOf(o, "mean_velocity_deg_s");
    x.movementTimeS = o.value("movement_time_s").toDouble(0.0);
  }
  return m;
}

SmoothnessValue smoothnessFromJson(const QJsonObject& o, const char* name) {
  const QString status = o.value(QString(name) + "_status").toString();
  for (const SmoothnessStatus s :
       {SmoothnessStatus::Ok, SmoothnessStatus::TooShort, SmoothnessStatus::NonFinite,
        SmoothnessStatus::NoMovement, SmoothnessStatus::ZeroJerk})
    if (status == QLatin1String(toString(s)))
      return {s == SmoothnessStatus::Ok ? o.value(name).toDouble(0.0) : 0.0, s};
  return {};
}

}  // namespace

SessionMetrics sessionMetricsFromJson(const QJsonObject& m) {
  SessionMetrics out;
  out.session = intervalFromJson(m.value("angles").toObject());
  out.durationS = m.value("duration_s").toDouble(0.0);
  out.samples = static_cast<std::size_t>(m.value("samples").toInteger(0));
  out.rejectedNonFinite = static_cast<std::size_t>(m.value("rejected_non_finite").toInteger(0));
  out.gaps = static_cast<std::size_t>(m.value("gaps").toInteger(0));
  out.session.samples = out.samples;
  out.sparc = smoothnessFromJson(m, "sparc");
  out.ldlj = smoothnessFromJson(m, "ldlj");
  const QJsonObject reps = m.value("repetitions").toObject();
  RepetitionResult& r = out.repetitions;
  for (int a = 0; a < kNumClinicalAngles; ++a)
    if (reps.value("primary_angle").toString() == angleKey(a)) r.primaryAngle = a;
  r.negativeDirection = reps.value("direction").toString() == "negative";
  r.referenceRad = radOf(reps, "reference_deg");
  r.fullCount = static_cast<std::size_t>(reps.value("full").toInteger(0));
  r.partialCount = static_cast<std::size_t>(reps.value("partial").toInteger(0));
  r.truncated = static_cast<std::size_t>(reps.value("truncated").toInteger(0));
  for (const QJsonValue& v : reps.value("list").toArray()) {
    const QJsonObject o = v.toObject();
    Repetition rep;
    rep.startS = o.value("start_s").toDouble(0.0);
    rep.peakS = o.value("peak_s").toDouble(0.0);
    rep.endS = o.value("end_s").toDouble(0.0);
    rep.excursionRad = radOf(o, "excursion_deg");
    rep.partial = o.value("partial").toBool();
    rep.metrics = intervalFromJson(o.value("angles").toObject());
    r.repetitions.push_back(rep);
    out.repetitionSmoothness.push_back({smoothnessFromJson(o, "sparc"), smoothnessFromJson(o, "ldlj")});
  }
  return out;
}

std::optional<SessionAngles> storedSessionAngles(ClinicalStore& store, qint64 sessionId) {
  const std::optional<ClinicalStore::StoredSeries> series = store.latestMetricSeries(sessionId);
  if (!series) return std::nullopt;
  const std::optional<QJsonObject> metrics = latestMetricsJson(store, sessionId);
  if (!metrics) return std::nullopt;
  const int version = metrics->value("estimate_version").toInt();
  if (version != store.estimateVersions(sessionId)) return std::nullopt;
  const std::string where =
      sessionText(sessionId) + ", metrics of estimates version " + std::to_string(version) + ": ";
  if (series->codec != kMetricRowsCodec)
    throw StorageError(Kind::Corrupt, where + "unknown codec '" + series->codec.toStdString() +
                                          "' of its rows (written by a newer ArmTrack?)");
  SessionAngles out;
  out.info = store.session(sessionId);
  out.side = store.recordingMeta(sessionId).side;
  out.version = version;
  out.metrics = sessionMetricsFromJson(*metrics);
  try {
    const EstimateColumns rows = EstimateCodec::decode(
        std::string(series->data.constData(), static_cast<std::size_t>(series->data.size())),
        static_cast<std::uint64_t>(out.metrics.samples + out.metrics.rejectedNonFinite));
    out.series = angleSeriesFromJoints(rows.t, rows.th);
  } catch (const std::runtime_error& e) {
    throw StorageError(Kind::Corrupt, where + "its rows: " + e.what() +
                                          " (run 'session reestimate')");
  }
  return out;
}

}  // namespace armtrack::storage
