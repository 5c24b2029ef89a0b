// One block of the sequential Kalman update (core/estimation/BlockUpdate.h) against the textbook
// formulas written out with dense matrices: the optimal update P - K S K^T, the Joseph form for
// the heading-blind gain (I - v u^T) K, a Jacobian given by its nonzero columns against the full
// one, and a matrix that is not positive definite refused without touching P. Each with the
// plain kernels and with the AVX2/FMA ones (skipped where the processor has none), and the two
// kernels against each other.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <limits>
#include <random>

#include "core/estimation/ArmFilterImpl.h"  // allFiniteFast
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

// The consider sensitivity (how the state's error depends on parameters taken as known) against
// its definition: a parameter error delta moves the prior state by S0 delta and each block's
// measurement by D delta, so each block sees its innovation change by (D - H S0) delta; the
// update is linear in the innovations, and the state's error after the blocks, less the one
// without delta, is S delta, column by column. Two blocks: the angles' columns only, then a
// heading-blind full block.
TEST_P(BlockUpdate, ConsiderSensitivityIsTheStatesResponseToTheParameters) {
  std::mt19937_64 rng(19);
  using Sens = Eigen::Matrix<double, N, 6, Eigen::RowMajor>;
  using Rows2 = Eigen::Matrix<double, 2, 6, Eigen::RowMajor>;
  using Rows3 = Eigen::Matrix<double, 3, 6, Eigen::RowMajor>;
  for (int trial = 0; trial < 10; ++trial) {
    const Mat p0 = randomCovariance(rng);
    const Eigen::Matrix<double, 2, 5> h1 = randomMatrix<2, 5>(rng);
    const Mat3N h2 = randomMatrix<3, N>(rng);
    const Rows2 d1 = randomMatrix<2, 6>(rng);
    const Rows3 d2 = Rows3::Zero();  // an IMU block
    const Sens s0 = 0.3 * randomMatrix<N, 6>(rng);
    const Eigen::Vector2d z1 = randomMatrix<2, 1>(rng), var1(0.02, 0.03);
    const Vec3 z2 = randomMatrix<3, 1>(rng), var2(0.05, 0.1, 0.2);
    Vec u = Vec::Zero();
    u.tail<5>() = randomMatrix<5, 1>(rng).normalized();
    Vec v = randomMatrix<N, 1>(rng);
    v += (1.0 - u.dot(v)) * u;
    const BlindDirection<N> blind{v, u};
    // The state's error after both blocks for a parameter error delta.
    auto errorAfter = [&](const Eigen::Matrix<double, 6, 1>& delta, Sens* sens) {
      Mat p = p0;
      Vec dx = Vec::Zero();
      double nis = 0.0;
      const Vec prior = s0 * delta;
      const Eigen::Vector2d i1 = z1 + d1 * delta - h1 * prior.segment<5>(10);
      const Vec3 i2 = z2 + d2 * delta - h2 * prior;
      EXPECT_TRUE((fuseBlock<2, 5, N>(h1, 10, i1, var1, nullptr, p, dx, nis, sens, &d1)));
      EXPECT_TRUE((fuseBlock<3, N, N>(h2, 0, i2, var2, &blind, p, dx, nis, sens, &d2)));
      return Vec(prior + dx);
    };
    Sens s = s0;
    const Vec base = errorAfter(Eigen::Matrix<double, 6, 1>::Zero(), &s);
    for (int c = 0; c < 6; ++c) {
      const Vec moved = errorAfter(Eigen::Matrix<double, 6, 1>::Unit(c), nullptr);
      EXPECT_LT((moved - base - s.col(c)).cwiseAbs().maxCoeff(), 1e-10) << "column " << c;
    }
    EXPECT_GT((s - s0).norm(), 1e-3);  // the blocks did carry it on
  }
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
    // Fused multiply-adds round once: the kernels differ in the last bits, not in the order.
    EXPECT_NE(p[1], p[0]);
  }
}

