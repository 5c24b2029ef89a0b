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
#include "core/storage/AnalysisRows.h"
#include "core/storage/EstimateCodec.h"

#ifndef ARMTRACK_VERSION
#define ARMTRACK_VERSION "0.0.0"
#endif

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;
using detail::angleKey;
using detail::merged;
using detail::MetricRowCollector;
using detail::MetricRows;
using detail::metricsParams;
using detail::sessionText;

constexpr std::size_t kCancelCheckRows = 1024;  // rows between two looks at the cancel flag
constexpr std::size_t kEstimateChunkRows = std::size_t{1} << 16;  // rows of a stored estimate chunk

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

// The calibration stored with the session's filter settings ("calibration": a calibration
// file's JSON object, docs/storage.md), if any.
std::optional<Calibration> storedCalibration(const QString& json, qint64 sessionId) {
  const std::optional<QJsonObject> f = detail::parseObject(json);
  if (!f || !f->contains("calibration")) return std::nullopt;
  const QJsonValue v = f->value("calibration");
  const std::string name = sessionText(sessionId) + ": stored filter setting \"calibration\"";
  if (!v.isObject())
    throw StorageError(Kind::Usage, name + " must be a calibration file's JSON object");
  try {
    return parseCalibration(QJsonDocument(v.toObject()).toJson().toStdString(), name);
  } catch (const CalibrationError& e) {
    throw StorageError(Kind::Usage, e.what());
  }
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

QJsonValue optionalNumber(const std::optional<double>& v) {
  return v ? number(*v) : QJsonValue(QJsonValue::Null);
}

// The trunk's four values (docs/storage.md, "Metrics"): null where not measured.
QJsonObject trunkJson(const TrunkExtremes& x) {
  return QJsonObject{{"max_flexion_deg", optionalNumber(x.maxFlexionDeg)},
                     {"max_lateral_deg", optionalNumber(x.maxLateralDeg)},
                     {"max_rotation_deg", optionalNumber(x.maxRotationDeg)},
                     {"max_shoulder_displacement_cm", optionalNumber(x.maxShoulderDisplacementCm)}};
}

// The summary stored in metrics.per_repetition_json: everything but the per-angle table.
QJsonObject summaryJson(const SessionMetrics& m, const TrunkCompensation& trunk,
                        const std::optional<double>& flexionLimitDeg, int estimateVersion,
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
    const TrunkExtremes x = i < trunk.repetitions.size() ? trunk.repetitions[i] : TrunkExtremes{};
    QJsonObject t = trunkJson(x);
    t.insert("compensated", x.compensated ? QJsonValue(*x.compensated) : QJsonValue());
    o.insert("trunk", t);
    list.append(o);
  }
  QJsonObject reps{{"primary_angle", angleKey(r.primaryAngle)},
                   {"direction", r.negativeDirection ? "negative" : "positive"},
                   {"reference_deg", r.referenceRad * kRadToDeg},
                   {"count", static_cast<qint64>(r.repetitions.size())},
                   {"full", static_cast<qint64>(r.fullCount)},
                   {"partial", static_cast<qint64>(r.partialCount)},
                   {"truncated", static_cast<qint64>(r.truncated)},
                   {"repetitions_with_compensation",
                    trunk.repetitionsWithCompensation
                        ? QJsonValue(static_cast<qint64>(*trunk.repetitionsWithCompensation))
                        : QJsonValue()},
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
  QJsonObject t = trunkJson(trunk.session);
  t.insert("flexion_limit_deg", optionalNumber(flexionLimitDeg));
  s.insert("trunk", t);
  putSmoothness(s, "sparc", m.sparc);
  putSmoothness(s, "ldlj", m.ldlj);
  return s;
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

// The rows the trunk's compensation is measured from, collected as the samples go: the trunk
// angles of the estimates (a trunk IMU's; the filter's settling time after each (re)start or
// recovery left out as the metrics leave it out, and at most one row per 1/kMetricsRateHz cell
// of time, as the metrics thin theirs) and every optical shoulder the recording holds. Rows of
// status 4 (the trunk moved unseen) are kept: their trunk values are what was measured.
class TrunkRowCollector {
 public:
  void add(const ArmSample& sample, const EstimateRow* row) {
    TrunkRow r;
    r.t = sample.t;
    if (row) {
      if (row->status == kStatusRestarted || row->status == kStatusRecovered)
        m_settledFrom = row->t + kStartupSeconds;
      if (row->t >= m_settledFrom && row->trunk.allFinite()) {
        const double cell = std::floor(row->t * kMetricsRateHz);
        if (!(cell <= m_lastCell)) {
          m_lastCell = cell;
          r.angle = row->trunk;
        }
      }
    }
    r.shoulder = sample.shoulder;
    if (r.angle || r.shoulder) m_rows.push_back(r);
  }
  const std::vector<TrunkRow>& rows() const { return m_rows; }

 private:
  std::vector<TrunkRow> m_rows;
  double m_settledFrom = -std::numeric_limits<double>::infinity();
  double m_lastCell = -std::numeric_limits<double>::infinity();
};

// A session's analysis as it runs: the estimates go to the database a chunk at a time and the
// rows the metrics use are collected, so neither the recording nor its estimates are ever in
// memory whole (docs/storage.md, "Memory of an analysis").
class AnalysisRun {
 public:
  // withTrunk: the estimates keep the trunk's columns (a recording with trunk output, as
  // `estimate --out` writes them).
  AnalysisRun(ClinicalStore& store, qint64 sessionId, bool withTrunk)
      : m_store(store),
        m_draft(store.beginEstimates(sessionId, EstimateCodec::kChunkedName)),
        m_withTrunk(withTrunk) {}
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
    m_block.append(row, m_withTrunk);
    m_metricRows.add(row.t, row.th, row.sd, row.status);
    ++m_rows;
    if (m_block.size() >= kEstimateChunkRows) flush();
  }
  void flush() {
    if (m_block.size() == 0) return;
    const std::string blob = EstimateCodec::encode(m_block);
    m_store.appendEstimateChunk(m_draft, m_seq++, static_cast<qint64>(m_block.size()),
                                QByteArray(blob.data(), static_cast<qsizetype>(blob.size())));
    m_block.clear();
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
  bool m_withTrunk = false;
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

// The trunk flexion limit the repetitions are judged by: the caller's; for a home session the
// limit its exercise held the patient to (the home summary's "trunk_limit_deg", null: none),
// else, with no summary stored yet, the patient's programme exercise of the session's protocol
// (effectiveTrunkLimit: its own, else the protocol's); else the session's protocol's
// (Protocol::trunkLimitDeg); else none.
static std::optional<double> trunkLimit(ClinicalStore& store, const SessionInfo& info,
                                        const AnalysisOptions& options,
                                        const std::optional<Protocol>& protocol) {
  if (options.trunkFlexionLimitDeg) return options.trunkFlexionLimitDeg;
  if (info.setting == kSettingHome && protocol) {
    const std::optional<QJsonObject> summary = detail::parseObject(info.homeSummaryJson);
    if (summary && summary->contains("trunk_limit_deg")) {
      const QJsonValue v = summary->value("trunk_limit_deg");
      if (v.isDouble() && std::isfinite(v.toDouble()) && v.toDouble() > 0) return v.toDouble();
      if (v.isNull()) return std::nullopt;
    }
    for (const ProgrammeItem& item : store.programme(info.patientCode))
      if (item.protocolName == protocol->name) return effectiveTrunkLimit(item, *protocol);
  }
  return protocol ? protocol->trunkLimitDeg : std::nullopt;
}

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
  // What the session holds that cannot be analysed as it is (unreadable filter settings or
  // sidecar, a protocol on an unknown angle) marks the analysis failed with the reason, so it is
  // not taken up again and again as pending.
  const auto storedProblem = [&](auto&& read) {
    try {
      return read();
    } catch (const StorageError& e) {
      if (e.kind() == Kind::Usage || e.kind() == Kind::Corrupt) failAnalysis(store, sessionId, e);
      throw;
    }
  };
  result.settings =
      storedProblem([&] { return parseFilterSettings(info.filterJson, sessionId, fromSession); });
  result.settingsSource = fromSession ? "session" : "defaults";
  // The caller's calibration, else the one the session was recorded with.
  result.calibration = options.calibration ? options.calibration : storedProblem([&] {
    return storedCalibration(info.filterJson, sessionId);
  });
  const std::optional<Calibration>& calibration = result.calibration;
  if (options.filter) result.settings.filter = *options.filter;
  if (options.model) result.settings.model = *options.model;
  if (options.noOptical) result.settings.useOptical = result.settings.useCamera = false;
  const auto progress = [&](int p) {
    if (options.progress) options.progress(p);
  };
  progress(0);

  RecordingMeta meta = storedProblem([&] { return store.recordingMeta(sessionId); });
  if (calibration) {
    try {
      applyCalibration(*calibration, meta);  // the calibrated geometry
    } catch (const std::invalid_argument& e) {
      throw StorageError(Kind::Usage,
                         sessionText(sessionId) + ": the calibration does not fit: " + e.what());
    }
  }
  if (options.trunkFlexionLimitDeg &&
      !(std::isfinite(*options.trunkFlexionLimitDeg) && *options.trunkFlexionLimitDeg > 0))
    throw StorageError(Kind::Usage, sessionText(sessionId) +
                                        ": the trunk flexion limit must be a positive number of "
                                        "degrees (or none)");
  const EstimatorParams params = estimatorParamsFor(meta, result.settings);
  std::optional<Protocol> protocol;
  const ClinicalMetricsParams mp =
      storedProblem([&] { return metricsParams(store, info, params.geometry, protocol); });
  const std::optional<double> flexionLimit = trunkLimit(store, info, options, protocol);

  AnalysisRun run(store, sessionId, hasTrunkOutput(columnsOf(info.columnsMask)));
  TrunkRowCollector trunkRows;
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
      if (estimator.push(s, row)) {
        run.add(row);
        trunkRows.add(s, &row);
      } else {
        trunkRows.add(s, nullptr);
      }
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
            if (calibration) {
              corrected = s;
              applyCalibration(*calibration, corrected);
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
                 StorageError(Kind::Usage,
                              sessionText(sessionId) + ": " + std::to_string(result.stats.imuRows) +
                                  " rows with IMU data gave " + std::to_string(estimateRows) +
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
    TrunkCompensationParams tp;
    tp.flexionLimitDeg = flexionLimit;
    result.trunk =
        computeTrunkCompensation(trunkRows.rows(), repetitionSpans(result.metrics.repetitions), tp);
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
           {"calibration", calibration.has_value()},
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
  const ClinicalStore::AnalysisVersions v = run.finish(
      QString::fromUtf8(QJsonDocument(paramsJson).toJson(QJsonDocument::Compact)),
      QString::fromUtf8(QJsonDocument(angles).toJson(QJsonDocument::Compact)),
      [&](int estimateVersion) {
        summary = summaryJson(result.metrics, result.trunk, flexionLimit, estimateVersion, protocol,
                              dropped, settling);
        return QString::fromUtf8(QJsonDocument(summary).toJson(QJsonDocument::Compact));
      },
      series);
  result.estimateVersion = v.estimates;
  result.metricsVersion = v.metrics;
  result.metricsJson = merged(summary, angles);
  progress(100);
  return result;
}

QJsonObject filterSettingsJson(const EstimateOptions& settings, const QString& storedJson) {
  QJsonObject o = detail::parseObject(storedJson).value_or(QJsonObject{});
  const QJsonObject f = filterSettingsJson(settings);
  for (auto it = f.begin(); it != f.end(); ++it) o.insert(it.key(), it.value());
  if (!settings.jointAccelStdDeg) o.remove("joint_accel_std_deg");
  return o;
}

void keepSessionCalibration(ClinicalStore& store, qint64 sessionId,
                            const Calibration& calibration) {
  QJsonObject f = detail::parseObject(store.session(sessionId).filterJson).value_or(QJsonObject{});
  const std::string name = sessionText(sessionId) + "'s calibration";
  QJsonObject c;
  try {
    c = QJsonDocument::fromJson(QByteArray::fromStdString(calibrationText(calibration, name)))
            .object();
  } catch (const CalibrationError& e) {
    throw StorageError(Kind::Usage, e.what());
  }
  f.insert("calibration", c);
  store.updateSessionFilterSettings(
      sessionId, QString::fromUtf8(QJsonDocument(f).toJson(QJsonDocument::Compact)));
}

QJsonObject filterSettingsJson(const EstimateOptions& settings) {
  QJsonObject o{{"filter", filterName(settings.filter)},
                {"method", QString::fromStdString(methodName(settings.model))},
                {"optical", settings.useOptical},
                {"camera", settings.useCamera}};
  if (settings.jointAccelStdDeg) o.insert("joint_accel_std_deg", *settings.jointAccelStdDeg);
  return o;
}

}  // namespace armtrack::storage
