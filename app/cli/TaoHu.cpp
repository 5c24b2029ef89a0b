#include "app/cli/TaoHu.h"

#include <chrono>
#include <stdexcept>

#include "app/cli/Text.h"

namespace armtrack::cli {

namespace {
constexpr const char* kJointLabels[kNumJoints] = {
    "th0 shoulder flexion/extension", "th1 shoulder abduction/adduction",
    "th2 shoulder internal/external rotation", "th4 elbow flexion/extension",
    "th5 forearm pronation/supination (from the IMU)"};
}  // namespace

TaoHuRun runTaoHuRecording(const Recording& recording, CsvOutput* writer) {
  TaoHuRun run;
  const auto start = std::chrono::steady_clock::now();
  try {
    run.result = runTaoHu(recording, taoHuParams(recording.meta));
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(std::string("--method tao-hu: ") + e.what());
  }
  if (writer) {
    double row[11];
    for (const TaoHuFrame& f : run.result.frames) {
      for (int i = 0; i < 3; ++i) {
        row[i] = f.wrist(i);
        row[3 + i] = f.elbow(i);
      }
      for (int j = 0; j < kNumJoints; ++j) row[6 + j] = f.th(j);
      writer->row(f.t, row, 11);
    }
  }
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.errors = taoHuErrors(run.result, recording.meta.geometry, recording.meta.side);
  return run;
}

std::string formatTaoHuReport(const TaoHuRun& run) {
  const TaoHuErrors& e = run.errors;
  if (e.count == 0) return {};
  std::string s = "Error against the true angles (" + std::to_string(e.count) +
                  " camera frames; the first second after start-up is left out):\n\n";
  s += "| joint | RMSE (deg) | peak (deg) |\n|---|---:|---:|\n";
  for (int j = 0; j < kNumJoints; ++j) {
    s += "| " + std::string(kJointLabels[j]) + " | " + fixed(e.rmseDeg(j), 3) + " | " +
         fixed(e.peakDeg(j), 3) + " |\n";
  }
  s += "\nPosition error against the forward kinematics of the true angles:\n\n";
  s += "| point | RMSE (cm) | peak (cm) |\n|---|---:|---:|\n";
  s += "| wrist | " + fixed(e.wristRmseCm, 2) + " | " + fixed(e.wristPeakCm, 2) + " |\n";
  s += "| elbow | " + fixed(e.elbowRmseCm, 2) + " | " + fixed(e.elbowPeakCm, 2) + " |\n";
  s += "\nLargest wrist error in one coordinate: " + fixed(e.wristAxisPeakCm, 2) +
       " cm (Tao & Hu report +/-5 cm per coordinate).\n";
  return s;
}

}  // namespace armtrack::cli
