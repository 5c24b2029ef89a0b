// Normal ranges for one patient (core/metrics/PatientNorms.h): the age on the session's day, the
// Soucie et al. 2011 age group and sex it picks, and the AAOS values wherever the study gives no
// value (abduction and rotation always; every angle for an age outside 2-69, an unknown sex or
// birth date, or a group without values). The table here is the tests' own: each value encodes
// its motion, group and sex, so the value picked says which row it came from.
#include <gtest/gtest.h>

#include <vector>

#include "core/metrics/PatientNorms.h"

namespace armtrack {
namespace {

constexpr SoucieMotion kMotions[] = {SoucieMotion::ShoulderFlexion, SoucieMotion::ElbowFlexion,
                                     SoucieMotion::ElbowExtension, SoucieMotion::ForearmPronation,
                                     SoucieMotion::ForearmSupination};

/// 100 + 10 * motion + 2 * group + (male ? 1 : 0) degrees: unique per row.
double code(SoucieMotion m, int group, Sex sex) {
  return 100.0 + 10.0 * static_cast<int>(m) + 2.0 * group + (sex == Sex::Male ? 1.0 : 0.0);
}

std::vector<SoucieValue> fullTable() {
  std::vector<SoucieValue> t;
  for (const SoucieMotion m : kMotions)
    for (int g = 0; g < 4; ++g)
      for (const Sex s : {Sex::Female, Sex::Male}) {
        const double v = code(m, g, s);
        t.push_back({m, g, s, v, v - 1.5, v + 1.5});
      }
  return t;
}

double deg(double rad) {
  return rad * kRadToDeg;
}

/// Every limit the study covers came from row (group, sex); the others are AAOS.
void expectRow(const PatientNorms& n, int group, Sex sex) {
  const auto& aaos = aaosNormativeRanges();
  EXPECT_EQ(n.fallback, NormFallback::None);
  ASSERT_EQ(n.ageGroup, group);
  EXPECT_NEAR(deg(n.ranges[0].maxRad), code(SoucieMotion::ShoulderFlexion, group, sex), 1e-9);
  EXPECT_EQ(n.ranges[0].maxSource, NormSource::Soucie2011);
  EXPECT_NEAR(deg(*n.ranges[0].minRad), -60, 1e-9);  // extension: not in the study
  EXPECT_EQ(n.ranges[0].minSource, NormSource::Aaos);
  EXPECT_NEAR(deg(n.ranges[3].maxRad), code(SoucieMotion::ElbowFlexion, group, sex), 1e-9);
  // Hyperextension past straight is negative elbow flexion.
  EXPECT_NEAR(deg(*n.ranges[3].minRad), -code(SoucieMotion::ElbowExtension, group, sex), 1e-9);
  EXPECT_NEAR(deg(n.ranges[4].maxRad), code(SoucieMotion::ForearmPronation, group, sex), 1e-9);
  EXPECT_NEAR(deg(*n.ranges[4].minRad), -code(SoucieMotion::ForearmSupination, group, sex), 1e-9);
  for (int a : {3, 4}) {
    EXPECT_EQ(n.ranges[a].maxSource, NormSource::Soucie2011) << a;
    EXPECT_EQ(n.ranges[a].minSource, NormSource::Soucie2011) << a;
  }
  for (int a : {1, 2}) {  // abduction, rotation: never in the study
    EXPECT_EQ(n.ranges[a].maxSource, NormSource::Aaos) << a;
    EXPECT_EQ(n.ranges[a].minSource, NormSource::Aaos) << a;
    EXPECT_EQ(n.ranges[a].maxRad, aaos[a].maxRad) << a;
    EXPECT_EQ(n.ranges[a].minRad, aaos[a].minRad) << a;
  }
}

void expectAllAaos(const PatientNorms& n) {
  const auto& aaos = aaosNormativeRanges();
  EXPECT_FALSE(n.usesSoucie());
  for (int a = 0; a < kNumClinicalAngles; ++a) {
    EXPECT_EQ(n.ranges[a].maxSource, NormSource::Aaos) << a;
    EXPECT_EQ(n.ranges[a].minSource, NormSource::Aaos) << a;
    EXPECT_EQ(n.ranges[a].maxRad, aaos[a].maxRad) << a;
    EXPECT_EQ(n.ranges[a].minRad, aaos[a].minRad) << a;
  }
}

TEST(PatientNorms, ParsesDatesAndRefusesImpossibleOnes) {
  const auto d = parseIsoDate("1961-03-14");
  ASSERT_TRUE(d);
  EXPECT_EQ(d->year, 1961);
  EXPECT_EQ(d->month, 3);
  EXPECT_EQ(d->day, 14);
  const auto t = parseIsoDate("2026-11-20T09:15:00Z");
  ASSERT_TRUE(t);
  EXPECT_EQ(t->day, 20);
  EXPECT_TRUE(parseIsoDate("2024-02-29"));
  for (const char* bad :
       {"", "1961", "1961-3-14", "1961-13-01", "1961-00-10", "2023-02-29", "1900-02-29",
        "1961-04-31", "19a1-03-14", "1961-03-14x", "-961-03-14", "1961/03/14"})
    EXPECT_FALSE(parseIsoDate(bad)) << bad;
}

TEST(PatientNorms, AgeCountsCompletedYearsFromTheBirthday) {
  const CivilDate birth{1957, 6, 15};
  EXPECT_EQ(ageInYears(birth, {2026, 6, 14}), 68);
  EXPECT_EQ(ageInYears(birth, {2026, 6, 15}), 69);
  EXPECT_EQ(ageInYears(birth, {2026, 12, 31}), 69);
  EXPECT_EQ(ageInYears(birth, {1957, 6, 15}), 0);
  EXPECT_FALSE(ageInYears(birth, {1957, 6, 14}));  // before birth
  EXPECT_FALSE(ageInYears({1957, 2, 30}, {2026, 1, 1}));
  // Born on 29 February: the year is completed on 1 March in a common year.
  EXPECT_EQ(ageInYears({2004, 2, 29}, {2024, 2, 28}), 19);
  EXPECT_EQ(ageInYears({2004, 2, 29}, {2024, 2, 29}), 20);
  EXPECT_EQ(ageInYears({2004, 2, 29}, {2025, 2, 28}), 20);
  EXPECT_EQ(ageInYears({2004, 2, 29}, {2025, 3, 1}), 21);
}

TEST(PatientNorms, AgeGroupsAreTheStudysWithTheirBoundaries) {
  const std::pair<int, std::optional<int>> cases[] = {{0, std::nullopt},
                                                      {1, std::nullopt},
                                                      {2, 0},
                                                      {8, 0},
                                                      {9, 1},
                                                      {19, 1},
                                                      {20, 2},
                                                      {44, 2},
                                                      {45, 3},
                                                      {69, 3},
                                                      {70, std::nullopt},
                                                      {-3, std::nullopt}};
  for (const auto& [age, group] : cases) EXPECT_EQ(soucieAgeGroup(age), group) << age;
}

TEST(PatientNorms, SexCodesOfTheRecords) {
  EXPECT_EQ(sexFromCode("f"), Sex::Female);
  EXPECT_EQ(sexFromCode("F"), Sex::Female);
  EXPECT_EQ(sexFromCode("m"), Sex::Male);
  EXPECT_EQ(sexFromCode("x"), Sex::Unknown);
  EXPECT_EQ(sexFromCode(""), Sex::Unknown);
  EXPECT_EQ(sexFromCode("female"), Sex::Unknown);
}

// The row picked at each group's first and last day of age, for each sex, from the session's
// date: the day before a birthday still belongs to the younger group.
TEST(PatientNorms, PicksTheRowOfTheAgeOnTheSessionDayAndTheSex) {
  const std::vector<SoucieValue> table = fullTable();
  struct Case {
    CivilDate birth, session;
    int group;
  };
  const Case cases[] = {
      {{2020, 5, 10}, {2022, 5, 10}, 0},    // 2 on the day
      {{2017, 5, 10}, {2026, 5, 9}, 0},     // 8, a day short of 9
      {{2017, 5, 10}, {2026, 5, 10}, 1},    // 9
      {{2006, 11, 26}, {2026, 11, 25}, 1},  // 19
      {{2006, 11, 26}, {2026, 11, 26}, 2},  // 20
      {{1981, 1, 1}, {2025, 12, 31}, 2},    // 44
      {{1981, 1, 1}, {2026, 1, 1}, 3},      // 45
      {{1957, 6, 15}, {2027, 6, 14}, 3},    // 69
  };
  for (const Case& c : cases)
    for (const Sex sex : {Sex::Female, Sex::Male}) {
      SCOPED_TRACE(testing::Message() << c.birth.year << "-" << c.birth.month << "-" << c.birth.day
                                      << " on " << c.session.year << "-" << c.session.month << "-"
                                      << c.session.day << (sex == Sex::Male ? " male" : " female"));
      const PatientNorms n = patientNorms(c.birth, c.session, sex, table);
      EXPECT_EQ(n.sex, sex);
      expectRow(n, c.group, sex);
    }
}

TEST(PatientNorms, FallsBackToAaosWithTheReason) {
  const std::vector<SoucieValue> table = fullTable();
  const CivilDate day{2026, 11, 20};
  {
    const PatientNorms n = patientNorms(CivilDate{1956, 11, 20}, day, Sex::Female, table);  // 70
    expectAllAaos(n);
    EXPECT_EQ(n.ageYears, 70);
    EXPECT_FALSE(n.ageGroup);
    EXPECT_EQ(n.fallback, NormFallback::AgeOutsideStudy);
  }
  {
    const PatientNorms n = patientNorms(CivilDate{2025, 1, 1}, day, Sex::Male, table);  // 1
    expectAllAaos(n);
    EXPECT_EQ(n.fallback, NormFallback::AgeOutsideStudy);
  }
  {
    const PatientNorms n = patientNorms(CivilDate{1961, 3, 14}, day, Sex::Unknown, table);
    expectAllAaos(n);
    EXPECT_EQ(n.ageGroup, 3);
    EXPECT_EQ(n.fallback, NormFallback::SexUnknown);
  }
  for (const std::optional<CivilDate> birth :
       {std::optional<CivilDate>{}, std::optional<CivilDate>(CivilDate{2027, 1, 1})}) {
    const PatientNorms n = patientNorms(birth, day, Sex::Female, table);
    expectAllAaos(n);
    EXPECT_FALSE(n.ageYears);
    EXPECT_EQ(n.fallback, NormFallback::AgeUnknown);
  }
  {  // an unknown session date
    const PatientNorms n = patientNorms(CivilDate{1961, 3, 14}, CivilDate{}, Sex::Female, table);
    expectAllAaos(n);
    EXPECT_EQ(n.fallback, NormFallback::AgeUnknown);
  }
  {  // no values for this group and sex
    std::vector<SoucieValue> women;
    for (const SoucieValue& v : table)
      if (v.sex == Sex::Female) women.push_back(v);
    const PatientNorms n = patientNorms(CivilDate{1961, 3, 14}, day, Sex::Male, women);
    expectAllAaos(n);
    EXPECT_EQ(n.fallback, NormFallback::NoValues);
    expectRow(patientNorms(CivilDate{1961, 3, 14}, day, Sex::Female, women), 3, Sex::Female);
  }
}

// A table with only some motions of a group gives those limits and leaves the rest AAOS.
TEST(PatientNorms, APartialRowMixesSourcesLimitByLimit) {
  const std::vector<SoucieValue> table = {
      {SoucieMotion::ForearmSupination, 2, Sex::Male, 85, 83, 87}};
  const PatientNorms n = patientNorms(CivilDate{1990, 1, 1}, {2026, 1, 1}, Sex::Male, table);
  EXPECT_TRUE(n.usesSoucie());
  EXPECT_EQ(n.fallback, NormFallback::None);
  EXPECT_NEAR(deg(*n.ranges[4].minRad), -85, 1e-9);
  EXPECT_EQ(n.ranges[4].minSource, NormSource::Soucie2011);
  EXPECT_NEAR(deg(n.ranges[4].maxRad), 80, 1e-9);  // pronation: AAOS
  EXPECT_EQ(n.ranges[4].maxSource, NormSource::Aaos);
  for (int a : {0, 1, 2, 3}) EXPECT_EQ(n.ranges[a].maxSource, NormSource::Aaos) << a;
}

// What this version ships: every value it carries is a plausible range of its motion within its
// printed confidence interval, in a real group and for a real sex; with none carried, every
// patient gets the AAOS values and is told why.
TEST(PatientNorms, TheShippedValuesAreWellFormed) {
  const std::span<const SoucieValue> shipped = soucieReferenceValues();
  for (const SoucieValue& v : shipped) {
    EXPECT_GE(v.ageGroup, 0);
    EXPECT_LT(v.ageGroup, 4);
    EXPECT_NE(v.sex, Sex::Unknown);
    EXPECT_LE(v.ciLowDeg, v.meanDeg);
    EXPECT_GE(v.ciHighDeg, v.meanDeg);
    EXPECT_GE(v.meanDeg, -30);
    EXPECT_LE(v.meanDeg, 200);
  }
  const PatientNorms n = patientNorms(CivilDate{1961, 3, 14}, {2026, 11, 20}, Sex::Female);
  if (shipped.empty()) {
    expectAllAaos(n);
    EXPECT_EQ(n.fallback, NormFallback::NoValues);
  }
  EXPECT_NE(normSourceCitation(NormSource::Soucie2011).find("10.1111/j.1365-2516.2010.02399.x"),
            std::string_view::npos);
  EXPECT_NE(normSourceCitation(NormSource::Soucie2011).find("ncbddd/jointrom"),
            std::string_view::npos);
}

}  // namespace
}  // namespace armtrack
