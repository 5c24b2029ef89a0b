#include "core/estimation/Initializer.h"

#include <optional>
#include <unsupported/Eigen/AutoDiff>
#include <unsupported/Eigen/LevenbergMarquardt>
#include <vector>

#include "core/camera/PinholeCamera.h"

namespace armtrack {
namespace {

constexpr double kPositionScale = 0.05;  // m of optical error worth one unit of residual
constexpr double kPriorWeight = 0.05;    // per rad away from the neutral posture

// How much an accelerometer's direction says about gravity: a reading far from g in size carries
// body acceleration (the arm is moving), so it counts less; optical positions then lead.
double gravityWeight(const Eigen::Vector3d& acc, double g) {
  const double dev = (acc.norm() - g) / (0.1 * g);
  return std::max(0.2, 1.0 / (1.0 + dev * dev));
}

// Residuals over the active joints: gravity direction per IMU, optical positions, prior.
struct PoseResidual {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  using QRSolver = Eigen::ColPivHouseholderQR<JacobianType>;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const EstimatorParams* params;
  const ArmSample* sample;
  std::vector<int> active;
  int nValues = 0;
  // Rays back-projected from the marker pixels (right-arm frame): a marker lies on its ray.
  struct Ray {
    Eigen::Vector3d origin, direction;
  };
  std::optional<Ray> wristRay, elbowRay;

  int inputs() const { return static_cast<int>(active.size()); }
  int values() const { return nValues; }

  // th: all five joints (inactive ones at their fixed value).
  template <typename T>
  void residual(const Eigen::Matrix<T, 5, 1>& th, Eigen::Matrix<T, Eigen::Dynamic, 1>& r) const {
    const Eigen::Matrix<T, 5, 1> zero = Eigen::Matrix<T, 5, 1>::Constant(T(0));
    const Eigen::Vector3d up = params->gUp.normalized();
    const ArmKinematics<T> k = armKinematics<T>(params->geometry, th, zero, zero, up);
    r.resize(nValues);
    int row = 0;
    auto put = [&](const Eigen::Matrix<T, 3, 1>& v) {
      r.template segment<3>(row) = v;
      row += 3;
    };
    const double g = params->gUp.norm();
    if (sample->upperArm)
      put((sample->upperArm->acc.normalized().cast<T>() - k.upperImu.up) *
          T(gravityWeight(sample->upperArm->acc, g)));
    if (sample->forearm)
      put((sample->forearm->acc.normalized().cast<T>() - k.forearmImu.up) *
          T(gravityWeight(sample->forearm->acc, g)));
    if (sample->elbow) put((sample->elbow->cast<T>() - k.elbow) / T(kPositionScale));
    if (sample->wrist) put((sample->wrist->cast<T>() - k.wrist) / T(kPositionScale));
    // Distance of a marker from its ray (the part of p - origin across the ray).
    auto offRay = [&](const Ray& ray, const Eigen::Matrix<T, 3, 1>& p) {
      const Eigen::Matrix<T, 3, 1> d = p - ray.origin.cast<T>();
      const Eigen::Matrix<T, 3, 1> u = ray.direction.cast<T>();
      put((d - u * u.dot(d)) / T(kPositionScale));
    };
    if (wristRay) offRay(*wristRay, k.wrist);
    if (elbowRay) offRay(*elbowRay, k.elbow);
    const JointVector prior = neutralPosture();
    for (int j : active) r(row++) = (th(j) - T(prior(j))) * T(kPriorWeight);
  }

  JointVector expand(const Eigen::VectorXd& x) const {
    JointVector th = params->fixedAngles;
    for (std::size_t i = 0; i < active.size(); ++i) th(active[i]) = x(static_cast<Eigen::Index>(i));
    return th;
  }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    residual<double>(expand(x), r);
    return 0;
  }

  // Fixed-size derivatives over all five joints; the active ones become the Jacobian's columns.
  int df(const Eigen::VectorXd& x, Eigen::MatrixXd& jac) const {
    using AD = Eigen::AutoDiffScalar<JointVector>;
    const JointVector th = expand(x);
    Eigen::Matrix<AD, 5, 1> tha;
    for (int j = 0; j < kNumJoints; ++j) tha(j) = AD(th(j), kNumJoints, j);
    Eigen::Matrix<AD, Eigen::Dynamic, 1> r;
    residual<AD>(tha, r);
    jac.resize(nValues, inputs());
    for (int i = 0; i < nValues; ++i)
      for (int c = 0; c < inputs(); ++c) jac(i, c) = r(i).derivatives()(active[c]);
    return 0;
  }
};

}  // namespace

