#include "core/metrics/PatientNorms.h"

#include <algorithm>
#include <cctype>
#include <tuple>

namespace armtrack {

namespace {

bool isLeap(int y) {
  return (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
}

int daysInMonth(int y, int m) {
  static constexpr std::array<int, 12> kDays{31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  return m == 2 && isLeap(y) ? 29 : kDays[static_cast<std::size_t>(m - 1)];
}

std::optional<int> digits(std::string_view s) {
  int v = 0;
  for (const char c : s) {
    if (c < '0' || c > '9') return std::nullopt;
    v = v * 10 + (c - '0');
  }
  return v;
}

/// Which limit of which clinical angle a motion of the study is.
struct MotionLimit {
  int angle;      ///< clinicalAngleInfo() order
  bool negative;  ///< the minimum, as -value; else the maximum
};
/// In SoucieMotion order: shoulder flexion, elbow flexion, elbow extension (past straight),
/// pronation, supination.
constexpr std::array<MotionLimit, 5> kMotionLimits{
    {{0, false}, {3, false}, {3, true}, {4, false}, {4, true}}};

// The reference values read from the CDC's page. None are entered yet: the page could not be
// read past its first age group's hip, knee and ankle rows where this was written (docs/metrics.md,
// "By age and sex: Soucie et al. 2011"). Enter each value as "mean (low - high)" is printed there,
// for example {SoucieMotion::ElbowFlexion, 2, Sex::Female, mean, low, high} for women aged 20-44.
constexpr std::array<SoucieValue, 0> kSoucieValues{};

}  // namespace

Sex sexFromCode(std::string_view code) {
  if (code.size() != 1) return Sex::Unknown;
  const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(code[0])));
  return c == 'f' ? Sex::Female : c == 'm' ? Sex::Male : Sex::Unknown;
}

bool isValidDate(const CivilDate& d) {
  return d.year >= 1 && d.year <= 9999 && d.month >= 1 && d.month <= 12 && d.day >= 1 &&
         d.day <= daysInMonth(d.year, d.month);
}

std::optional<CivilDate> parseIsoDate(std::string_view text) {
  if (text.size() < 10 || text[4] != '-' || text[7] != '-') return std::nullopt;
  if (text.size() > 10 && text[10] != 'T' && text[10] != ' ') return std::nullopt;
  const auto y = digits(text.substr(0, 4)), m = digits(text.substr(5, 2)),
             d = digits(text.substr(8, 2));
  if (!y || !m || !d) return std::nullopt;
  const CivilDate date{*y, *m, *d};
  return isValidDate(date) ? std::optional<CivilDate>(date) : std::nullopt;
}

std::optional<int> ageInYears(const CivilDate& birth, const CivilDate& on) {
  if (!isValidDate(birth) || !isValidDate(on)) return std::nullopt;
  if (std::tie(on.year, on.month, on.day) < std::tie(birth.year, birth.month, birth.day))
    return std::nullopt;
  const bool birthdayReached = std::tie(on.month, on.day) >= std::tie(birth.month, birth.day);
  return on.year - birth.year - (birthdayReached ? 0 : 1);
}

std::optional<int> soucieAgeGroup(int ageYears) {
  for (std::size_t g = 0; g < kSoucieAgeGroups.size(); ++g)
    if (ageYears >= kSoucieAgeGroups[g].fromYears && ageYears <= kSoucieAgeGroups[g].toYears)
      return static_cast<int>(g);
  return std::nullopt;
}

std::span<const SoucieValue> soucieReferenceValues() {
  return kSoucieValues;
}

bool PatientNorms::usesSoucie() const {
  return std::any_of(ranges.begin(), ranges.end(), [](const NormativeRange& r) {
    return r.maxSource == NormSource::Soucie2011 || r.minSource == NormSource::Soucie2011;
  });
}

PatientNorms patientNorms(std::optional<CivilDate> birth, const CivilDate& on, Sex sex,
                          std::span<const SoucieValue> table) {
  PatientNorms n;
  n.ranges = aaosNormativeRanges();
  n.sex = sex;
  if (birth) n.ageYears = ageInYears(*birth, on);
  if (n.ageYears) n.ageGroup = soucieAgeGroup(*n.ageYears);
  if (!n.ageYears) {
    n.fallback = NormFallback::AgeUnknown;
    return n;
  }
  if (!n.ageGroup) {
    n.fallback = NormFallback::AgeOutsideStudy;
    return n;
  }
  if (sex == Sex::Unknown) {
    n.fallback = NormFallback::SexUnknown;
    return n;
  }
  for (const SoucieValue& v : table) {
    if (v.ageGroup != *n.ageGroup || v.sex != sex) continue;
    const MotionLimit l = kMotionLimits[static_cast<std::size_t>(v.motion)];
    NormativeRange& r = n.ranges[static_cast<std::size_t>(l.angle)];
    const double rad = v.meanDeg * kDegToRad;
    if (l.negative) {
      r.minRad = -rad;
      r.minSource = NormSource::Soucie2011;
    } else {
      r.maxRad = rad;
      r.maxSource = NormSource::Soucie2011;
    }
  }
  if (!n.usesSoucie()) n.fallback = NormFallback::NoValues;
  return n;
}

std::optional<double> sessionPercentOfNormal(std::optional<CivilDate> birth, Sex sex,
                                             std::optional<CivilDate> on, int angle,
                                             const std::optional<double>& minRad,
                                             const std::optional<double>& maxRad, bool opposite) {
  if (angle < 0 || angle >= kNumClinicalAngles) return std::nullopt;
  const PatientNorms norms = patientNorms(birth, on.value_or(CivilDate{}), sex);
  return percentOfNormal(norms.ranges[static_cast<std::size_t>(angle)], minRad, maxRad, opposite);
}

}  // namespace armtrack
