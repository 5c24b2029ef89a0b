#include "core/estimation/RecordingEstimator.h"

#include <algorithm>
#include <deque>
#include <limits>

#include "core/metrics/Accuracy.h"

namespace armtrack {

namespace {

constexpr double kWindowSeconds = 10.0;  // drift comparison windows
constexpr std::size_t kCancelCheckRows = 1024;

int statusOf(UpdateResult r) {
  return r == UpdateResult::Predicted     ? kStatusPredicted
         : r == UpdateResult::Initialised ? kStatusRestarted
         : r == UpdateResult::Recovered   ? kStatusRecovered
                                          : kStatusFused;
}

}  // namespace

EstimatorParams estimatorParamsFor(const RecordingMeta& meta, const EstimateOptions& options) {
  EstimatorParams p = recordingParams(meta);
  p.filter = options.filter;
  p.model = options.model;
  p.useOptical = options.useOptical;
  p.useCamera = options.useCamera;
  if (options.jointAccelStdDeg) {
    const double s = *options.jointAccelStdDeg * kDeg;
    p.jointAccelVariance = s * s;
  }
  if (options.gyroNoiseStdDeg) {
    const double s = *options.gyroNoiseStdDeg * kDeg;
    p.gyroVariance = s * s;
  }
  if (options.accelNoiseStd) p.accelVariance = *options.accelNoiseStd * *options.accelNoiseStd;
  return p;
}

// One error sample of the last drift window, held until the window is known.
struct RecentError {
  double t;
  JointVector th, truth;
};

struct StreamingEstimator::Impl {
  explicit Impl(const EstimatorParams& params) : filter(makeEstimator(params)) {}

