// A batch fit of the arm's motion over a short window of samples: the start (or restart) of the
// joint-angle filter in the middle of a movement, and its recovery when it has lost the arm.
// A single sample cannot tell gravity from body acceleration while the arm moves; a fraction of
// a second of gyroscope, accelerometer and optical data explained by one smooth motion can.
// See docs/estimator.md, "Start-up and recovery".
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/ArmSample.h"
#include "core/camera/CameraParams.h"
#include "core/estimation/ArmFilter.h"
#include "core/kinematics/ArmModel.h"

namespace armtrack {

/// The fitted motion at the window's last sample.
struct WindowFitResult {
  bool ok = false;                                       ///< the solver converged from some seed
  Eigen::Matrix<double, 15, 1> x = decltype(x)::Zero();  ///< [th'' th' th] at tEnd
  double tEnd = 0.0;                                     ///< s
  /// Root mean square of the whitened residuals of the samples the motion explains (1 when it
  /// explains them to within the sensors' stated noise; large when it does not). Samples whose
  /// residual is beyond 5 sigma per row on average are outliers: counted, not averaged in.
  double rms = 0.0;
  int residuals = 0;       ///< number of residual rows used
  int samples = 0;         ///< residual blocks (IMU samples and optical frames) in the fit
  int outlierSamples = 0;  ///< of which outliers
  /// Whether the fit explains the window: an RMS below `goodRms` with at most a fifth of the
  /// samples outliers.
  bool explains(double goodRms) const {
    return ok && rms < goodRms && 5 * outlierSamples <= samples;
  }
};

/// Frame 0 at one sample of a window, when the trunk moves (docs/estimator.md, "Trunk"): its
/// motion, which enters every IMU reading (gravity's direction among it), and the camera as seen
/// from it. A window without frames is one of a still trunk: gravity params.gUp, params.camera.
struct WindowFrame {
  FrameState<double> base;
  std::optional<CameraParams> camera;
};

/// Fits th(t) as a cubic per active joint over `window` (time-ordered samples already in the
/// filter's right-arm frame, implausible blocks removed) to every IMU and optical reading in it,
/// through the filter's own measurement model (params.model, params.camera), with a robust loss
/// against outliers. Each seed is a 15-state [th'' th' th] at the window's last sample; the fit
/// from the seed with the lowest cost is returned. Inactive joints stay at params.fixedAngles.
/// IMU samples are thinned to at most maxImuSamples, spread evenly. The heading about the
/// vertical is not observable without optical data and stays near the seed's.
/// With headingAnchor (angles, rad), the heading of the fitted angles at the window's end is held
/// at the anchor's (a residual of 0.5 deg along the heading direction at the anchor): for windows
/// without optical data, where nothing else fixes it.
/// With frames (frames[i] belongs to window[i]), each sample is predicted from frame 0 as it was
/// then: a moving trunk's rates, the shoulder's acceleration and the tilted gravity.
WindowFitResult fitWindow(const EstimatorParams& params, const std::vector<ArmSample>& window,
                          const std::vector<Eigen::Matrix<double, 15, 1>>& seeds,
                          const std::optional<JointVector>& headingAnchor = std::nullopt,
                          int maxImuSamples = 60, const std::vector<WindowFrame>* frames = nullptr);

/// Whitened residual RMS of a filter's own states over the window (states[i] belongs to
/// window[i]), without a robust loss: how well the running filter explains the same data.
double trajectoryRms(const EstimatorParams& params, const std::vector<ArmSample>& window,
                     const std::vector<Eigen::Matrix<double, 15, 1>>& states,
                     const std::vector<WindowFrame>* frames = nullptr);

}  // namespace armtrack
