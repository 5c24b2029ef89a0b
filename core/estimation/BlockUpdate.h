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

namespace detail {

// Eigen's SIMD packet for doubles (two with SSE2; one double when vectorisation is off).
using Packet = Eigen::internal::packet_traits<double>::type;
inline constexpr int kPacket = Eigen::internal::packet_traits<double>::size;

// out.col(i) = sum_k a.col(k) * h(i, k) for i < M, k < K, where a holds K columns of length N
// (column-major, leading dimension N): M x K multiply-adds per row, the M sums held in registers
// while a's rows stream through once. Sums in the order of k.
template <int M, int K, int N>
void columnsTimesTranspose(const double* a, const Eigen::Matrix<double, M, K>& h,
                           Eigen::Matrix<double, N, M>& out) {
  using namespace Eigen::internal;
  Packet hb[K][M];  // h's entries, each broadcast to a packet once
  for (int k = 0; k < K; ++k)
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) hb[k][i] = pset1<Packet>(h(i, k));
  int r = 0;
  for (; r + kPacket <= N; r += kPacket) {
    Packet acc[M];
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) acc[i] = pset1<Packet>(0.0);
    for (int k = 0; k < K; ++k) {
      const Packet x = ploadu<Packet>(a + k * N + r);
#pragma GCC unroll 4
      for (int i = 0; i < M; ++i) acc[i] = padd(acc[i], pmul(x, hb[k][i]));
    }
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) pstoreu(out.data() + i * N + r, acc[i]);
  }
  for (; r < N; ++r)
    for (int i = 0; i < M; ++i) {
      double acc = 0.0;
      for (int k = 0; k < K; ++k) acc += a[k * N + r] * h(i, k);
      out(r, i) = acc;
    }
}

// p -= vt vt^T (+ a a^T WithA), column by column. Entry (r, c) subtracts
// sum_m vt(r, m) vt(c, m) summed in the order of m, exactly what entry (c, r) subtracts, so a
// symmetric p stays exactly symmetric.
template <int M, int N, bool WithA>
void symmetricDowndate(const Eigen::Matrix<double, N, M>& vt, const Eigen::Matrix<double, N, 1>& a,
                       Eigen::Matrix<double, N, N>& p) {
  using namespace Eigen::internal;
  const double* v = vt.data();
  for (int c = 0; c < N; ++c) {
    double* pc = p.data() + c * N;
    Packet b[M];
#pragma GCC unroll 4
    for (int m = 0; m < M; ++m) b[m] = pset1<Packet>(vt(c, m));
    const Packet ac = pset1<Packet>(WithA ? a(c) : 0.0);
    int r = 0;
    for (; r + kPacket <= N; r += kPacket) {
      Packet sum = pmul(ploadu<Packet>(v + r), b[0]);
#pragma GCC unroll 4
      for (int m = 1; m < M; ++m) sum = padd(sum, pmul(ploadu<Packet>(v + m * N + r), b[m]));
      Packet x = psub(ploadu<Packet>(pc + r), sum);
      if constexpr (WithA) x = padd(x, pmul(ploadu<Packet>(a.data() + r), ac));
      pstoreu(pc + r, x);
    }
    for (; r < N; ++r) {
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
// Same order of sums; the tails (N not a multiple of four) use the same fused steps in a masked
// packet, so symmetricDowndate still keeps P exactly symmetric.
#define ARMTRACK_TARGET_FMA __attribute__((target("avx2,fma")))

// Lanes 0 .. T-1 of a packet: the tail of a column whose length is not a multiple of four is
// loaded and stored as one packet (masked lanes are neither read nor written), with the same
// steps per lane as a full packet, so the tail rounds exactly as a scalar loop of those steps.
template <int T>
ARMTRACK_TARGET_FMA inline __m256i tailMask() {
  static_assert(T > 0 && T < 4);
  return _mm256_setr_epi64x(-1, T > 1 ? -1 : 0, T > 2 ? -1 : 0, 0);
}

template <int M, int K, int N>
ARMTRACK_TARGET_FMA void columnsTimesTransposeFma(const double* a,
                                                  const Eigen::Matrix<double, M, K>& h,
                                                  Eigen::Matrix<double, N, M>& out) {
  static_assert(K >= 1);
  int r = 0;
  for (; r + 4 <= N; r += 4) {
    __m256d acc[M];
    const __m256d x0 = _mm256_loadu_pd(a + r);
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) acc[i] = _mm256_mul_pd(x0, _mm256_set1_pd(h(i, 0)));
    for (int k = 1; k < K; ++k) {
      const __m256d x = _mm256_loadu_pd(a + k * N + r);
#pragma GCC unroll 4
      for (int i = 0; i < M; ++i) acc[i] = _mm256_fmadd_pd(x, _mm256_set1_pd(h(i, k)), acc[i]);
    }
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) _mm256_storeu_pd(out.data() + i * N + r, acc[i]);
  }
  if constexpr (N % 4 != 0) {
    // The last N % 4 rows as one masked packet, with the same steps as the full ones.
    const __m256i mask = tailMask<N % 4>();
    __m256d acc[M];
    const __m256d x0 = _mm256_maskload_pd(a + r, mask);
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) acc[i] = _mm256_mul_pd(x0, _mm256_set1_pd(h(i, 0)));
    for (int k = 1; k < K; ++k) {
      const __m256d x = _mm256_maskload_pd(a + k * N + r, mask);
#pragma GCC unroll 4
      for (int i = 0; i < M; ++i) acc[i] = _mm256_fmadd_pd(x, _mm256_set1_pd(h(i, k)), acc[i]);
    }
#pragma GCC unroll 4
    for (int i = 0; i < M; ++i) _mm256_maskstore_pd(out.data() + i * N + r, mask, acc[i]);
  }
}

