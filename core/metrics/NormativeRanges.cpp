#include "core/metrics/NormativeRanges.h"

namespace armtrack {

namespace {
constexpr std::string_view kAaos =
    "AAOS 1965, Joint Motion: Method of Measuring and Recording; via Norkin & White, "
    "Measurement of Joint Motion, Table A.1";
}  // namespace

const std::array<NormativeRange, kNumClinicalAngles>& aaosNormativeRanges() {
  static const std::array<NormativeRange, kNumClinicalAngles> ranges{{
      {0, -60.0 * kDegToRad, 180.0 * kDegToRad, kAaos, "flexion 180, extension 60 deg"},
      {1, std::nullopt, 180.0 * kDegToRad, kAaos,
       "abduction 180 deg; adduction is not given in the source table"},
      {2, -90.0 * kDegToRad, 70.0 * kDegToRad, kAaos,
       "internal (medial) rotation 70, external (lateral) rotation 90 deg"},
      {3, 0.0, 150.0 * kDegToRad, kAaos, "flexion 150 deg from full extension (0)"},
      {4, -80.0 * kDegToRad, 80.0 * kDegToRad, kAaos, "pronation 80, supination 80 deg"},
  }};
  return ranges;
}

double normativeSpanRad(const NormativeRange& r) {
  return r.maxRad - r.minRad.value_or(0.0);
}

double fractionOfNormativeSpan(const NormativeRange& r, double romRad) {
  return romRad / normativeSpanRad(r);
}

double namedMotionNormalRad(const NormativeRange& r) {
  return r.maxRad;
}

double fractionOfNamedMotionNormal(const NormativeRange& r, double romRad) {
  return romRad / namedMotionNormalRad(r);
}

}  // namespace armtrack
