// One block of a sequential Kalman update, on fixed-size matrices: the arithmetic of ArmFilter's
// EKF update, where R is block-diagonal and the blocks are fused one after another (exactly the
// batch update, at a third of the cost). Qt-free; no allocation.
#pragma once

#include <Eigen/Core>
#include <cmath>
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define ARMTRACK_FMA_KERNELS 1
#endif

namespace armtrack {

/// A direction the update must not move the state along (a Schmidt, or "consider", update along
/// one direction): the gain K becomes Kb = (I - v u^T) K, with u . v = 1.
template <int N>
struct BlindDirection {
  const Eigen::Matrix<double, N, 1>& v;  // the direction in the state
  const Eigen::Matrix<double, N, 1>& u;  // reads the component along v
};

/// P as fuseBlock keeps it: each column padded with zero rows to a whole number of four-double
/// packets (kRows) and the whole aligned to 32 bytes, so every column starts on a packet and
/// the kernels read and write whole, aligned packets only. Without the padding (15 rows of 120
/// bytes) a third of the 32-byte accesses straddled a cache line and each column ended in a
/// masked load and store; with it the kernels have no tails. (Measured alone it left the hour's
/// time unchanged: the downdate got faster and fuseBlock's own code slower; docs/estimator.md,
/// "Sixth round".) Rows N .. kRows-1 stay zero: every kernel computes them from zero rows, and
/// nothing reads them back into P.
template <int N>
struct alignas(32) PaddedCovariance {
  static constexpr int kRows = (N + 3) / 4 * 4;
  Eigen::Matrix<double, kRows, N> m;

  PaddedCovariance() = default;
  explicit PaddedCovariance(const Eigen::Matrix<double, N, N>& p) { load(p); }
  void load(const Eigen::Matrix<double, N, N>& p) {
    m.template topRows<N>() = p;
    if constexpr (kRows > N) m.template bottomRows<kRows - N>().setZero();
  }
  void store(Eigen::Matrix<double, N, N>& p) const { p = m.template topRows<N>(); }
};

namespace detail {

// Eigen's SIMD packet for doubles (two with SSE2; one double when vectorisation is off).
using Packet = Eigen::internal::packet_traits<double>::type;
inline constexpr int kPacket = Eigen::internal::packet_traits<double>::size;

// out.col(i) = sum_k a.col(k) * h(i, k) for i < M, k < K, where a holds K columns of length L
// (column-major, leading dimension L, padded as PaddedCovariance): M x K multiply-adds per row,
// the M sums held in registers while a's rows stream through once. Sums in the order of k.
template <int M, int K, int L>
void columnsTimesTranspose(const double* a, const Eigen::Matrix<double, M, K>& h,
                           Eigen::Matrix<double, L, M>& out) {
  using namespace Eigen::internal;
  Packet hb[K][M];  // h's entries, each broadcast to a packet once
  for (int k = 0; k < K; ++k)
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) hb[k][i] = pset1<Packet>(h(i, k));
  int r = 0;
  for (; r + kPacket <= L; r += kPacket) {
    Packet acc[M];
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) acc[i] = pset1<Packet>(0.0);
    for (int k = 0; k < K; ++k) {
      const Packet x = ploadu<Packet>(a + k * L + r);
#pragma GCC unroll 4
      for (int i = 0; i < M; ++i) acc[i] = padd(acc[i], pmul(x, hb[k][i]));
    }
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) pstoreu(out.data() + i * L + r, acc[i]);
  }
  for (; r < L; ++r)
    for (int i = 0; i < M; ++i) {
      double acc = 0.0;
      for (int k = 0; k < K; ++k) acc += a[k * L + r] * h(i, k);
      out(r, i) = acc;
    }
}

