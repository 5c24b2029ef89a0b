// Sensor faults found by hostile testing (issue 9): one absurd but finite row, a 200 ms burst of
// saturated readings, 200 ms of all-zero rows and a 5 s gap, in the middle of a five-joint
// movement with a Kinect, default settings. The estimator must keep giving an estimate on every
// row that carries IMU data (predicting through refused readings, restarting after the gap), say
// what it refused, and be back under 1 deg RMSE within 2 s of the fault's end. The truth is the
// simulation's.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "core/estimation/ArmFilter.h"
#include "core/metrics/Accuracy.h"
#include "core/simulation/SensorSimulator.h"
#include "core/simulation/Trajectory.h"

namespace armtrack {
namespace {

enum class Fault { Spike, SaturatedBurst, ZeroBurst, Gap };

struct Case {
  Fault fault;
  FilterKind filter;
  std::uint64_t seed;
};

std::string caseName(const testing::TestParamInfo<Case>& info) {
  static const char* kFault[] = {"Spike", "SaturatedBurst", "ZeroBurst", "Gap"};
  return std::string(kFault[static_cast<int>(info.param.fault)]) +
         (info.param.filter == FilterKind::Ekf ? "Ekf" : "Ukf") + "Seed" +
         std::to_string(info.param.seed);
}

constexpr double kFaultStart = 6.0;

// The fault applied to a clean recording; returns the time it ends.
double inject(Fault fault, std::vector<ArmSample>& samples) {
  std::vector<ArmSample> out;
  double end = kFaultStart;
  bool spiked = false;
  for (ArmSample s : samples) {
    const bool burst = s.t >= kFaultStart && s.t < kFaultStart + 0.2;
    switch (fault) {
      case Fault::Spike:
        if (!spiked && s.t >= kFaultStart && s.upperArm) {
          s.upperArm->gyr << 1e6, -6e36, 3e20;
          s.upperArm->acc << 2e7, 1e6, -1e6;
          spiked = true;
          end = s.t;
        }
        break;
      case Fault::SaturatedBurst:
        end = kFaultStart + 0.2;
        if (burst) {
          for (std::optional<ImuReading>* r : {&s.upperArm, &s.forearm}) {
            if (!*r) continue;
            (*r)->gyr.setConstant(2000.0 * kDeg);
            (*r)->acc.setConstant(16.0 * 9.80665);
          }
        }
        break;
      case Fault::ZeroBurst:
        end = kFaultStart + 0.2;
        if (burst) {  // every column of the row zero, optics included
          for (std::optional<ImuReading>* r : {&s.upperArm, &s.forearm})
            if (*r) (*r)->gyr.setZero(), (*r)->acc.setZero();
          if (s.elbow) s.elbow->setZero();
          if (s.wrist) s.wrist->setZero();
        }
        break;
      case Fault::Gap:
        end = kFaultStart + 5.0;
        if (s.t >= kFaultStart && s.t < end) continue;
        break;
    }
    out.push_back(s);
  }
  samples = out;
  return end;
}

class SensorFault : public testing::TestWithParam<Case> {};

TEST_P(SensorFault, KeepsEstimatingReportsAndRecoversWithinTwoSeconds) {
  const Case c = GetParam();
  SimulationParams sp = defaultSimulation();
  sp.duration = 16.0;
  sp.seed = c.seed;
  const MultiJointTrajectory traj(c.seed);
  std::vector<ArmSample> samples = simulateRecording(traj, sp).samples;
  const double end = inject(c.fault, samples);

  EstimatorParams p;  // defaults: nothing tuned for this test
  p.filter = c.filter;
  auto f = makeEstimator(p);
  std::size_t imuRows = 0, estimated = 0, predicted = 0;
  ErrorAccumulator recovered;
  for (const ArmSample& s : samples) {
    const UpdateResult r = f->update(s);
    if (s.hasImu()) {
      ++imuRows;
      estimated += hasEstimate(r);
      predicted += r == UpdateResult::Predicted;
    }
    if (hasEstimate(r)) {
      const JointEstimate e = f->estimate();
      ASSERT_TRUE(e.th.allFinite() && e.thStd.allFinite()) << "t = " << s.t;
    }
    if (s.trueAngles && f->initialised() && s.t >= end + 2.0) recovered.add(f->estimate().th, *s.trueAngles);
  }
  const EstimatorCounters& k = f->counters();
  const JointVector rmse = recovered.rmse() / kDeg;
  std::printf("[ measured ] RMSE from 2 s after the fault (deg): %s; refused %llu, predicted %zu, "
              "restarts %llu\n",
              [&] {
                std::string s;
                for (int j = 0; j < kNumJoints; ++j) s += std::to_string(rmse(j)) + " ";
                return s;
              }()
                  .c_str(),
              static_cast<unsigned long long>(k.implausible.total()), predicted,
              static_cast<unsigned long long>(k.restarts));

  EXPECT_EQ(estimated, imuRows) << "every row with IMU data gets an estimate";
  EXPECT_GT(recovered.count(), 1000u);
  for (int j = 0; j < kNumJoints; ++j) EXPECT_LT(rmse(j), 1.0) << "joint " << j;
  switch (c.fault) {
    case Fault::Spike:
      EXPECT_EQ(k.implausible.byReason(Implausible::BeyondRange), 1u);
      EXPECT_EQ(k.implausible.byBlock(SensorBlock::UpperArm), 1u);
      EXPECT_NEAR(k.implausible.firstT, end, 1e-12);
      EXPECT_EQ(k.restarts, 0u);
      break;
    case Fault::SaturatedBurst:
      // Both IMUs at 1 kHz for 200 ms.
      EXPECT_NEAR(double(k.implausible.byReason(Implausible::Saturated)), 400.0, 2.0);
      EXPECT_EQ(k.implausible.total(), k.implausible.byReason(Implausible::Saturated));
      EXPECT_GE(k.implausible.firstT, kFaultStart);
      EXPECT_LT(k.implausible.lastT, end);
      break;
    case Fault::ZeroBurst:
      EXPECT_NEAR(double(k.implausible.byBlock(SensorBlock::UpperArm)), 200.0, 1.0);
      EXPECT_NEAR(double(k.implausible.byBlock(SensorBlock::Forearm)), 200.0, 1.0);
      EXPECT_NEAR(double(k.implausible.byBlock(SensorBlock::Elbow)), 6.0, 1.0);  // Kinect 30 Hz
      EXPECT_EQ(k.implausible.total(), k.implausible.byReason(Implausible::AllZero));
      break;
    case Fault::Gap:
      EXPECT_EQ(k.implausible.total(), 0u);
      EXPECT_EQ(k.restarts, 1u);
      break;
  }
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (Fault fault : {Fault::Spike, Fault::SaturatedBurst, Fault::ZeroBurst, Fault::Gap})
    for (FilterKind filter : {FilterKind::Ekf, FilterKind::Ukf})
      out.push_back({fault, filter, 31 + static_cast<std::uint64_t>(fault)});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Faults, SensorFault, testing::ValuesIn(cases()), caseName);

}  // namespace
}  // namespace armtrack
