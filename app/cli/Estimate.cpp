#include "app/cli/Estimate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "app/cli/Text.h"
#include "core/metrics/Accuracy.h"

namespace armtrack::cli {

namespace {

constexpr double kStartupSeconds = 1.0;  // left out of the statistics after each (re)start
constexpr double kWindowSeconds = 10.0;  // drift comparison windows
constexpr const char* kJointLabels[kNumJoints] = {
    "th0 shoulder flexion/extension", "th1 shoulder abduction/adduction",
    "th2 shoulder internal/external rotation", "th4 elbow flexion/extension",
    "th5 forearm pronation/supination"};

}  // namespace

EstimatorParams makeParams(const RecordingMeta& meta, const EstimateOptions& options) {
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

// ---------------------------------------------------------------------------------------------

EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                CsvOutput* writer, const EstimateProgress& progress) {
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
  const bool reporting = progress && n > kProgressRows;
  int nextPercent = 10;
  std::size_t nextRow = reporting ? n / 10 : std::numeric_limits<std::size_t>::max();

  std::array<double, 2 * kNumJoints + 1> values{};
  for (std::size_t i = 0; i < n; ++i) {
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
      if (writer) {
        std::copy(e.th.data(), e.th.data() + kNumJoints, values.begin());
        std::copy(e.thStd.data(), e.thStd.data() + kNumJoints, values.begin() + kNumJoints);
        values.back() = r == UpdateResult::Predicted     ? kStatusPredicted
                        : r == UpdateResult::Initialised ? kStatusRestarted
                        : r == UpdateResult::Recovered   ? kStatusRecovered
                                                         : kStatusFused;
        writer->row(e.t, values.data(), static_cast<int>(values.size()));
      }
      st.truthRows += s.trueAngles.has_value();
      if (s.trueAngles && e.t >= tStart + kStartupSeconds) {
        all.add(e.th, *s.trueAngles);
        if (e.t >= st.firstWindow.from && e.t <= st.firstWindow.to) first.add(e.th, *s.trueAngles);
        if (e.t > st.lastWindow.from && e.t <= st.lastWindow.to) last.add(e.th, *s.trueAngles);
      }
    }
    if (i + 1 >= nextRow) {
      progress(nextPercent);
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

std::string formatReport(const EstimateStats& st) {
  std::string s;
  if (st.truthCount > 0) {
    s += "Error against the true angles (" + std::to_string(st.truthCount) +
         " samples; the first second after start-up is left out):\n\n";
    s += "| joint | RMSE (deg) | peak (deg) |\n|---|---:|---:|\n";
    for (int j = 0; j < kNumJoints; ++j) {
      s += "| " + std::string(kJointLabels[j]) + " | " + fixed(st.rmseDeg(j), 3) + " | " +
           fixed(st.peakDeg(j), 3) + " |\n";
    }
  }
  if (!st.opticalUsed) {
    if (!s.empty()) s += "\n";
    s += "No optical data: the arm's heading about the vertical is not observable from IMUs "
         "alone; shoulder angles rest on the start-pose assumption and drift with it.\n";
    if (st.truthCount > 0) {
      s += "\nRMSE (deg) early vs late, to show the drift:\n\n";
      s += "| window | th0 | th1 | th2 | th4 | th5 |\n|---|---:|---:|---:|---:|---:|\n";
      for (const auto& [name, w] :
           {std::pair{"first", &st.firstWindow}, std::pair{"last", &st.lastWindow}}) {
        if (w->count == 0) continue;  // a recording too short for two windows has one
        s += "| " + std::string(name) + " " + fixed(w->to - w->from, 1) + " s (" +
             fixed(w->from, 1) + "-" + fixed(w->to, 1) + " s) |";
        for (int j = 0; j < kNumJoints; ++j) {
          s += " " + (w->count > 0 ? fixed(w->rmseDeg(j), 3) : std::string("-")) + " |";
        }
        s += "\n";
      }
    }
  }
  return s;
}

}  // namespace armtrack::cli