// p -= vt vt^T (+ a a^T WithA) on P's N columns of length L (padded). Entry (r, c) subtracts
// sum_m vt(r, m) vt(c, m) summed in the order of m, exactly what entry (c, r) subtracts, so a
// symmetric p stays exactly symmetric.
template <int M, int L, int N, bool WithA>
void symmetricDowndate(const Eigen::Matrix<double, L, M>& vt, const Eigen::Matrix<double, L, 1>& a,
                       Eigen::Matrix<double, L, N>& p) {
  using namespace Eigen::internal;
  const double* v = vt.data();
  for (int c = 0; c < N; ++c) {
    double* pc = p.data() + c * L;
    Packet b[M];
#pragma GCC unroll 4
    for (int m = 0; m < M; ++m) b[m] = pset1<Packet>(vt(c, m));
    const Packet ac = pset1<Packet>(WithA ? a(c) : 0.0);
    int r = 0;
    for (; r + kPacket <= L; r += kPacket) {
      Packet sum = pmul(ploadu<Packet>(v + r), b[0]);
#pragma GCC unroll 4
      for (int m = 1; m < M; ++m) sum = padd(sum, pmul(ploadu<Packet>(v + m * L + r), b[m]));
      Packet x = psub(ploadu<Packet>(pc + r), sum);
      if constexpr (WithA) x = padd(x, pmul(ploadu<Packet>(a.data() + r), ac));
      pstoreu(pc + r, x);
    }
    for (; r < L; ++r) {
      double sum = vt(r, 0) * vt(c, 0);
      for (int m = 1; m < M; ++m) sum += vt(r, m) * vt(c, m);
      double x = pc[r] - sum;
      if constexpr (WithA) x += a(r) * a(c);
      pc[r] = x;
    }
  }
}

#ifdef ARMTRACK_FMA_KERNELS
// The two kernels above for processors with AVX2 and FMA (chosen at run time, so the build
// still runs on plain x86-64): four doubles per instruction, and each multiply-add rounded once.
// Same order of sums; L is a whole number of packets, so there are no tails.
#define ARMTRACK_TARGET_FMA __attribute__((target("avx2,fma")))

template <int M, int K, int L>
ARMTRACK_TARGET_FMA void columnsTimesTransposeFma(const double* a,
                                                  const Eigen::Matrix<double, M, K>& h,
                                                  Eigen::Matrix<double, L, M>& out) {
  static_assert(K >= 1 && L % 4 == 0);
  for (int r = 0; r < L; r += 4) {
    __m256d acc[M];
    const __m256d x0 = _mm256_loadu_pd(a + r);
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) acc[i] = _mm256_mul_pd(x0, _mm256_set1_pd(h(i, 0)));
    for (int k = 1; k < K; ++k) {
      const __m256d x = _mm256_loadu_pd(a + k * L + r);
#pragma GCC unroll 4
      for (int i = 0; i < M; ++i) acc[i] = _mm256_fmadd_pd(x, _mm256_set1_pd(h(i, k)), acc[i]);
    }
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) _mm256_storeu_pd(out.data() + i * L + r, acc[i]);
  }
}

template <int M, int L, int N, bool WithA>
ARMTRACK_TARGET_FMA void symmetricDowndateFma(const Eigen::Matrix<double, L, M>& vt,
                                              const Eigen::Matrix<double, L, 1>& a,
                                              Eigen::Matrix<double, L, N>& p) {
  static_assert(L % 4 == 0);
  const double* v = vt.data();
  for (int c = 0; c < N; ++c) {
    double* pc = p.data() + c * L;
    __m256d b[M];
#pragma GCC unroll 4
    for (int m = 0; m < M; ++m) b[m] = _mm256_set1_pd(vt(c, m));
    const __m256d ac = _mm256_set1_pd(WithA ? a(c) : 0.0);
    for (int r = 0; r < L; r += 4) {
      __m256d sum = _mm256_mul_pd(_mm256_loadu_pd(v + r), b[0]);
#pragma GCC unroll 4
      for (int m = 1; m < M; ++m) sum = _mm256_fmadd_pd(_mm256_loadu_pd(v + m * L + r), b[m], sum);
      __m256d x = _mm256_sub_pd(_mm256_loadu_pd(pc + r), sum);
      if constexpr (WithA) x = _mm256_fmadd_pd(_mm256_loadu_pd(a.data() + r), ac, x);
      _mm256_storeu_pd(pc + r, x);
    }
  }
}
#undef ARMTRACK_TARGET_FMA

inline bool processorHasFma() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}
#endif

/// Whether fuseBlock uses the AVX2/FMA kernels: true when the processor has them. A test may set
/// it to false to run the plain kernels (before any filter runs; it is not synchronised).
inline bool& useFmaKernels() {
#ifdef ARMTRACK_FMA_KERNELS
  static bool use = processorHasFma();
#else
  static bool use = false;
#endif
  return use;
}

