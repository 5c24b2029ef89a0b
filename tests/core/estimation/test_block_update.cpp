// One block of the sequential Kalman update (core/estimation/BlockUpdate.h) against the textbook
// formulas written out with dense matrices: the optimal update P - K S K^T, the Joseph form for
// the heading-blind gain (I - v u^T) K, a Jacobian given by its nonzero columns against the full
// one, and a matrix that is not positive definite refused without touching P. Each with the
// plain kernels and with the AVX2/FMA ones (skipped where the processor has none), and the two
// kernels against each other.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/estimation/BlockUpdate.h"

namespace armtrack {
namespace {

constexpr int N = 15;
using Mat = Eigen::Matrix<double, N, N>;
using Vec = Eigen::Matrix<double, N, 1>;
using Mat3N = Eigen::Matrix<double, 3, N>;
using Vec3 = Eigen::Matrix<double, 3, 1>;

Mat randomCovariance(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Mat a;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) a(i, j) = g(rng);
  Mat p = a * a.transpose() / N + 0.1 * Mat::Identity();
  return 0.5 * (p + p.transpose());
}

template <int R, int C>
Eigen::Matrix<double, R, C> randomMatrix(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Eigen::Matrix<double, R, C> m;
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) m(i, j) = g(rng);
  return m;
}

// The reference: gain k (N x 3) applied to P with the Joseph form, the state moved by k r.
void josephReference(const Mat& p, const Mat3N& h, const Eigen::Matrix<double, N, 3>& k,
                     const Vec3& variance, Mat& pOut) {
  const Mat ikh = Mat::Identity() - k * h;
  pOut = ikh * p * ikh.transpose() + k * variance.asDiagonal() * k.transpose();
}

// The parameter: whether fuseBlock uses the AVX2/FMA kernels.
class BlockUpdate : public ::testing::TestWithParam<bool> {
 protected:
  void SetUp() override {
    if (GetParam() && !m_hasFma) GTEST_SKIP() << "this processor has no AVX2/FMA";
    detail::useFmaKernels() = GetParam();
  }
  void TearDown() override { detail::useFmaKernels() = m_hasFma; }

 private:
  const bool m_hasFma = detail::useFmaKernels();
};

INSTANTIATE_TEST_SUITE_P(Kernels, BlockUpdate, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& info) {
                           return info.param ? "Fma" : "Plain";
                         });

TEST_P(BlockUpdate, OptimalUpdateEqualsTheTextbookFormulas) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Mat p0 = randomCovariance(rng);
    const Mat3N h = randomMatrix<3, N>(rng);
    const Vec3 variance = Vec3(0.01, 0.2, 1.5);
    const Vec3 z = randomMatrix<3, 1>(rng);
    const Vec dx0 = 0.1 * randomMatrix<N, 1>(rng);

    Mat p = p0;
    Vec dx = dx0;
    double nis = -1.0;
    ASSERT_TRUE((fuseBlock<3, N, N>(h, 0, z, variance, nullptr, p, dx, nis)));

    const Eigen::Matrix3d s = h * p0 * h.transpose() + Eigen::Matrix3d(variance.asDiagonal());
    const Eigen::Matrix<double, N, 3> k = p0 * h.transpose() * s.inverse();
    const Vec3 r = z - h * dx0;
    Mat pRef;
    josephReference(p0, h, k, variance, pRef);
    EXPECT_LT((p - pRef).cwiseAbs().maxCoeff(), 1e-12 * p0.cwiseAbs().maxCoeff());
    EXPECT_LT((dx - (dx0 + k * r)).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(nis, r.dot(s.inverse() * r), 1e-12 * (1.0 + nis));
    EXPECT_EQ(p, p.transpose());  // exactly symmetric
  }
}

TEST_P(BlockUpdate, BlindDirectionFollowsTheJosephFormOfTheProjectedGain) {
  std::mt19937_64 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const Mat p0 = randomCovariance(rng);
    const Mat3N h = randomMatrix<3, N>(rng);
    const Vec3 variance = Vec3(0.05, 0.05, 0.05);
    const Vec3 z = randomMatrix<3, 1>(rng);
    // u among the last five states (the angles), v with u . v = 1 as the filter's are.
    Vec u = Vec::Zero();
    u.tail<5>() = randomMatrix<5, 1>(rng).normalized();
    Vec v = randomMatrix<N, 1>(rng);
    v += (1.0 - u.dot(v)) * u;
    ASSERT_NEAR(u.dot(v), 1.0, 1e-14);

    Mat p = p0;
    Vec dx = Vec::Zero();
    double nis = 0.0;
    const BlindDirection<N> blind{v, u};
    ASSERT_TRUE((fuseBlock<3, N, N>(h, 0, z, variance, &blind, p, dx, nis)));

    const Eigen::Matrix3d s = h * p0 * h.transpose() + Eigen::Matrix3d(variance.asDiagonal());
    const Eigen::Matrix<double, N, 3> k = p0 * h.transpose() * s.inverse();
    const Eigen::Matrix<double, N, 3> kb = (Mat::Identity() - v * u.transpose()) * k;
    Mat pRef;
    josephReference(p0, h, kb, variance, pRef);
    EXPECT_LT((p - pRef).cwiseAbs().maxCoeff(), 1e-11 * p0.cwiseAbs().maxCoeff());
    EXPECT_LT((dx - kb * z).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_NEAR(u.dot(dx), 0.0, 1e-12);  // the state does not move along v
    EXPECT_EQ(p, p.transpose());
    // The blind update keeps more variance than the optimal one, never less.
    Mat pOpt = p0;
    Vec dxOpt = Vec::Zero();
    ASSERT_TRUE((fuseBlock<3, N, N>(h, 0, z, variance, nullptr, pOpt, dxOpt, nis)));
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat>(p - pOpt).eigenvalues().minCoeff(), -1e-12);
  }
}