JointVector neutralPosture() {
  JointVector th;
  th << 0.0, 0.0, 0.0, -20.0 * kDeg, 0.0;
  return th;
}

InitialPose initialPose(const EstimatorParams& params, const ArmSample& sample) {
  PoseResidual f;
  f.params = &params;
  f.sample = &sample;
  for (int j = 0; j < kNumJoints; ++j)
    if (params.activeJoints[j]) f.active.push_back(j);
  const int n = static_cast<int>(f.active.size());
  if (params.camera && params.useCamera) {
    const PinholeCamera camera(*params.camera);
    const bool left = params.side == Side::Left;
    auto rayOf = [&](const Eigen::Vector2d& px) {
      PoseResidual::Ray r;
      camera.ray(px, r.origin, r.direction);
      if (left) {  // the filter's arm is the mirror image of the one the camera sees
        r.origin = mirrorPoint(r.origin);
        r.direction = mirrorPoint(r.direction);
      }
      return r;
    };
    if (sample.camWrist && sample.camWrist->allFinite()) f.wristRay = rayOf(*sample.camWrist);
    if (sample.camElbow && sample.camElbow->allFinite()) f.elbowRay = rayOf(*sample.camElbow);
  }
  f.nValues = 3 * (int(sample.upperArm.has_value()) + int(sample.forearm.has_value()) +
                   int(sample.elbow.has_value()) + int(sample.wrist.has_value()) +
                   int(f.wristRay.has_value()) + int(f.elbowRay.has_value())) +
              n;

  InitialPose best;
  best.th = params.fixedAngles;
  best.cost = std::numeric_limits<double>::infinity();
  if (n == 0) return best;

  // A coarse set of starts covering the workspace; LM refines each, the lowest cost wins.
  const std::array<std::vector<double>, kNumJoints> starts{
      std::vector<double>{-60 * kDeg, 0.0, 60 * kDeg, 120 * kDeg},
      std::vector<double>{0.0, 60 * kDeg}, std::vector<double>{-60 * kDeg, 30 * kDeg},
      std::vector<double>{-100 * kDeg, -20 * kDeg}, std::vector<double>{-60 * kDeg, 60 * kDeg}};
  std::vector<std::size_t> idx(n, 0);
  for (;;) {
    Eigen::VectorXd x(n);
    for (int i = 0; i < n; ++i) x(i) = starts[f.active[i]][idx[i]];
    Eigen::LevenbergMarquardt<PoseResidual> lm(f);
    lm.setMaxfev(200);
    lm.minimize(x);
    Eigen::VectorXd r;
    f(x, r);
    const double cost = 0.5 * r.squaredNorm();
    if (cost < best.cost) {
      best.cost = cost;
      for (int i = 0; i < n; ++i) best.th(f.active[i]) = wrapAngle(x(i));
    }
    int k = 0;
    while (k < n && ++idx[k] == starts[f.active[k]].size()) idx[k++] = 0;
    if (k == n) break;
  }

  // Joint rates: the gyroscopes are linear in th' for a given th.
  Eigen::Matrix<double, 15, 1> x = Eigen::Matrix<double, 15, 1>::Zero();
  x.segment<5>(10) = best.th;
  const Eigen::Matrix<double, 18, 15> jac = predictAllJacobian(params, x);
  Eigen::Matrix<double, Eigen::Dynamic, 5, 0, 6, 5> a(0, 5);
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1> b(0);
  auto addGyro = [&](int row, const Eigen::Vector3d& w) {
    const auto n0 = a.rows();
    a.conservativeResize(n0 + 3, 5);
    b.conservativeResize(n0 + 3);
    a.middleRows<3>(n0) = jac.block<3, 5>(row, 5);
    b.segment<3>(n0) = w;
  };
  if (params.model != MeasurementModel::Inclinometer) {
    if (sample.upperArm) addGyro(0, sample.upperArm->gyr);
    if (sample.forearm) addGyro(6, sample.forearm->gyr);
  }
  if (a.rows() > 0) {
    for (int j = 0; j < kNumJoints; ++j)
      if (!params.activeJoints[j]) a.col(j).setZero();
    // Small damping keeps joints the gyroscopes cannot see (e.g. the heading) at rest.
    const Eigen::Matrix<double, 5, 5> normal =
        a.transpose() * a + 1e-3 * Eigen::Matrix<double, 5, 5>::Identity();
    best.thd = normal.ldlt().solve(a.transpose() * b);
  }
  return best;
}

}  // namespace armtrack