// A run of blocks on P padded once (as ArmFilter::sequentialUpdate does) gives exactly what
// fusing each block into the unpadded P does, whatever the state size; the padding rows stay
// exactly zero throughout, so nothing of them can reach P.
template <int S>
void checkPaddedRun(std::mt19937_64& rng) {
  using MatS = Eigen::Matrix<double, S, S>;
  using VecS = Eigen::Matrix<double, S, 1>;
  std::normal_distribution<double> g;
  MatS a;
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j) a(i, j) = g(rng);
  MatS p0 = a * a.transpose() / S + 0.1 * MatS::Identity();
  p0 = (0.5 * (p0 + p0.transpose())).eval();  // exactly symmetric, as the filter's P
  VecS u = VecS::Zero(), v = VecS::Zero();
  u.template segment<5>(10) = randomMatrix<5, 1>(rng).normalized();
  v.template head<15>() = randomMatrix<15, 1>(rng);
  v += (1.0 - u.dot(v)) * u;
  const BlindDirection<S> blind{v, u};
  const Vec3 variance(0.02, 0.3, 0.7);

  PaddedCovariance<S> padded(p0);
  MatS p = p0;
  VecS dxPadded = VecS::Zero(), dx = VecS::Zero();
  for (int block = 0; block < 4; ++block) {
    const Vec3 z = randomMatrix<3, 1>(rng);
    double nisPadded = 0.0, nis = 0.0;
    if (block < 3) {  // IMU-like rows over every column, two of them heading-blind
      const Eigen::Matrix<double, 3, S> h = randomMatrix<3, S>(rng);
      const BlindDirection<S>* b = block == 1 ? nullptr : &blind;
      ASSERT_TRUE((fuseBlock<3, S, S>(h, 0, z, variance, b, padded, dxPadded, nisPadded)));
      ASSERT_TRUE((fuseBlock<3, S, S>(h, 0, z, variance, b, p, dx, nis)));
    } else {  // an optical block on the five angle columns
      const Eigen::Matrix<double, 3, 5> h = randomMatrix<3, 5>(rng);
      ASSERT_TRUE((fuseBlock<3, 5, S>(h, 10, z, variance, nullptr, padded, dxPadded, nisPadded)));
      ASSERT_TRUE((fuseBlock<3, 5, S>(h, 10, z, variance, nullptr, p, dx, nis)));
    }
    EXPECT_EQ(nisPadded, nis);
    constexpr int kPad = PaddedCovariance<S>::kRows - S;
    EXPECT_TRUE((padded.m.template bottomRows<kPad>().array() == 0.0).all());
  }
  MatS out;
  padded.store(out);
  EXPECT_EQ(out, p);
  EXPECT_EQ(dxPadded, dx);
  EXPECT_EQ(out, out.transpose());
}

TEST_P(BlockUpdate, PaddedRunEqualsBlockByBlockAndKeepsThePaddingZero) {
  std::mt19937_64 rng(23);
  for (int trial = 0; trial < 10; ++trial) {
    checkPaddedRun<15>(rng);  // Method A and C: 16 rows
    checkPaddedRun<21>(rng);  // Method B: 24 rows
  }
}

// ArmFilter's finiteness check of x and P: every entry finite, however large; one NaN or
// infinity anywhere makes it false.
TEST(AllFiniteFast, AnyNonFiniteEntryAnywhereIsFound) {
  Mat p = Mat::Constant(1e308);  // finite, and their sum would overflow
  p(3, 3) = -1e308;
  EXPECT_TRUE(detail::allFiniteFast(p));
  EXPECT_TRUE(detail::allFiniteFast(Mat::Zero()));
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(),
                           std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
    for (const int at : {0, 7, 112, 224}) {
      Mat q = p;
      q(at % N, at / N) = bad;
      EXPECT_FALSE(detail::allFiniteFast(q)) << bad << " at " << at;
    }
    Vec x = Vec::Ones();
    x(14) = bad;
    EXPECT_FALSE(detail::allFiniteFast(x)) << bad;
  }
}

}  // namespace
}  // namespace armtrack
