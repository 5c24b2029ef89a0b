#include "core/estimation/RecordingEstimator.h"

#include <algorithm>
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
  return p;
}

EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                const EstimateCallbacks& callbacks) {
  const std::vector<ArmSample>& samples = recording.samples;
  const std::size_t n = samples.size();
  EstimateStats st;
  st.rows = n;

  double tLastImu = std::numeric_limits<double>::quiet_NaN();
  for (auto it = samples.rbegin(); it != samples.rend(); ++it) {
    if (it->hasImu()) {
      tLastImu = it->t;
      break;
    }
  }

  const auto filter = makeEstimator(params);
  ErrorAccumulator all, first, last;
  bool started = false;
  double tStart = 0.0;  // time of the latest (re)start
  int nextPercent = 10;
  std::size_t nextRow = callbacks.progress ? n / 10 : std::numeric_limits<std::size_t>::max();

  EstimateRow row;
  for (std::size_t i = 0; i < n; ++i) {
    if (callbacks.cancel && i % kCancelCheckRows == 0 &&
        callbacks.cancel->load(std::memory_order_relaxed)) {
      st.cancelled = true;
      break;
    }
    const ArmSample& s = samples[i];
    const UpdateResult r = filter->update(s);
    st.imuRows += s.hasImu();
    if (hasEstimate(r) && s.hasImu()) {
      const JointEstimate e = filter->estimate();
      if (r == UpdateResult::Initialised) tStart = e.t;
      if (!started) {
        started = true;
        st.tFirst = e.t;
        // Windows within the data: the first after start-up, the last after the first.
        st.firstWindow.from = std::min(st.tFirst + kStartupSeconds, tLastImu);
        st.firstWindow.to = std::min(st.firstWindow.from + kWindowSeconds, tLastImu);
        st.lastWindow.to = tLastImu;
        st.lastWindow.from = std::max(tLastImu - kWindowSeconds, st.firstWindow.to);
      }
      st.tLast = e.t;
      ++st.estimates;
      st.predicted += r == UpdateResult::Predicted;
      if (callbacks.row) {
        row.t = e.t;
        row.th = e.th;
        row.sd = e.thStd;
        row.status = statusOf(r);
        callbacks.row(row);
      }
      st.truthRows += s.trueAngles.has_value();
      if (s.trueAngles && e.t >= tStart + kStartupSeconds) {
        all.add(e.th, *s.trueAngles);
        if (e.t >= st.firstWindow.from && e.t <= st.firstWindow.to) first.add(e.th, *s.trueAngles);
        if (e.t > st.lastWindow.from && e.t <= st.lastWindow.to) last.add(e.th, *s.trueAngles);
      }
    }
    if (i + 1 >= nextRow) {
      callbacks.progress(nextPercent);
      nextPercent += 10;
      nextRow = nextPercent <= 100 ? n * static_cast<std::size_t>(nextPercent) / 100
                                   : std::numeric_limits<std::size_t>::max();
    }
  }

  st.counters = filter->counters();
  st.opticalUsed = st.counters.opticalUpdates > 0 || st.counters.cameraUpdates > 0;
  st.truthCount = all.count();
  st.rmseDeg = all.rmse() / kDeg;
  st.peakDeg = all.peak() / kDeg;
  st.firstWindow.count = first.count();
  st.firstWindow.rmseDeg = first.rmse() / kDeg;
  st.lastWindow.count = last.count();
  st.lastWindow.rmseDeg = last.rmse() / kDeg;
  return st;
}

}  // namespace armtrack
