#include "app/cli/AutoCalibration.h"

#include <exception>

#include "app/cli/Text.h"

namespace armtrack::cli {

AutoCalibrationResult autoCalibrate(const std::filesystem::path& input,
                                    const EstimateOptions& options,
                                    const AutoCalibrationParams& params) {
  Recording rec;
  try {
    RecordingReader reader(input);
    rec.meta = reader.meta();
    ArmSample s;
    double t0 = 0.0;
    while (reader.next(s)) {
      if (rec.samples.empty()) t0 = s.t;
      if (s.t - t0 > params.windowSeconds) break;
      rec.samples.push_back(s);
    }
  } catch (const std::exception& e) {
    AutoCalibrationResult out;
    out.line = "calibration from movement: not tried: the first " + shortest(params.windowSeconds) +
               " s could not be read (" + e.what() + ")";
    return out;
  }
  return armtrack::autoCalibrate(
      rec, [&](const RecordingMeta& meta) { return estimatorParamsFor(meta, options); }, params);
}

}  // namespace armtrack::cli