template <int M, int N, bool WithA>
ARMTRACK_TARGET_FMA void symmetricDowndateFma(const Eigen::Matrix<double, N, M>& vt,
                                              const Eigen::Matrix<double, N, 1>& a,
                                              Eigen::Matrix<double, N, N>& p) {
  const double* v = vt.data();
  for (int c = 0; c < N; ++c) {
    double* pc = p.data() + c * N;
    __m256d b[M];
#pragma GCC unroll 4
    for (int m = 0; m < M; ++m) b[m] = _mm256_set1_pd(vt(c, m));
    const __m256d ac = _mm256_set1_pd(WithA ? a(c) : 0.0);
    int r = 0;
    for (; r + 4 <= N; r += 4) {
      __m256d sum = _mm256_mul_pd(_mm256_loadu_pd(v + r), b[0]);
#pragma GCC unroll 4
      for (int m = 1; m < M; ++m) sum = _mm256_fmadd_pd(_mm256_loadu_pd(v + m * N + r), b[m], sum);
      __m256d x = _mm256_sub_pd(_mm256_loadu_pd(pc + r), sum);
      if constexpr (WithA) x = _mm256_fmadd_pd(_mm256_loadu_pd(a.data() + r), ac, x);
      _mm256_storeu_pd(pc + r, x);
    }
    if constexpr (N % 4 != 0) {
      const __m256i mask = tailMask<N % 4>();
      __m256d sum = _mm256_mul_pd(_mm256_maskload_pd(v + r, mask), b[0]);
#pragma GCC unroll 4
      for (int m = 1; m < M; ++m)
        sum = _mm256_fmadd_pd(_mm256_maskload_pd(v + m * N + r, mask), b[m], sum);
      __m256d x = _mm256_sub_pd(_mm256_maskload_pd(pc + r, mask), sum);
      if constexpr (WithA) x = _mm256_fmadd_pd(_mm256_maskload_pd(a.data() + r, mask), ac, x);
      _mm256_maskstore_pd(pc + r, mask, x);
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

template <int M, int K, int N>
void columnsTimesTransposeAny(const double* a, const Eigen::Matrix<double, M, K>& h,
                              Eigen::Matrix<double, N, M>& out) {
#ifdef ARMTRACK_FMA_KERNELS
  if (useFmaKernels()) return columnsTimesTransposeFma<M, K, N>(a, h, out);
#endif
  columnsTimesTranspose<M, K, N>(a, h, out);
}

template <int M, int N, bool WithA>
void symmetricDowndateAny(const Eigen::Matrix<double, N, M>& vt,
                          const Eigen::Matrix<double, N, 1>& a, Eigen::Matrix<double, N, N>& p) {
#ifdef ARMTRACK_FMA_KERNELS
  if (useFmaKernels()) return symmetricDowndateFma<M, N, WithA>(vt, a, p);
#endif
  symmetricDowndate<M, N, WithA>(vt, a, p);
}

}  // namespace detail

/// Fuses one M-row block whose measurement Jacobian is zero outside columns [col, col + K),
/// given as h (M x K), with diagonal noise variance, into P (p) and the state correction dx,
/// which holds what the blocks before it corrected. innovation is the block's z - h(x) at the
/// linearisation point; nis gets r^T S^-1 r for the innovation r left by the blocks before.
/// Returns false when S = H P H^T + R is not positive definite (p and dx then unchanged).
///
/// Per block: L the Cholesky factor of S, W = H P, V = L^-1 W, dx += W^T S^-1 r, and the
/// symmetric rank-M downdate P -= V^T V. With a blind direction the gain Kb = (I - v u^T) K is
/// used and P follows it exactly: the Joseph form P + Kb S Kb^T - Kb W - W^T Kb^T equals,
/// because K S K^T = K W = V^T V, the optimal update P - V^T V plus |V u|^2 v v^T, a rank-1
/// update; so the blind update costs what the optimal one does.
///
/// Everything N-long is worked on as columns, on contiguous memory and in SIMD packets: W^T =
/// P H^T (P is symmetric), V^T = W^T L^-T, and the downdate P -= V^T V; the M x M Cholesky
/// factor and its solves are written out. (Eigen's general kernels, and its coefficient-based
/// products, cost several times the arithmetic at these sizes.)
template <int M, int K, int N>
bool fuseBlock(const Eigen::Matrix<double, M, K>& h, int col,
               const Eigen::Matrix<double, M, 1>& innovation,
               const Eigen::Matrix<double, M, 1>& variance, const BlindDirection<N>* blind,
               Eigen::Matrix<double, N, N>& p, Eigen::Matrix<double, N, 1>& dx, double& nis) {
  using Cols = Eigen::Matrix<double, N, M>;
  using SMat = Eigen::Matrix<double, M, M>;
  using MVec = Eigen::Matrix<double, M, 1>;
  Cols wt;  // W^T = P H^T (P is symmetric): K of P's columns combined
  detail::columnsTimesTransposeAny<M, K, N>(p.data() + col * N, h, wt);
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
  // V^T = W^T L^-T, column by column.
  Cols vt;
  for (int j = 0; j < M; ++j) {
    vt.col(j) = wt.col(j);
    for (int k = 0; k < j; ++k) vt.col(j) -= l(j, k) * vt.col(k);
    vt.col(j) *= inv(j);
  }
  Eigen::Matrix<double, N, 1> g = wt.col(0) * sr(0);  // K r = W^T S^-1 r
  for (int i = 1; i < M; ++i) g += wt.col(i) * sr(i);
  if (!blind) {
    detail::symmetricDowndateAny<M, N, false>(vt, g, p);
    dx += g;
    return true;
  }
  dx += g - blind->v * blind->u.dot(g);
  // P - V^T V + a a^T with a = |V u| v.
  const Eigen::Matrix<double, N, 1> a = (vt.transpose() * blind->u).norm() * blind->v;
  detail::symmetricDowndateAny<M, N, true>(vt, a, p);
  return true;
}

}  // namespace armtrack
