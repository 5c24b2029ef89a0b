// The filter's measurement vector: the six 3-row blocks of eq. 16 (gyroscope and accelerometer
// of each IMU, elbow and wrist positions) and the webcam's 2-row marker pixels, the list of
// blocks one update fuses, and the predicted readings at a state. Private to the estimator
// (ArmFilter*.cpp).
#pragma once

#include <Eigen/Core>
#include <array>
#include <unsupported/Eigen/AutoDiff>

#include "core/camera/PinholeCamera.h"
#include "core/estimation/ArmFilter.h"

namespace armtrack::detail {

inline constexpr int kBase = 15;
inline constexpr int kModelRows = 18;            // the six 3-row blocks of eq. 16
inline constexpr int kMaxRows = kModelRows + 4;  // plus two 2-row marker pixels
using Vec15 = Eigen::Matrix<double, kBase, 1>;
using AD = Eigen::AutoDiffScalar<Vec15>;

// Measurement blocks in the order of eq. 16 (gyros and accelerometers per IMU, then optics),
// then the webcam's marker pixels.
enum Block { kUaGyr = 0, kUaAcc, kFaGyr, kFaAcc, kElbow, kWrist, kCamWrist, kCamElbow, kNumBlocks };

inline constexpr bool isCamera(int b) {
  return b == kCamWrist || b == kCamElbow;
}
inline constexpr bool isOptical(int b) {
  return b == kElbow || b == kWrist || isCamera(b);
}

// The blocks present in one update: 3 rows for IMU and Kinect blocks, 2 for marker pixels.
struct BlockList {
  std::array<int, kNumBlocks> block{};
  std::array<int, kNumBlocks> offset{};
  std::array<int, kNumBlocks> size{};
  int count = 0;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1> z;
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxRows, 1> variance;  // diagonal of R
  int rows() const { return static_cast<int>(z.size()); }
  template <int M>
  void add(int b, const Eigen::Matrix<double, M, 1>& value, double var) {
    const auto n = z.size();
    block[count] = b;
    offset[count] = static_cast<int>(n);
    size[count++] = M;
    z.conservativeResize(n + M);
    variance.conservativeResize(n + M);
    z.template segment<M>(n) = value;
    variance.template segment<M>(n).setConstant(var);
  }
  bool has(int b) const {
    for (int i = 0; i < count; ++i)
      if (block[i] == b) return true;
    return false;
  }
  bool anyOptical() const {
    for (int i = 0; i < count; ++i)
      if (isOptical(block[i])) return true;
    return false;
  }
  // A copy without block i.
  BlockList without(int i) const {
    BlockList out;
    for (int k = 0; k < count; ++k) {
      if (k == i) continue;
      if (size[k] == 3)
        out.add<3>(block[k], z.segment<3>(offset[k]), variance(offset[k]));
      else
        out.add<2>(block[k], z.segment<2>(offset[k]), variance(offset[k]));
    }
    return out;
  }
};

// A marker's pixel from its predicted position p (right-arm frame) and dp/dx: the camera sees the
// real arm, which for a left arm is the mirror image of the one the filter works on.
inline bool markerPixel(const PinholeCamera& camera, bool left, const Eigen::Vector3d& p,
                        const Eigen::Matrix<double, 3, kBase>* dp, Eigen::Vector2d& pixel,
                        Eigen::Matrix<double, 2, kBase>* jac) {
  const Eigen::Vector3d real = left ? mirrorPoint(p) : p;
  if (!jac) return camera.project(real, pixel);
  Eigen::Matrix<double, 2, 3> dPixel;
  if (!camera.project(real, pixel, dPixel)) return false;
  if (left) dPixel.col(2) = -dPixel.col(2);
  *jac = dPixel * *dp;
  return true;
}

// Predicted readings of all six blocks for the 15-state base, templated for AutoDiff.
// base: frame 0's motion (a still trunk when null: gravity p.gUp alone).
template <typename T>
void predictBase(const EstimatorParams& p, const Eigen::Matrix<T, kBase, 1>& x,
                 Eigen::Matrix<T, kModelRows, 1>& out, const FrameState<double>* base = nullptr) {
  const Eigen::Matrix<T, 5, 1> thdd = x.template segment<5>(0);
  const Eigen::Matrix<T, 5, 1> thd = x.template segment<5>(5);
  const Eigen::Matrix<T, 5, 1> th = x.template segment<5>(10);
  const ArmKinematics<T> k = base ? armKinematics<T>(p.geometry, th, thd, thdd, *base)
                                  : armKinematics<T>(p.geometry, th, thd, thdd, p.gUp);
  const bool bodyAccel = p.model == MeasurementModel::AccelGyro;
  out.template segment<3>(0) = k.upperImu.omega;
  out.template segment<3>(3) =
      bodyAccel ? Eigen::Matrix<T, 3, 1>(k.upperImu.up + k.upperImu.accel) : k.upperImu.up;
  out.template segment<3>(6) = k.forearmImu.omega;
  out.template segment<3>(9) =
      bodyAccel ? Eigen::Matrix<T, 3, 1>(k.forearmImu.up + k.forearmImu.accel) : k.forearmImu.up;
  out.template segment<3>(12) = k.elbow;
  out.template segment<3>(15) = k.wrist;
}

inline void predictBaseWithJacobian(const EstimatorParams& p, const Vec15& x,
                                    Eigen::Matrix<double, kModelRows, 1>& h,
                                    Eigen::Matrix<double, kModelRows, kBase>& jac,
                                    const FrameState<double>* base = nullptr) {
  Eigen::Matrix<AD, kBase, 1> xa;
  for (int i = 0; i < kBase; ++i) xa(i) = AD(x(i), kBase, i);
  Eigen::Matrix<AD, kModelRows, 1> out;
  predictBase<AD>(p, xa, out, base);
  for (int i = 0; i < kModelRows; ++i) {
    h(i) = out(i).value();
    jac.row(i) = out(i).derivatives().transpose();
  }
}

}  // namespace armtrack::detail
