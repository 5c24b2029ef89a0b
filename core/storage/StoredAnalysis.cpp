// Reading stored analyses back: the estimates a block at a time, the newest analysis, and what
// reports and exports draw from (docs/storage.md, "Estimates" and "Metrics").
#include <QJsonArray>
#include <QJsonDocument>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "core/storage/AnalysisRows.h"
#include "core/storage/EstimateCodec.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::storage {

namespace {

using Kind = StorageError::Kind;
using detail::angleKey;
using detail::merged;
using detail::MetricRowCollector;
using detail::MetricRows;
using detail::metricsParams;
using detail::parseObject;
using detail::sessionText;

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
  std::optional<bool> trunk;  // whether the chunks hold the trunk's columns: all or none
  double lastT = -std::numeric_limits<double>::infinity();
  store.readEstimateChunks(rec, [&](int seq, std::uint64_t n, const QByteArray& data) {
    if (seq != expectedSeq) throw damaged("chunk " + std::to_string(expectedSeq) + " is missing");
    ++expectedSeq;
    EstimateColumns block;
    try {
      block = EstimateCodec::decode(std::string(data.constData(), data.size()), n);
    } catch (const std::runtime_error& e) {
      throw damaged("chunk " + std::to_string(seq) + ": " + e.what());
    }
    if (block.size() > 0) {
      if (trunk && *trunk != block.hasTrunk())
        throw damaged("chunk " + std::to_string(seq) +
                      (block.hasTrunk() ? " holds the trunk's angles, the chunks before do not"
                                        : " lacks the trunk's angles the chunks before hold"));
      trunk = block.hasTrunk();
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
  forEachEstimateBlock(
      store, *rec, versionText(sessionId, rec->version), [&](EstimateColumns&& block) {
        if (a.t.empty()) {
          a.t = std::move(block.t);
          a.joints = std::move(block.th);
          a.sd = std::move(block.sd);
          a.status = std::move(block.status);
          a.trunk = std::move(block.trunk);
          a.trunkSd = std::move(block.trunkSd);
          return;
        }
        a.t.insert(a.t.end(), block.t.begin(), block.t.end());
        a.joints.insert(a.joints.end(), block.th.begin(), block.th.end());
        a.sd.insert(a.sd.end(), block.sd.begin(), block.sd.end());
        a.status.insert(a.status.end(), block.status.begin(), block.status.end());
        a.trunk.insert(a.trunk.end(), block.trunk.begin(), block.trunk.end());
        a.trunkSd.insert(a.trunkSd.end(), block.trunkSd.begin(), block.trunkSd.end());
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
  forEachEstimateBlock(
      store, *rec, versionText(sessionId, rec->version), [&](EstimateColumns&& block) {
        const bool trunk = block.hasTrunk();
        for (std::size_t i = 0; i < block.size(); ++i)
          collector.add(block.t[i], block.th[i], block.sd[i], block.status[i],
                        trunk ? &block.trunk[i] : nullptr, trunk ? &block.trunkSd[i] : nullptr);
      });
  MetricRows settled = collector.finish(sessionId, &out.series);
  try {
    out.metrics = computeSessionMetrics(settled.metricSeries, mp);
  } catch (const std::invalid_argument& e) {
    throw StorageError(Kind::Usage,
                       sessionText(sessionId) + ": metrics cannot be computed: " + e.what());
  }
  out.sdRad = std::move(settled.sdRad);
  out.trunkRad = std::move(settled.trunkRad);
  out.trunkSdRad = std::move(settled.trunkSdRad);
  return out;
}

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
    out.repetitionSmoothness.push_back(
        {smoothnessFromJson(o, "sparc"), smoothnessFromJson(o, "ldlj")});
  }
  return out;
}

namespace {

std::optional<double> optionalOf(const QJsonObject& o, const char* key) {
  const QJsonValue v = o.value(key);
  if (!v.isDouble() || !std::isfinite(v.toDouble())) return std::nullopt;
  return v.toDouble();
}

TrunkExtremes extremesFromJson(const QJsonObject& o) {
  TrunkExtremes x;
  x.maxFlexionDeg = optionalOf(o, "max_flexion_deg");
  x.maxLateralDeg = optionalOf(o, "max_lateral_deg");
  x.maxRotationDeg = optionalOf(o, "max_rotation_deg");
  x.maxShoulderDisplacementCm = optionalOf(o, "max_shoulder_displacement_cm");
  if (o.value("compensated").isBool()) x.compensated = o.value("compensated").toBool();
  return x;
}

}  // namespace

bool measured(const TrunkExtremes& x) {
  return x.maxFlexionDeg || x.maxLateralDeg || x.maxRotationDeg || x.maxShoulderDisplacementCm;
}

std::optional<TrunkCompensation> trunkCompensationFromJson(const QJsonObject& m) {
  if (!m.value("trunk").isObject()) return std::nullopt;
  TrunkCompensation out;
  out.session = extremesFromJson(m.value("trunk").toObject());
  const QJsonObject reps = m.value("repetitions").toObject();
  for (const QJsonValue& v : reps.value("list").toArray())
    out.repetitions.push_back(extremesFromJson(v.toObject().value("trunk").toObject()));
  const QJsonValue n = reps.value("repetitions_with_compensation");
  if (n.isDouble() && n.toDouble() >= 0)
    out.repetitionsWithCompensation = static_cast<std::size_t>(n.toInteger());
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
    throw StorageError(Kind::Corrupt,
                       where + "its rows: " + e.what() + " (run 'session reestimate')");
  }
  return out;
}

}  // namespace armtrack::storage
