// Internal to core/storage's session analysis: what analyseSession (SessionAnalysis.cpp) and the
// readers of stored analyses (StoredAnalysis.cpp) share, above all the one rule for the rows the
// metrics use, so that an analysis and a report computed later from its estimates agree.
#pragma once

#include <QJsonObject>
#include <QString>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/estimation/RecordingEstimator.h"
#include "core/metrics/ClinicalMetrics.h"
#include "core/storage/ClinicalStore.h"
#include "core/storage/SessionAnalysis.h"

namespace armtrack::storage::detail {

/// "session N", the start of every message about a session.
std::string sessionText(qint64 id);
/// The key of clinical angle index (clinicalAngleInfo() order), e.g. "shoulder_flexion".
QString angleKey(int index);

/// The rows the metrics use, and what was left out.
struct MetricRows {
  AngleSeries metricSeries;               // what the metrics are computed from
  std::vector<JointVector> metricJoints;  // the same rows as joint angles (rad)
  std::vector<ClinicalRow> sdRad;         // standard deviations of the series' rows, when asked for
  // The trunk's angles and standard deviations (rad) of the series' rows, when the estimates
  // hold them (empty otherwise).
  std::vector<Eigen::Vector3d> trunkRad, trunkSdRad;
  std::size_t dropped = 0, settling = 0;
};

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

  /// trunk and trunkSd: the row's trunk angles and their standard deviations, when the
  /// estimates hold them (both or neither, for every row alike).
  void add(double t, const JointVector& th, const JointVector& sd, int status,
           const Eigen::Vector3d* trunk = nullptr, const Eigen::Vector3d* trunkSd = nullptr) {
    ++m_rows;
    if (status == kStatusRestarted || status == kStatusRecovered)
      m_settledFrom = t + kStartupSeconds;
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
    if (trunk && trunkSd) {
      m_trunk.push_back(*trunk);
      m_trunkSd.push_back(*trunkSd);
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
      throw StorageError(StorageError::Kind::Usage,
                         sessionText(sessionId) + ": " + std::to_string(m_rows) + " estimates, " +
                             std::to_string(m_metricT.size()) +
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
    out.trunkRad = std::move(m_trunk);
    out.trunkSdRad = std::move(m_trunkSd);
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
  std::vector<Eigen::Vector3d> m_trunk, m_trunkSd;
};

/// Metrics parameters for a session: the wrist path from its geometry, repetitions on its
/// protocol's primary angle judged against the protocol's target (protocol is set then).
ClinicalMetricsParams metricsParams(ClinicalStore& store, const SessionInfo& info,
                                    const ArmGeometry& geometry, std::optional<Protocol>& protocol);

/// The metrics JSON as latestAnalysis() returns it: the summary with "angles" added.
QJsonObject merged(const QJsonObject& summary, const QJsonObject& angles);
/// The object json holds, or nothing when it is not one.
std::optional<QJsonObject> parseObject(const QString& json);

}  // namespace armtrack::storage::detail
