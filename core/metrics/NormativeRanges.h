// Normative active ranges of motion of the five clinical angles, with their published source
// (docs/metrics.md), for comparing a patient's range of motion in reports.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "core/metrics/RangeOfMotion.h"

namespace armtrack {

/// Where a normal limit comes from.
enum class NormSource {
  Aaos,        ///< aaosNormativeRanges(): one value for everyone
  Soucie2011,  ///< the CDC's reference values by age group and sex (core/metrics/PatientNorms.h)
};

/// The source's citation, for reports and docs.
std::string_view normSourceCitation(NormSource s);
/// A short name ("AAOS", "Soucie et al. 2011") for a table cell or a caption.
std::string_view normSourceShortName(NormSource s);

/// Normal limits of one clinical angle on its signed axis (rad): the motion in the negative
/// direction (extension, adduction, external rotation, supination) as a negative limit. Each
/// limit names its own source, since a source may give one direction of an angle and not the
/// other (Soucie et al. give shoulder flexion but not extension).
struct NormativeRange {
  int angle = 0;                 ///< index in clinicalAngleInfo() order
  std::optional<double> minRad;  ///< limit of the negative direction; empty = not in source
  double maxRad = 0;             ///< limit of the positive direction
  NormSource minSource = NormSource::Aaos;  ///< where minRad comes from
  NormSource maxSource = NormSource::Aaos;  ///< where maxRad comes from
  std::string_view note;                    ///< what the AAOS values mean, and what is missing
};

/// AAOS values (American Academy of Orthopaedic Surgeons, "Joint Motion: Method of Measuring and
/// Recording", 1965), as tabulated by Norkin & White, "Measurement of Joint Motion: A Guide to
/// Goniometry", Table A.1: shoulder flexion 180 / extension 60, abduction 180, internal
/// (medial) rotation 70 / external (lateral) rotation 90, elbow flexion 150 / extension 0,
/// pronation 80 / supination 80 degrees. Adduction is not in that table (minRad empty).
const std::array<NormativeRange, kNumClinicalAngles>& aaosNormativeRanges();

/// The range's span (rad): maxRad - minRad, or maxRad when the source gives no negative limit.
double normativeSpanRad(const NormativeRange& r);

/// A patient's range of motion as a fraction of the normative span (1 = the full normal range).
double fractionOfNormativeSpan(const NormativeRange& r, double romRad);

/// The normal range of the motion the angle is named after, from the neutral position (rad):
/// flexion 180, abduction 180, internal rotation 70, elbow flexion 150, pronation 80 deg. What a
/// "flexion range of motion" is compared with; the span above adds the opposite motion
/// (extension, external rotation, supination), which belongs to the full arc only.
double namedMotionNormalRad(const NormativeRange& r);

/// A patient's range of motion of the named motion as a fraction of its normal range.
double fractionOfNamedMotionNormal(const NormativeRange& r, double romRad);

/// One direction of a clinical angle's motion: the one its name says (flexion, abduction,
/// internal rotation, elbow flexion, pronation) or the opposite one (extension, external
/// rotation, supination), the signed axis' negative side.
struct MotionDirection {
  int angle = 0;  ///< index in clinicalAngleInfo() order
  bool opposite = false;
};

/// The directions with a normal limit of their own, in angle order, each angle's named direction
/// first: the opposite one where the range gives a negative limit (not shoulder adduction, which
/// has none in the AAOS table, nor elbow extension, whose normal end is 0).
std::vector<MotionDirection> motionDirections(
    const std::array<NormativeRange, kNumClinicalAngles>& ranges);

/// The direction's normal range from the neutral position (rad): namedMotionNormalRad, or minus
/// the negative limit (0 where there is none).
double motionNormalRad(const NormativeRange& r, bool opposite);

/// The largest angle a session reached in the direction (rad), from its smallest and largest
/// angle: the largest, or minus the smallest. Empty when that end is unknown.
std::optional<double> largestInDirection(const std::optional<double>& minRad,
                                         const std::optional<double>& maxRad, bool opposite);

/// "% of normal", the one definition the patient page, the progress chart and the PDF reports
/// share (docs/metrics.md, "Percent of normal"): the largest angle the session reached in the
/// direction (largestInDirection) against that direction's normal range from the neutral
/// position (motionNormalRad), in percent; shoulder flexion of 80 deg against a normal 180 is
/// 44 %. Not the range of motion against the whole arc (flexion plus extension, 240 deg): a
/// normal range counts motion in one direction. Never below 0 (a session that did not reach
/// the neutral position); empty when that end is unknown or the direction has no normal limit.
std::optional<double> percentOfNormal(const NormativeRange& r, const std::optional<double>& minRad,
                                      const std::optional<double>& maxRad, bool opposite = false);

}  // namespace armtrack
