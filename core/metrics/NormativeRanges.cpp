#include "core/metrics/NormativeRanges.h"

#include <algorithm>
#include <cmath>

namespace armtrack {

std::string_view normSourceCitation(NormSource s) {
  switch (s) {
    case NormSource::Soucie2011:
      return "Soucie JM et al., Range of motion measurements: reference values and a database "
             "for comparison studies, Haemophilia 2011;17(3):500-507, "
             "doi:10.1111/j.1365-2516.2010.02399.x; values from the CDC's Joint Range of Motion "
             "Study, archive.cdc.gov/www_cdc_gov/ncbddd/jointrom/index.html";
    case NormSource::Aaos:
      break;
  }
  return "AAOS 1965, Joint Motion: Method of Measuring and Recording; via Norkin & White, "
         "Measurement of Joint Motion, Table A.1";
}

std::string_view normSourceShortName(NormSource s) {
  return s == NormSource::Soucie2011 ? "Soucie et al. 2011" : "AAOS";
}

const std::array<NormativeRange, kNumClinicalAngles>& aaosNormativeRanges() {
  using enum NormSource;
  static const std::array<NormativeRange, kNumClinicalAngles> ranges{{
      {0, -60.0 * kDegToRad, 180.0 * kDegToRad, Aaos, Aaos, "flexion 180, extension 60 deg"},
      {1, std::nullopt, 180.0 * kDegToRad, Aaos, Aaos,
       "abduction 180 deg; adduction is not given in the source table"},
      {2, -90.0 * kDegToRad, 70.0 * kDegToRad, Aaos, Aaos,
       "internal (medial) rotation 70, external (lateral) rotation 90 deg"},
      {3, 0.0, 150.0 * kDegToRad, Aaos, Aaos, "flexion 150 deg from full extension (0)"},
      {4, -80.0 * kDegToRad, 80.0 * kDegToRad, Aaos, Aaos, "pronation 80, supination 80 deg"},
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

std::vector<MotionDirection> motionDirections(
    const std::array<NormativeRange, kNumClinicalAngles>& ranges) {
  std::vector<MotionDirection> out;
  for (const NormativeRange& r : ranges) {
    out.push_back({r.angle, false});
    if (r.minRad && *r.minRad < 0) out.push_back({r.angle, true});
  }
  return out;
}

double motionNormalRad(const NormativeRange& r, bool opposite) {
  return opposite ? -r.minRad.value_or(0.0) : namedMotionNormalRad(r);
}

std::optional<double> largestInDirection(const std::optional<double>& minRad,
                                         const std::optional<double>& maxRad, bool opposite) {
  if (!opposite) return maxRad;
  return minRad ? std::optional<double>(-*minRad) : std::nullopt;
}

std::optional<double> percentOfNormal(const NormativeRange& r, const std::optional<double>& minRad,
                                      const std::optional<double>& maxRad, bool opposite) {
  const std::optional<double> peak = largestInDirection(minRad, maxRad, opposite);
  const double normal = motionNormalRad(r, opposite);
  if (!peak || !std::isfinite(*peak) || !(normal > 0)) return std::nullopt;
  return 100.0 * std::max(0.0, *peak / normal);
}

}  // namespace armtrack