template <int M, int K, int L>
void columnsTimesTransposeAny(const double* a, const Eigen::Matrix<double, M, K>& h,
                              Eigen::Matrix<double, L, M>& out) {
#ifdef ARMTRACK_FMA_KERNELS
  if (useFmaKernels()) return columnsTimesTransposeFma<M, K, L>(a, h, out);
#endif
  columnsTimesTranspose<M, K, L>(a, h, out);
}

template <int M, int L, int N, bool WithA>
void symmetricDowndateAny(const Eigen::Matrix<double, L, M>& vt,
                          const Eigen::Matrix<double, L, 1>& a, Eigen::Matrix<double, L, N>& p) {
#ifdef ARMTRACK_FMA_KERNELS
  if (useFmaKernels()) return symmetricDowndateFma<M, L, N, WithA>(vt, a, p);
#endif
  symmetricDowndate<M, L, N, WithA>(vt, a, p);
}

}  // namespace detail

/// Fuses one M-row block whose measurement Jacobian is zero outside columns [col, col + K),
/// given as h (M x K), with diagonal noise variance, into P (p, padded) and the state
/// correction dx, which holds what the blocks before it corrected. innovation is the block's
/// z - h(x) at the linearisation point; nis gets r^T S^-1 r for the innovation r left by the
/// blocks before. Returns false when S = H P H^T + R is not positive definite (p and dx then
/// unchanged).
///
/// Per block: L the Cholesky factor of S, W = H P, V = L^-1 W, dx += W^T S^-1 r, and the
/// symmetric rank-M downdate P -= V^T V. With a blind direction the gain Kb = (I - v u^T) K is
/// used and P follows it exactly: the Joseph form P + Kb S Kb^T - Kb W - W^T Kb^T equals,
/// because K S K^T = K W = V^T V, the optimal update P - V^T V plus |V u|^2 v v^T, a rank-1
/// update; so the blind update costs what the optimal one does.
///
/// Everything N-long is worked on as padded columns, on aligned memory and in whole SIMD packets:
/// W^T = P H^T (P is symmetric), V^T = W^T L^-T, and the downdate P -= V^T V; the M x M Cholesky
/// factor and its solves are written out. (Eigen's general kernels, and its coefficient-based
/// products, cost several times the arithmetic at these sizes.)
///
/// sens, when given, is a consider (Schmidt) sensitivity: how the state's error depends on
/// parameters the filter takes as known (dx_err = sens * p_err). The block's gain carries it on,
/// sens += Kb (D - H sens), where D (M x C, none: zero) is how the parameters' error enters the
/// measurement; the state and P are not touched by it.
template <int M, int K, int N, int C = 6>
bool fuseBlock(const Eigen::Matrix<double, M, K>& h, int col,
               const Eigen::Matrix<double, M, 1>& innovation,
               const Eigen::Matrix<double, M, 1>& variance, const BlindDirection<N>* blind,
               PaddedCovariance<N>& padded, Eigen::Matrix<double, N, 1>& dx, double& nis,
               Eigen::Matrix<double, N, C, Eigen::RowMajor>* sens = nullptr,
               const Eigen::Matrix<double, M, C, Eigen::RowMajor>* d = nullptr) {
  constexpr int L = PaddedCovariance<N>::kRows;
  using Cols = Eigen::Matrix<double, L, M>;
  using Column = Eigen::Matrix<double, L, 1>;
  using SMat = Eigen::Matrix<double, M, M>;
  using MVec = Eigen::Matrix<double, M, 1>;
  alignas(32) Cols wt;  // W^T = P H^T (P is symmetric): K of P's columns combined
  detail::columnsTimesTransposeAny<M, K, L>(padded.m.data() + col * L, h, wt);
  // S = H W^T + R and its Cholesky factor L (lower), with the reciprocals of its diagonal: the
  // solves below multiply by them, so the only divisions are the M reciprocals (a division's
  // latency is several multiplications', and these steps depend on each other).
  SMat l = SMat::Zero();
  MVec inv;
  for (int j = 0; j < M; ++j) {
    for (int i = j; i < M; ++i) {
      double sij = h.row(i).dot(wt.col(j).template segment<K>(col));
      if (i == j) sij += variance(i);
      for (int k = 0; k < j; ++k) sij -= l(i, k) * l(j, k);
      if (i == j) {
        if (!(sij > 0.0)) return false;
        l(j, j) = std::sqrt(sij);
        inv(j) = 1.0 / l(j, j);
      } else {
        l(i, j) = sij * inv(j);
      }
    }
  }
  // r, y = L^-1 r and S^-1 r = L^-T y.
  const MVec r = innovation - h * dx.template segment<K>(col);
  MVec sr;
  for (int i = 0; i < M; ++i) {
    double y = r(i);
    for (int k = 0; k < i; ++k) y -= l(i, k) * sr(k);
    sr(i) = y * inv(i);
  }
  for (int i = M - 1; i >= 0; --i) {
    double y = sr(i);
    for (int k = i + 1; k < M; ++k) y -= l(k, i) * sr(k);
    sr(i) = y * inv(i);
  }
  nis = r.dot(sr);
  // V^T = W^T L^-T, column by column (its padding rows stay zero, as W^T's).
  alignas(32) Cols vt;
  for (int j = 0; j < M; ++j) {
    vt.col(j) = wt.col(j);
    for (int k = 0; k < j; ++k) vt.col(j) -= l(j, k) * vt.col(k);
    vt.col(j) *= inv(j);
  }
  if (sens) {
    // y = D - H sens, then S^-1 y by the same two substitutions, and Kb y = W^T S^-1 y; row by
    // row (sens is row-major, so each row is whole packets).
    using Rows = Eigen::Matrix<double, M, C, Eigen::RowMajor>;
    Rows y = d ? *d : Rows::Zero();
    for (int i = 0; i < M; ++i)
      for (int k = 0; k < K; ++k) y.row(i) -= h(i, k) * sens->row(col + k);
    for (int i = 0; i < M; ++i) {
      for (int k = 0; k < i; ++k) y.row(i) -= l(i, k) * y.row(k);
      y.row(i) *= inv(i);
    }
    for (int i = M - 1; i >= 0; --i) {
      for (int k = i + 1; k < M; ++k) y.row(i) -= l(k, i) * y.row(k);
      y.row(i) *= inv(i);
    }
    Eigen::Matrix<double, 1, C> along = Eigen::Matrix<double, 1, C>::Zero();  // u^T K y
    for (int n = 0; n < N; ++n) {
      Eigen::Matrix<double, 1, C> ky = wt(n, 0) * y.row(0);
      for (int m = 1; m < M; ++m) ky += wt(n, m) * y.row(m);
      sens->row(n) += ky;
      if (blind) along += blind->u(n) * ky;
    }
    if (blind)
      for (int n = 0; n < N; ++n) sens->row(n) -= blind->v(n) * along;
  }
  alignas(32) Column g = wt.col(0) * sr(0);  // K r = W^T S^-1 r
  for (int i = 1; i < M; ++i) g += wt.col(i) * sr(i);
  if (!blind) {
    detail::symmetricDowndateAny<M, L, N, false>(vt, g, padded.m);
    dx += g.template head<N>();
    return true;
  }
  dx += g.template head<N>() - blind->v * blind->u.dot(g.template head<N>());
  // P - V^T V + a a^T with a = |V u| v.
  double vu2 = 0.0;  // |V u|^2
  for (int m = 0; m < M; ++m) {
    const double vu = vt.col(m).template head<N>().dot(blind->u);
    vu2 += vu * vu;
  }
  alignas(32) Column a = Column::Zero();
  a.template head<N>() = std::sqrt(vu2) * blind->v;
  detail::symmetricDowndateAny<M, L, N, true>(vt, a, padded.m);
  return true;
}

/// fuseBlock on an unpadded P: pads it, fuses and writes it back (for a single block; a run of
/// blocks pads once).
template <int M, int K, int N, int C = 6>
bool fuseBlock(const Eigen::Matrix<double, M, K>& h, int col,
               const Eigen::Matrix<double, M, 1>& innovation,
               const Eigen::Matrix<double, M, 1>& variance, const BlindDirection<N>* blind,
               Eigen::Matrix<double, N, N>& p, Eigen::Matrix<double, N, 1>& dx, double& nis,
               Eigen::Matrix<double, N, C, Eigen::RowMajor>* sens = nullptr,
               const Eigen::Matrix<double, M, C, Eigen::RowMajor>* d = nullptr) {
  PaddedCovariance<N> padded(p);
  if (!fuseBlock<M, K, N, C>(h, col, innovation, variance, blind, padded, dx, nis, sens, d))
    return false;
  padded.store(p);
  return true;
}

}  // namespace armtrack
