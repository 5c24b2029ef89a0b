// Normal ranges of motion for one patient (docs/metrics.md, "Normative ranges"): the CDC's
// reference values by age group and sex (Soucie et al. 2011) where the study measured the
// motion, the AAOS values elsewhere, each limit naming its source. Plain C++, no Qt.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>

#include "core/metrics/NormativeRanges.h"

namespace armtrack {

enum class Sex { Female, Male, Unknown };

/// A patient's sex as stored in the clinical records ("f", "m", any case); anything else
/// ("x", "") is Unknown.
Sex sexFromCode(std::string_view code);

/// A calendar date (proleptic Gregorian).
struct CivilDate {
  int year = 0, month = 0, day = 0;
};

bool isValidDate(const CivilDate& d);

/// The date of "YYYY-MM-DD", or of an ISO 8601 date-time that starts with one
/// ("2026-11-20T09:15:00Z"); empty when the text does not start with a valid date.
std::optional<CivilDate> parseIsoDate(std::string_view text);

/// Completed years of age on `on`: a year is completed on the birthday's month and day, so a
/// 29 February birthday completes it on 1 March in a common year. Empty when a date is invalid
/// or `on` is before `birth`.
std::optional<int> ageInYears(const CivilDate& birth, const CivilDate& on);

/// An age group of the study, in completed years (inclusive).
struct SoucieAgeGroup {
  int fromYears, toYears;
};
/// The study's four groups: 2-8, 9-19, 20-44, 45-69 years.
inline constexpr std::array<SoucieAgeGroup, 4> kSoucieAgeGroups{
    {{2, 8}, {9, 19}, {20, 44}, {45, 69}}};

/// The index in kSoucieAgeGroups of an age in completed years; empty outside 2-69.
std::optional<int> soucieAgeGroup(int ageYears);

/// The motions of the study that are limits of our clinical angles. Soucie et al. also measured
/// hip, knee and ankle; not shoulder abduction, adduction or rotation.
enum class SoucieMotion {
  ShoulderFlexion,    ///< maxRad of shoulder flexion
  ElbowFlexion,       ///< maxRad of elbow flexion
  ElbowExtension,     ///< past straight (hyperextension, positive): minRad = -value
  ForearmPronation,   ///< maxRad of forearm pronation
  ForearmSupination,  ///< minRad = -value
};

/// One reference value of the study (deg): the mean passive range of motion of healthy subjects
/// of one age group and sex, with the 95 % confidence interval of that mean.
struct SoucieValue {
  SoucieMotion motion;
  int ageGroup;  ///< index in kSoucieAgeGroups
  Sex sex;       ///< Female or Male
  double meanDeg, ciLowDeg, ciHighDeg;
};

/// The reference values this version carries, each as printed on the CDC's page
/// (normSourceCitation(NormSource::Soucie2011)). Only values read from that page go in; a
/// motion, group or sex without a value falls back to AAOS.
std::span<const SoucieValue> soucieReferenceValues();

/// Why a patient's ranges are all AAOS.
enum class NormFallback {
  None,             ///< at least one limit comes from Soucie et al.
  AgeUnknown,       ///< no valid birth or session date, or a birth after the session
  AgeOutsideStudy,  ///< under 2 or over 69 years on the day
  SexUnknown,       ///< sex not recorded as female or male
  NoValues,         ///< the table has no value for the patient's age group and sex
};

/// The normal ranges of one patient on one day.
struct PatientNorms {
  /// Per angle, in clinicalAngleInfo() order; each limit names its source.
  std::array<NormativeRange, kNumClinicalAngles> ranges;
  std::optional<int> ageYears;  ///< on the day, when the birth date is known
  std::optional<int> ageGroup;  ///< index in kSoucieAgeGroups, when the age is in one
  Sex sex = Sex::Unknown;
  /// Why no limit comes from Soucie et al. (None when at least one does).
  NormFallback fallback = NormFallback::None;
  bool usesSoucie() const;
};

/// The normal ranges for a patient born on `birth` (empty = unknown), of sex `sex`, measured on
/// `on`: every limit the study covers for that age group and sex from `table`, the rest (and
/// everything when no row matches) from aaosNormativeRanges().
PatientNorms patientNorms(std::optional<CivilDate> birth, const CivilDate& on, Sex sex,
                          std::span<const SoucieValue> table = soucieReferenceValues());

/// The "% of normal" of one session of a patient, the one the patient page, the progress chart
/// and both PDF reports show: percentOfNormal() of the largest angle in the direction against
/// the patient's normal range on the session's day (patientNorms(): Soucie et al. where the
/// study covers the patient's age and sex, else AAOS). birth and on empty = unknown (AAOS).
std::optional<double> sessionPercentOfNormal(std::optional<CivilDate> birth, Sex sex,
                                             std::optional<CivilDate> on, int angle,
                                             const std::optional<double>& minRad,
                                             const std::optional<double>& maxRad,
                                             bool opposite = false);

}  // namespace armtrack
