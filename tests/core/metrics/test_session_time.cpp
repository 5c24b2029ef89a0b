// The definitions the screens and the reports share (core/metrics/SessionTime.h,
// NormativeRanges.h, Repetitions.h): recording time and event markers, the review's first
// converged sample, "% of normal", and the angle repetitions are counted on.
#include <gtest/gtest.h>

#include "core/metrics/NormativeRanges.h"
#include "core/metrics/PatientNorms.h"
#include "core/metrics/Repetitions.h"
#include "core/metrics/SessionTime.h"

namespace armtrack {
namespace {

TEST(PercentOfNormal, IsTheNamedMotionAgainstItsOwnNormal) {
  const auto& n = aaosNormativeRanges();
  // Shoulder flexion reaching 80 deg from 20 deg of extension: 80 of 180 = 44 %, not the
  // 100 deg range of motion over the 240 deg of flexion plus extension (42 %), nor 80 / 240.
  const auto p = percentOfNormal(n[0], -20 * kDegToRad, 80 * kDegToRad);
  ASSERT_TRUE(p);
  EXPECT_NEAR(*p, 100.0 * 80 / 180, 1e-9);
  EXPECT_EQ(std::lround(*p), 44);
  // The opposite direction against its own normal: 20 of 60 deg of extension.
  EXPECT_NEAR(*percentOfNormal(n[0], -20 * kDegToRad, 80 * kDegToRad, true), 100.0 * 20 / 60, 1e-9);
  // Never below neutral: 0 %; an unknown end: nothing.
  EXPECT_EQ(*percentOfNormal(n[2], -70 * kDegToRad, -20 * kDegToRad), 0.0);
  EXPECT_FALSE(percentOfNormal(n[0], std::nullopt, std::nullopt));
  EXPECT_FALSE(percentOfNormal(n[1], 0.1, 0.5, true)) << "adduction has no normal limit";
  EXPECT_FALSE(percentOfNormal(n[0], 0.0, std::numeric_limits<double>::quiet_NaN()));
}

TEST(PercentOfNormal, ForAPatientUsesTheirNormsOfTheDay) {
  // Without age or sex: AAOS, as above.
  EXPECT_NEAR(*sessionPercentOfNormal(std::nullopt, Sex::Unknown, CivilDate{2026, 11, 20}, 0, 0.0,
                                      80 * kDegToRad),
              100.0 * 80 / 180, 1e-9);
  // A woman of 65: the study's shoulder flexion for her group, not AAOS.
  const PatientNorms norms =
      patientNorms(CivilDate{1961, 3, 14}, CivilDate{2026, 11, 20}, Sex::Female);
  const double limit = norms.ranges[0].maxRad;
  EXPECT_NEAR(*sessionPercentOfNormal(CivilDate{1961, 3, 14}, Sex::Female, CivilDate{2026, 11, 20},
                                      0, 0.0, 80 * kDegToRad),
              100.0 * 80 * kDegToRad / limit, 1e-9);
  EXPECT_FALSE(sessionPercentOfNormal(std::nullopt, Sex::Unknown, std::nullopt, 7, 0.0, 1.0));
}

TEST(RecordingTime, EventsRoundTripAndOlderNotesConvert) {
  EXPECT_EQ(eventLine({15.44, "Pain"}), "[0:15.4] Pain");
  EXPECT_EQ(eventLine({75.0, "Rest"}), "[1:15.0] Rest");
  EXPECT_EQ(eventLine({-2.0, "Early"}), "[-0:02.0] Early");
  const std::string notes = "Patient tired.\n" + eventLine({15.4, "Pain"}) + "\n" +
                            eventLine({75.0, "Rest\nnow"}) + "\n[x] not an event";
  const std::vector<EventMark> e = parseEventMarks(notes, 13.0);
  ASSERT_EQ(e.size(), 2u);
  EXPECT_NEAR(e[0].recordingS, 15.4, 1e-9);
  EXPECT_EQ(e[0].label, "Pain");
  EXPECT_NEAR(e[1].recordingS, 75.0, 1e-9);
  EXPECT_EQ(e[1].label, "Rest now");
  // The live screen's older line, on the session clock: 28.4 s with the first row at 14.0 s is
  // 14.4 s of recording time.
  const std::vector<EventMark> old = parseEventMarks("Events: 28.4 s: Pain; 30.0 s: Fatigue", 14.0);
  ASSERT_EQ(old.size(), 2u);
  EXPECT_NEAR(old[0].recordingS, 14.4, 1e-9);
  EXPECT_EQ(old[0].label, "Pain");
  EXPECT_NEAR(old[1].recordingS, 16.0, 1e-9);
  EXPECT_EQ(old[1].label, "Fatigue");
  EXPECT_EQ(notesWithoutEvents(notes), "Patient tired.\n[x] not an event");
  EXPECT_EQ(notesWithoutEvents("Events: 28.4 s: Pain\nKeep going."), "Keep going.");
  // Garbage: nothing, no throw.
  EXPECT_TRUE(parseEventMarks("", 0).empty());
  EXPECT_TRUE(parseEventMarks("Events: soon; later", 0).empty());
  EXPECT_TRUE(parseEventMarks(std::string(10000, '['), 0).empty());
}

TEST(RecordingTime, TheReviewOpensAfterTheStartUpSecond) {
  std::vector<double> t;
  for (int i = 0; i < 500; ++i) t.push_back(13.0 + i * 0.01);
  EXPECT_DOUBLE_EQ(firstConvergedTime(t, 1.0), t[100]);
  EXPECT_DOUBLE_EQ(firstConvergedTime({13.0, 13.5}, 1.0), 13.0) << "shorter than start-up";
  EXPECT_DOUBLE_EQ(firstConvergedTime({}, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(recordingTime(28.4, 13.0), 28.4 - 13.0);
}

TEST(RepetitionAngle, TheProtocolsElseShoulderFlexion) {
  EXPECT_EQ(repetitionAngle(4), 4);
  EXPECT_EQ(repetitionAngle(std::nullopt), 0);
  EXPECT_EQ(repetitionAngle(-1), 0);
  EXPECT_EQ(repetitionAngle(9), 0);
}

}  // namespace
}  // namespace armtrack
