// The baseline study (core/baseline/BaselineStudy.h), short: every case runs, both methods are
// scored on the same samples, and the DH filter follows a perfect-model pendulum whose hinge
// bends beyond the anatomical elbow limits, as the baseline does.
#include <gtest/gtest.h>

#include <string>

#include "core/baseline/BaselineStudy.h"

namespace armtrack {
namespace {

TEST(BaselineStudy, ScoresBothMethodsOnEveryCase) {
  BaselineStudySetup setup;
  setup.pendulumSeconds = 8.0;  // the DH filter recovers on the lively pendulum: room to settle
  setup.reachingSeconds = 3.0;
  setup.reachingRuns = 1;
  setup.zerosDeg = {0.0, 35.0};
  int calls = 0;
  const auto rows = runBaselineStudy(setup, [&](int done, int total) {
    ++calls;
    EXPECT_EQ(done, calls);
    EXPECT_EQ(total, 2 * 2 * 2 + 1);
  });
  EXPECT_EQ(calls, 9);
  // Per pendulum case: DH filter and baseline told where the sensor sits on the rod (+ both with
  // the model's mounting when the zero is not 0); two for reaching.
  ASSERT_EQ(rows.size(), 4u * 2 + 4u * 4 + 2);
  for (const BaselineStudyRow& r : rows) {
    EXPECT_GT(r.errors.hinge.count, 0u) << r.recording << " " << r.method;
    EXPECT_GT(r.errors.swing.count, 0u) << r.recording << " " << r.method;
  }
  // The lively pendulum at zero 0 with ideal sensors: its hinge passes the default elbow limits
  // (hyperextension to +81 deg), and the DH filter follows it as the baseline does.
  EXPECT_EQ(rows[0].method, "DH filter");
  EXPECT_LT(rows[0].errors.hinge.rmseDeg(), 0.5);
  EXPECT_EQ(rows[1].method, "baseline");
  EXPECT_LT(rows[1].errors.hinge.rmseDeg(), 0.5);
  EXPECT_GT(rows[0].trueHingeMaxDeg, 20.0);
  EXPECT_EQ(rows[4].method, "DH filter, model's mounting");
  const std::string text = formatBaselineStudy(rows, setup);
  EXPECT_NE(text.find("| pendulum 80/70, ideal, 1 kHz | 0 |"), std::string::npos) << text;
  EXPECT_NE(text.find("| reaching, Table 5, IMUs only | - | - | baseline |"), std::string::npos);
}

}  // namespace
}  // namespace armtrack