TEST_P(BlockUpdate, NonzeroColumnsGiveTheFullJacobiansUpdate) {
  std::mt19937_64 rng(13);
  const Mat p0 = randomCovariance(rng);
  const Eigen::Matrix<double, 2, 5> hAngles = randomMatrix<2, 5>(rng);
  Eigen::Matrix<double, 2, N> hFull = Eigen::Matrix<double, 2, N>::Zero();
  hFull.rightCols<5>() = hAngles;
  const Eigen::Vector2d z(0.3, -0.2), variance(1.0, 1.0);
  const Vec dx0 = 0.1 * randomMatrix<N, 1>(rng);
  Mat pa = p0, pb = p0;
  Vec da = dx0, db = dx0;
  double na = 0.0, nb = 0.0;
  ASSERT_TRUE((fuseBlock<2, 5, N>(hAngles, 10, z, variance, nullptr, pa, da, na)));
  ASSERT_TRUE((fuseBlock<2, N, N>(hFull, 0, z, variance, nullptr, pb, db, nb)));
  EXPECT_LT((pa - pb).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((da - db).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_NEAR(na, nb, 1e-14);
}

TEST_P(BlockUpdate, IndefiniteInnovationCovarianceIsRefusedAndChangesNothing) {
  std::mt19937_64 rng(17);
  const Mat p0 = -randomCovariance(rng);  // S = H P H^T + R negative definite for small R
  const Mat3N h = randomMatrix<3, N>(rng);
  Mat p = p0;
  Vec dx = Vec::Constant(0.5);
  double nis = 42.0;
  EXPECT_FALSE((fuseBlock<3, N, N>(h, 0, Vec3::Ones(), Vec3::Constant(1e-3), nullptr, p, dx, nis)));
  EXPECT_EQ(p, p0);
  EXPECT_EQ(dx, Vec::Constant(0.5));
}

// The AVX2/FMA kernels round each multiply-add once instead of twice; otherwise they sum in the
// same order, so they agree with the plain ones to round-off, and P stays exactly symmetric.
TEST(BlockUpdateKernels, FmaAndPlainKernelsAgreeToRoundOff) {
  const bool hasFma = detail::useFmaKernels();
  if (!hasFma) GTEST_SKIP() << "this processor has no AVX2/FMA";
  std::mt19937_64 rng(19);
  for (int trial = 0; trial < 50; ++trial) {
    const Mat p0 = randomCovariance(rng);
    const Mat3N h = randomMatrix<3, N>(rng);
    const Vec3 z = randomMatrix<3, 1>(rng), variance(0.02, 0.3, 0.7);
    Vec u = Vec::Zero();
    u.tail<5>() = randomMatrix<5, 1>(rng).normalized();
    Vec v = randomMatrix<N, 1>(rng);
    v += (1.0 - u.dot(v)) * u;
    const BlindDirection<N> blind{v, u};
    Mat p[2] = {p0, p0};
    Vec dx[2] = {Vec::Zero(), Vec::Zero()};
    double nis[2] = {0.0, 0.0};
    for (int k = 0; k < 2; ++k) {
      detail::useFmaKernels() = k == 1;
      ASSERT_TRUE((fuseBlock<3, N, N>(h, 0, z, variance, trial % 2 ? &blind : nullptr, p[k], dx[k],
                                      nis[k])));
      EXPECT_EQ(p[k], p[k].transpose());
    }
    detail::useFmaKernels() = hasFma;
    EXPECT_LT((p[1] - p[0]).cwiseAbs().maxCoeff(), 1e-14 * p0.cwiseAbs().maxCoeff());
    EXPECT_LT((dx[1] - dx[0]).cwiseAbs().maxCoeff(), 1e-14 * (1.0 + dx[0].cwiseAbs().maxCoeff()));
    EXPECT_NEAR(nis[1], nis[0], 1e-13 * (1.0 + nis[0]));
    // 3-row blocks over 15 columns: the tail columns (12-14) go through the scalar fused steps.
    EXPECT_NE(p[1], p[0]);
  }
}

}  // namespace
}  // namespace armtrack