  std::unique_ptr<JointEstimator> filter;
  ErrorAccumulator all, first;
  std::deque<RecentError> recent;  // error samples of the last kWindowSeconds, in time order
  bool started = false;
  double tStart = 0.0;                                         // time of the latest (re)start
  double tLastImu = std::numeric_limits<double>::quiet_NaN();  // the latest IMU sample's time
  double firstFrom = 0.0, firstTo = 0.0;  // the first window, before it is cut at the data's end
  // Without a trunk IMU, an optical shoulder tells whether the trunk moved (status 4).
  std::optional<TrunkMotionDetector> trunkDetector;
  bool trunkImuSeen = false;
  Eigen::Vector3d trunkSquared = Eigen::Vector3d::Zero();  // summed squared trunk errors (rad^2)
  Eigen::Vector3d trunkPeak = Eigen::Vector3d::Zero();     // largest trunk errors (rad)
};

StreamingEstimator::StreamingEstimator(const EstimatorParams& params)
    : m_impl(std::make_unique<Impl>(params)) {}

StreamingEstimator::~StreamingEstimator() = default;

bool StreamingEstimator::push(const ArmSample& s, EstimateRow& row) {
  Impl& d = *m_impl;
  ++m_st.rows;
  const UpdateResult r = d.filter->update(s);
  if (s.trunk) d.trunkImuSeen = true;
  if (s.shoulder && !d.trunkDetector && !d.trunkImuSeen) d.trunkDetector.emplace();
  bool trunkMoved = false;
  if (d.trunkDetector && !d.trunkImuSeen) {
    TrunkMotionInput in;
    in.t = s.t;
    in.shoulder = s.shoulder;
    trunkMoved = d.trunkDetector->update(in).moving;
  }
  if (!s.hasImu()) return false;
  ++m_st.imuRows;
  d.tLastImu = s.t;
  if (!hasEstimate(r)) return false;
  const JointEstimate e = d.filter->estimate();
  if (r == UpdateResult::Initialised) d.tStart = e.t;
  if (!d.started) {
    d.started = true;
    m_st.tFirst = e.t;
    d.firstFrom = m_st.tFirst + kStartupSeconds;
    d.firstTo = d.firstFrom + kWindowSeconds;
  }
  m_st.tLast = e.t;
  ++m_st.estimates;
  m_st.predicted += r == UpdateResult::Predicted;
  row.t = e.t;
  row.th = e.th;
  row.sd = e.thStd;
  row.status = statusOf(r);
  if (trunkMoved && row.status == kStatusFused) row.status = kStatusTrunkMoved;
  row.trunk.setConstant(std::numeric_limits<double>::quiet_NaN());
  row.trunkSd = row.trunk;
  if (const std::optional<TrunkEstimate> trunk = d.filter->trunk(); trunk && trunk->measured) {
    row.trunk = trunk->angles;
    row.trunkSd = trunk->angleStd;
    if (s.trueTrunk && e.t >= d.tStart + kStartupSeconds) {
      const Eigen::Vector3d err = trunk->angles - *s.trueTrunk;
      d.trunkSquared += err.cwiseAbs2();
      d.trunkPeak = d.trunkPeak.cwiseMax(err.cwiseAbs());
      ++m_st.trunkTruthCount;
    }
  }
  m_st.truthRows += s.trueAngles.has_value();
  if (s.trueAngles && e.t >= d.tStart + kStartupSeconds) {
    d.all.add(e.th, *s.trueAngles);
    // Estimates are never later than the last IMU sample, so the first window's end can be
    // applied when that sample is known (stats()); until then, its full length is used.
    if (e.t >= d.firstFrom && e.t <= d.firstTo) d.first.add(e.th, *s.trueAngles);
    d.recent.push_back({e.t, e.th, *s.trueAngles});
  }
  // What lies kWindowSeconds before the latest IMU sample cannot be in the last window.
  while (!d.recent.empty() && d.recent.front().t <= d.tLastImu - kWindowSeconds)
    d.recent.pop_front();
  return true;
}

EstimateStats StreamingEstimator::stats() const {
  const Impl& d = *m_impl;
  EstimateStats st = m_st;
  ErrorAccumulator last;
  if (d.started) {
    // Windows within the data: the first after start-up, the last after the first.
    const double tEnd = d.tLastImu;
    st.firstWindow.from = std::min(st.tFirst + kStartupSeconds, tEnd);
    st.firstWindow.to = std::min(st.firstWindow.from + kWindowSeconds, tEnd);
    st.lastWindow.to = tEnd;
    st.lastWindow.from = std::max(tEnd - kWindowSeconds, st.firstWindow.to);
    for (const RecentError& e : d.recent)
      if (e.t > st.lastWindow.from && e.t <= st.lastWindow.to) last.add(e.th, e.truth);
  }
  st.counters = d.filter->counters();
  st.opticalUsed = st.counters.opticalUpdates > 0 || st.counters.cameraUpdates > 0;
  st.truthCount = d.all.count();
  st.rmseDeg = d.all.rmse() / kDeg;
  st.peakDeg = d.all.peak() / kDeg;
  if (d.trunkDetector && !d.trunkImuSeen) st.trunkMovedSpans = d.trunkDetector->spans();
  if (st.trunkTruthCount > 0) {
    st.trunkRmseDeg = (d.trunkSquared / double(st.trunkTruthCount)).cwiseSqrt() / kDeg;
    st.trunkPeakDeg = d.trunkPeak / kDeg;
  }
  st.firstWindow.count = d.first.count();
  st.firstWindow.rmseDeg = d.first.rmse() / kDeg;
  st.lastWindow.count = last.count();
  st.lastWindow.rmseDeg = last.rmse() / kDeg;
  return st;
}

EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                const EstimateCallbacks& callbacks) {
  const std::vector<ArmSample>& samples = recording.samples;
  const std::size_t n = samples.size();
  StreamingEstimator estimator(params);
  bool cancelled = false;
  int nextPercent = 10;
  std::size_t nextRow = callbacks.progress ? n / 10 : std::numeric_limits<std::size_t>::max();

  EstimateRow row;
  for (std::size_t i = 0; i < n; ++i) {
    if (callbacks.cancel && i % kCancelCheckRows == 0 &&
        callbacks.cancel->load(std::memory_order_relaxed)) {
      cancelled = true;
      break;
    }
    if (estimator.push(samples[i], row) && callbacks.row) callbacks.row(row);
    if (i + 1 >= nextRow) {
      callbacks.progress(nextPercent);
      nextPercent += 10;
      nextRow = nextPercent <= 100 ? n * static_cast<std::size_t>(nextPercent) / 100
                                   : std::numeric_limits<std::size_t>::max();
    }
  }
  EstimateStats st = estimator.stats();
  st.rows = n;
  st.cancelled = cancelled;
  return st;
}

}  // namespace armtrack
