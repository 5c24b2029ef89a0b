#include "app/cli/Estimate.h"

#include <algorithm>
#include <array>

#include "app/cli/Text.h"

namespace armtrack::cli {

namespace {

constexpr const char* kJointLabels[kNumJoints] = {
    "th0 shoulder flexion/extension", "th1 shoulder abduction/adduction",
    "th2 shoulder internal/external rotation", "th4 elbow flexion/extension",
    "th5 forearm pronation/supination"};

}  // namespace

EstimatorParams makeParams(const RecordingMeta& meta, const EstimateOptions& options) {
  return estimatorParamsFor(meta, options);
}

EstimateStats estimateRecording(const Recording& recording, const EstimatorParams& params,
                                CsvOutput* writer, const EstimateProgress& progress) {
  EstimateCallbacks callbacks;
  std::array<double, 2 * kNumJoints + 1> values{};
  if (writer) {
    callbacks.row = [&](const EstimateRow& r) {
      std::copy(r.th.data(), r.th.data() + kNumJoints, values.begin());
      std::copy(r.sd.data(), r.sd.data() + kNumJoints, values.begin() + kNumJoints);
      values.back() = r.status;
      writer->row(r.t, values.data(), static_cast<int>(values.size()));
    };
  }
  if (progress && recording.samples.size() > kProgressRows) callbacks.progress = progress;
  return armtrack::estimateRecording(recording, params, callbacks);
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
