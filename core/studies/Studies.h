// The paper's simulation studies (section 3), reproduced: Table 6 (body-acceleration
// compensation, Methods A/B/C) and Fig. 5 (error against motion frequency per measurement model).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/estimation/ArmFilter.h"

namespace armtrack {

/// Called after each finished run with (done, total), for progress display. May be empty.
using StudyProgress = std::function<void(int done, int total)>;

/// Mean and standard deviation over runs (deg).
struct Stat {
  double mean = 0.0;
  double std = 0.0;
};

struct Table6Row {
  MeasurementModel method;
  Stat rmse;                                                ///< deg
  Stat peak;                                                ///< deg
  double paperRmse, paperRmseStd, paperPeak, paperPeakStd;  ///< the paper's Table 6 (deg)
};

struct StudySetup {
  int runs = 10;
  double duration = 10.0;      ///< s per run; errors count after the first second
  double amplitudeDeg = 90.0;  ///< th0 sinusoid amplitude
  FilterKind filter = FilterKind::Ekf;
};

/// One segment (shoulder and upper arm, one IMU near the elbow), th0 = 90 deg sin(2 pi 1 Hz t),
/// Table 5 noise, seeds 1..runs.
std::vector<Table6Row> runTable6(const StudySetup& setup, const StudyProgress& progress = {});
std::string formatTable6(const std::vector<Table6Row>& rows, const StudySetup& setup);

struct Fig5Point {
  double frequencyHz;
  MeasurementModel model;  ///< Inclinometer, InclinometerGyro or AccelGyro
  FilterKind filter;
  Stat rmse;  ///< deg
};

/// The IMU at the shoulder's centre of rotation (no body acceleration), th0 sinusoid of 90 deg
/// at 0 to 2.5 Hz in steps of 0.25 Hz, three measurement models, EKF and UKF.
std::vector<Fig5Point> runFig5(const StudySetup& setup, const StudyProgress& progress = {});
std::string formatFig5(const std::vector<Fig5Point>& points, const StudySetup& setup);

}  // namespace armtrack
