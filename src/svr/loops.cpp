// Inner loops of the SMO solver and of kernel rows. See loops.hpp for why they live here and for
// the floating-point flags this file is compiled with (src/CMakeLists.txt).
#include "svr/loops.hpp"

#include <algorithm>
#include <bit>
#include <cfloat>
#include <iterator>

// One portable and one AVX2 build of each hot loop, chosen at load time. Sanitizer builds keep
// the portable one only: ifunc resolvers run before the sanitizer runtime is ready.
#if defined(__GNUC__) && !defined(FOGDRIFT_NO_CLONES) && defined(__x86_64__)
#define FOGDRIFT_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define FOGDRIFT_CLONES
#endif
#if defined(__x86_64__) && defined(__GNUC__) && !defined(FOGDRIFT_NO_CLONES)
#define FOGDRIFT_HAVE_AVX2_GATHER 1
#include <immintrin.h>

#include <cstring>
#else
#define FOGDRIFT_HAVE_AVX2_GATHER 0
#endif

namespace fogdrift::svr::detail {
namespace {

constexpr double kLog2e = 1.4426950408889634074;
// ln 2 split so that n·kLn2Hi is exact for |n| < 2^20 (Cody & Waite range reduction).
constexpr double kLn2Hi = 6.93147180369123816490e-01;
constexpr double kLn2Lo = 1.90821492927058770002e-10;
constexpr double kShifter = 6755399441055744.0;  // 1.5·2^52: adding it rounds to an integer

// e^x through e^x = 2^n·e^r, n = round(x/ln 2), |r| ≤ ln 2 / 2, and the Taylor series of e^r to
// degree 13 (truncation error r^14/14! < 5e-18). Branch-free so that loops around it vectorise.
inline double exp_core(double x) {
  x = x < -700.0 ? -700.0 : x;  // e^-700 is 0 in float; keeps 2^n a normal double
  x = x > 700.0 ? 700.0 : x;
  const double t = x * kLog2e + kShifter;
  const double n = t - kShifter;
  const double r = (x - n * kLn2Hi) - n * kLn2Lo;
  double p = 1.0 / 6227020800.0;  // 1/13!
  p = p * r + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  const std::int64_t k = std::bit_cast<std::int64_t>(t) - std::bit_cast<std::int64_t>(kShifter);
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(k + 1023) << 52);
  return p * scale;
}

constexpr std::size_t kBlock = 256;  // columns per block: the accumulators stay in L1

// acc[j] = x_i·x_{j0+j} for j < m, summed over features in order (LIBSVM's order), from the
// feature-major copy `xt` (feature f of column j at xt[f·stride + j]). Inlined into each
// caller's AVX2 and portable builds.
inline void dot_block(const double* xi, const double* xt, std::size_t stride, std::size_t d,
                      std::size_t j0, std::size_t m, double* acc) {
  for (std::size_t j = 0; j < m; ++j) acc[j] = 0.0;
  for (std::size_t f = 0; f < d; ++f) {
    const double xf = xi[f];
    const double* col = xt + f * stride + j0;
    for (std::size_t j = 0; j < m; ++j) acc[j] += xf * col[j];
  }
}

}  // namespace

float exp_to_float(double x) {
  return static_cast<float>(exp_core(x));
}

namespace {
void rbf_row_portable(const double* xi, double sq_i, const double* xt, std::size_t stride,
                      const double* sq, std::size_t n, std::size_t d, double gamma, float* out) {
  double acc[kBlock];
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - j0);
    dot_block(xi, xt, stride, d, j0, m, acc);
    for (std::size_t j = 0; j < m; ++j) {
      const double dist = (sq_i + sq[j0 + j]) - 2.0 * acc[j];
      out[j0 + j] = static_cast<float>(exp_core(-gamma * dist));
    }
  }
}
}  // namespace

FOGDRIFT_CLONES
void linear_row(const double* xi, const double* xt, std::size_t stride, std::size_t n,
                std::size_t d, float* out) {
  double acc[kBlock];
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - j0);
    dot_block(xi, xt, stride, d, j0, m, acc);
    for (std::size_t j = 0; j < m; ++j) out[j0 + j] = static_cast<float>(acc[j]);
  }
}

FOGDRIFT_CLONES
void distance_row(const double* xi, double sq_i, const double* xt, const double* sq, std::size_t n,
                  std::size_t d, float* out) {
  double acc[kBlock];
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - j0);
    dot_block(xi, xt, n, d, j0, m, acc);
    for (std::size_t j = 0; j < m; ++j)
      out[j0 + j] = static_cast<float>((sq_i + sq[j0 + j]) - 2.0 * acc[j]);
  }
}

namespace {
void rbf_row_from_distances_portable(const float* dist, std::size_t n, double gamma, float* out) {
  for (std::size_t j = 0; j < n; ++j)
    out[j] = static_cast<float>(exp_core(-gamma * static_cast<double>(dist[j])));
}

}  // namespace

#if FOGDRIFT_HAVE_AVX2_GATHER
namespace {
const bool kHasAvx2 = __builtin_cpu_supports("avx2");
const bool kHasAvx512 = __builtin_cpu_supports("avx512f");
}  // namespace
#endif

// Kernel rows with explicit AVX2 and AVX-512 code. They compute exactly what the portable rows
// compute: the same products and sums in the same order, no fused multiply-add, exp_core's
// polynomial lane by lane. IEEE arithmetic rounds each lane as it rounds a scalar, so every
// float of a row is bit for bit the portable one (kernel_test checks it), and a fit takes the
// same path on every processor. GCC does not vectorise exp_core's loop for AVX-512 by itself,
// and its AVX2 clone runs at half the speed of this code (16 µs against 9 µs a row of 6000 ×
// 9 with AVX-512).
#if FOGDRIFT_HAVE_AVX2_GATHER
// GCC 12 warns inside its own AVX-512 headers (GCC bug 105593; see the pair loops below).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
namespace {

constexpr double kExpCoefficients[] = {1.0 / 6227020800.0,
                                       1.0 / 479001600.0,
                                       1.0 / 39916800.0,
                                       1.0 / 3628800.0,
                                       1.0 / 362880.0,
                                       1.0 / 40320.0,
                                       1.0 / 5040.0,
                                       1.0 / 720.0,
                                       1.0 / 120.0,
                                       1.0 / 24.0,
                                       1.0 / 6.0,
                                       0.5,
                                       1.0,
                                       1.0};

// exp_core on eight lanes, rounded to float.
__attribute__((target("avx512f"))) inline __m256 exp_to_float_avx512(__m512d x) {
  x = _mm512_max_pd(x, _mm512_set1_pd(-700.0));
  x = _mm512_min_pd(x, _mm512_set1_pd(700.0));
  const __m512d shifter = _mm512_set1_pd(kShifter);
  const __m512d t = _mm512_add_pd(_mm512_mul_pd(x, _mm512_set1_pd(kLog2e)), shifter);
  const __m512d n = _mm512_sub_pd(t, shifter);
  const __m512d r = _mm512_sub_pd(_mm512_sub_pd(x, _mm512_mul_pd(n, _mm512_set1_pd(kLn2Hi))),
                                  _mm512_mul_pd(n, _mm512_set1_pd(kLn2Lo)));
  __m512d p = _mm512_set1_pd(kExpCoefficients[0]);
  for (std::size_t c = 1; c < std::size(kExpCoefficients); ++c)
    p = _mm512_add_pd(_mm512_mul_pd(p, r), _mm512_set1_pd(kExpCoefficients[c]));
  const __m512i k = _mm512_sub_epi64(_mm512_castpd_si512(t), _mm512_castpd_si512(shifter));
  const __m512d scale =
      _mm512_castsi512_pd(_mm512_slli_epi64(_mm512_add_epi64(k, _mm512_set1_epi64(1023)), 52));
  return _mm512_cvtpd_ps(_mm512_mul_pd(p, scale));
}

__attribute__((target("avx2"))) inline __m128 exp_to_float_avx2(__m256d x) {
  x = _mm256_max_pd(x, _mm256_set1_pd(-700.0));
  x = _mm256_min_pd(x, _mm256_set1_pd(700.0));
  const __m256d shifter = _mm256_set1_pd(kShifter);
  const __m256d t = _mm256_add_pd(_mm256_mul_pd(x, _mm256_set1_pd(kLog2e)), shifter);
  const __m256d n = _mm256_sub_pd(t, shifter);
  const __m256d r = _mm256_sub_pd(_mm256_sub_pd(x, _mm256_mul_pd(n, _mm256_set1_pd(kLn2Hi))),
                                  _mm256_mul_pd(n, _mm256_set1_pd(kLn2Lo)));
  __m256d p = _mm256_set1_pd(kExpCoefficients[0]);
  for (std::size_t c = 1; c < std::size(kExpCoefficients); ++c)
    p = _mm256_add_pd(_mm256_mul_pd(p, r), _mm256_set1_pd(kExpCoefficients[c]));
  const __m256i k = _mm256_sub_epi64(_mm256_castpd_si256(t), _mm256_castpd_si256(shifter));
  const __m256d scale =
      _mm256_castsi256_pd(_mm256_slli_epi64(_mm256_add_epi64(k, _mm256_set1_epi64x(1023)), 52));
  return _mm256_cvtpd_ps(_mm256_mul_pd(p, scale));
}

// Eight columns from j of an RBF row; `mask` selects the columns that exist (the others read
// nothing and compute a harmless value). Returns the eight floats.
__attribute__((target("avx512f"))) inline __m256 rbf_columns_avx512(
    const double* xi, __m512d sq_i, const double* xt, std::size_t stride, const double* sq,
    std::size_t d, __m512d minus_gamma, std::size_t j, __mmask8 mask) {
  __m512d acc = _mm512_setzero_pd();
  for (std::size_t f = 0; f < d; ++f)
    acc = _mm512_add_pd(acc, _mm512_mul_pd(_mm512_set1_pd(xi[f]),
                                           _mm512_maskz_loadu_pd(mask, xt + f * stride + j)));
  const __m512d dist = _mm512_sub_pd(_mm512_add_pd(sq_i, _mm512_maskz_loadu_pd(mask, sq + j)),
                                     _mm512_mul_pd(_mm512_set1_pd(2.0), acc));
  return exp_to_float_avx512(_mm512_mul_pd(minus_gamma, dist));
}

__attribute__((target("avx512f"))) void rbf_row_avx512(const double* xi, double sq_i,
                                                       const double* xt, std::size_t stride,
                                                       const double* sq, std::size_t n,
                                                       std::size_t d, double gamma, float* out) {
  const __m512d sqi = _mm512_set1_pd(sq_i);
  const __m512d minus_gamma = _mm512_set1_pd(-gamma);
  std::size_t j = 0;
  for (; j + 8 <= n; j += 8)
    _mm256_storeu_ps(out + j, rbf_columns_avx512(xi, sqi, xt, stride, sq, d, minus_gamma, j, 0xFF));
  if (j < n) {
    alignas(32) float tail[8];
    const auto mask = static_cast<__mmask8>((1u << (n - j)) - 1u);
    _mm256_store_ps(tail, rbf_columns_avx512(xi, sqi, xt, stride, sq, d, minus_gamma, j, mask));
    std::memcpy(out + j, tail, (n - j) * sizeof(float));
  }
}

__attribute__((target("avx512f"))) void rbf_row_from_distances_avx512(const float* dist,
                                                                      std::size_t n, double gamma,
                                                                      float* out) {
  const __m512d minus_gamma = _mm512_set1_pd(-gamma);
  std::size_t j = 0;
  for (; j + 8 <= n; j += 8)
    _mm256_storeu_ps(out + j, exp_to_float_avx512(_mm512_mul_pd(
                                  minus_gamma, _mm512_cvtps_pd(_mm256_loadu_ps(dist + j)))));
  rbf_row_from_distances_portable(dist + j, n - j, gamma, out + j);
}

// Four columns from `xt`, `sq` (pointing at the first of them).
__attribute__((target("avx2"))) inline __m128 rbf_columns_avx2(const double* xi, __m256d sq_i,
                                                               const double* xt, std::size_t stride,
                                                               const double* sq, std::size_t d,
                                                               __m256d minus_gamma) {
  __m256d acc = _mm256_setzero_pd();
  for (std::size_t f = 0; f < d; ++f)
    acc =
        _mm256_add_pd(acc, _mm256_mul_pd(_mm256_set1_pd(xi[f]), _mm256_loadu_pd(xt + f * stride)));
  const __m256d dist = _mm256_sub_pd(_mm256_add_pd(sq_i, _mm256_loadu_pd(sq)),
                                     _mm256_mul_pd(_mm256_set1_pd(2.0), acc));
  return exp_to_float_avx2(_mm256_mul_pd(minus_gamma, dist));
}

__attribute__((target("avx2"))) void rbf_row_avx2(const double* xi, double sq_i, const double* xt,
                                                  std::size_t stride, const double* sq,
                                                  std::size_t n, std::size_t d, double gamma,
                                                  float* out) {
  const __m256d sqi = _mm256_set1_pd(sq_i);
  const __m256d minus_gamma = _mm256_set1_pd(-gamma);
  std::size_t j = 0;
  for (; j + 4 <= n; j += 4)
    _mm_storeu_ps(out + j, rbf_columns_avx2(xi, sqi, xt + j, stride, sq + j, d, minus_gamma));
  rbf_row_portable(xi, sq_i, xt + j, stride, sq + j, n - j, d, gamma, out + j);
}

__attribute__((target("avx2"))) void rbf_row_from_distances_avx2(const float* dist, std::size_t n,
                                                                 double gamma, float* out) {
  const __m256d minus_gamma = _mm256_set1_pd(-gamma);
  std::size_t j = 0;
  for (; j + 4 <= n; j += 4)
    _mm_storeu_ps(out + j, exp_to_float_avx2(_mm256_mul_pd(
                               minus_gamma, _mm256_cvtps_pd(_mm_loadu_ps(dist + j)))));
  rbf_row_from_distances_portable(dist + j, n - j, gamma, out + j);
}

}  // namespace
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#endif

void rbf_row(const double* xi, double sq_i, const double* xt, std::size_t stride, const double* sq,
             std::size_t n, std::size_t d, double gamma, float* out) {
  rbf_row_with(best_isa(), xi, sq_i, xt, stride, sq, n, d, gamma, out);
}

void rbf_row_from_distances(const float* dist, std::size_t n, double gamma, float* out) {
  rbf_row_from_distances_with(best_isa(), dist, n, gamma, out);
}

void rbf_row_with(Isa isa, const double* xi, double sq_i, const double* xt, std::size_t stride,
                  const double* sq, std::size_t n, std::size_t d, double gamma, float* out) {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (isa == Isa::avx512 && kHasAvx512)
    return rbf_row_avx512(xi, sq_i, xt, stride, sq, n, d, gamma, out);
  if (isa == Isa::avx2 && kHasAvx2) return rbf_row_avx2(xi, sq_i, xt, stride, sq, n, d, gamma, out);
#endif
  (void)isa;
  rbf_row_portable(xi, sq_i, xt, stride, sq, n, d, gamma, out);
}

void rbf_row_from_distances_with(Isa isa, const float* dist, std::size_t n, double gamma,
                                 float* out) {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (isa == Isa::avx512 && kHasAvx512) return rbf_row_from_distances_avx512(dist, n, gamma, out);
  if (isa == Isa::avx2 && kHasAvx2) return rbf_row_from_distances_avx2(dist, n, gamma, out);
#endif
  (void)isa;
  rbf_row_from_distances_portable(dist, n, gamma, out);
}

// A plain indexed copy: AVX2's gather instruction is no faster than scalar loads on the AMD
// processors this was measured on, and rows are gathered rarely (see RowsInSolverOrder).
void gather(const float* row, const std::int32_t* index, std::size_t begin, std::size_t end,
            float* out) {
  for (std::size_t j = begin; j < end; ++j) out[j] = row[index[j]];
}

FOGDRIFT_CLONES
void update_gradient(double* g, const std::int8_t* y, const float* k_i, const float* k_j,
                     double a_i, double a_j, std::size_t len) {
  for (std::size_t k = 0; k < len; ++k)
    g[k] += static_cast<double>(y[k]) *
            (static_cast<double>(k_i[k]) * a_i + static_cast<double>(k_j[k]) * a_j);
}

FOGDRIFT_CLONES
void add_scaled(double* g, const std::int8_t* y, const float* k_row, double a, std::size_t begin,
                std::size_t end) {
  for (std::size_t k = begin; k < end; ++k)
    g[k] += static_cast<double>(y[k]) * (a * static_cast<double>(k_row[k]));
}

namespace {
// t ∈ I_up: α_t may grow along y_t (LIBSVM: y=+1 not at the upper bound, y=−1 not at the lower).
// Written with & and | rather than ?: or && so that the loops have no branches and vectorise.
inline bool in_up(std::int8_t y, std::uint8_t s) {
  return ((y > 0) & (s != kUpperBound)) | ((y < 0) & (s != kLowerBound));
}
inline bool in_low(std::int8_t y, std::uint8_t s) {
  return ((y > 0) & (s != kLowerBound)) | ((y < 0) & (s != kUpperBound));
}
}  // namespace

namespace {
Selection select_i_portable(const double* g, const std::int8_t* y, const std::uint8_t* status,
                            std::size_t len) {
  double best = -DBL_MAX;
  for (std::size_t t = 0; t < len; ++t) {
    const double v = -static_cast<double>(y[t]) * g[t];
    const double c = in_up(y[t], status[t]) ? v : -DBL_MAX;
    best = c > best ? c : best;
  }
  // LIBSVM keeps the last maximiser (its test is >=); find it from the end.
  for (std::size_t t = len; t-- > 0;) {
    if (in_up(y[t], status[t]) && -static_cast<double>(y[t]) * g[t] == best)
      return {best, static_cast<std::int64_t>(t)};
  }
  return {-DBL_MAX, -1};
}
}  // namespace

namespace {
// The curvature of the two-variable subproblem, τ when not positive (LIBSVM's quad_coef).
inline double curvature(double qd_i, double qd_j, float k_ij, double tau) {
  const double quad = (qd_i + qd_j) - 2.0 * static_cast<double>(k_ij);
  return quad > 0 ? quad : tau;
}

inline double objective_decrease(double grad_diff, double qd_i, double qd_j, float k_ij,
                                 double tau) {
  const double quad = (qd_i + qd_j) - 2.0 * static_cast<double>(k_ij);
  return -(grad_diff * grad_diff) / (quad > 0 ? quad : tau);
}

SelectionJ select_j_portable(const double* g, const std::int8_t* y, const std::uint8_t* status,
                             const float* k_i, const double* qd, double qd_i, double g_max,
                             double tau, std::size_t len) {
  double g_max2 = -DBL_MAX;
  double obj_min = DBL_MAX;
  for (std::size_t j = 0; j < len; ++j) {
    const bool low = in_low(y[j], status[j]);
    const double yg = static_cast<double>(y[j]) * g[j];
    const double c2 = low ? yg : -DBL_MAX;
    g_max2 = c2 > g_max2 ? c2 : g_max2;
    const double grad_diff = g_max + yg;
    const double obj = objective_decrease(grad_diff, qd_i, qd[j], k_i[j], tau);
    const double c = (low & (grad_diff > 0)) ? obj : DBL_MAX;
    obj_min = c < obj_min ? c : obj_min;
  }
  SelectionJ out;
  out.g_max2 = g_max2;
  if (obj_min == DBL_MAX) return out;
  // LIBSVM keeps the last minimiser (its test is <=).
  for (std::size_t j = len; j-- > 0;) {
    if (!in_low(y[j], status[j])) continue;
    const double grad_diff = g_max + static_cast<double>(y[j]) * g[j];
    if (!(grad_diff > 0)) continue;
    if (objective_decrease(grad_diff, qd_i, qd[j], k_i[j], tau) == obj_min) {
      out.index = static_cast<std::int64_t>(j);
      break;
    }
  }
  return out;
}

// update_and_select_up over [begin, len), continuing from `out`; the portable version, and the
// tail of the vectorised one.
template <bool kUpdate>
void update_and_select_up_scalar(double* f, const double* up, const float* k_i, const float* k_j,
                                 double b_i, double b_j, std::size_t begin, std::size_t len,
                                 Selection& out) {
  for (std::size_t k = begin; k < len; ++k) {
    if constexpr (kUpdate)
      f[k] += static_cast<double>(k_i[k]) * b_i + static_cast<double>(k_j[k]) * b_j;
    const double v = up[k] - f[k];
    if (v >= out.value) out = {v, static_cast<std::int64_t>(k)};
  }
}

// No sample offers a variable when the best value is a kNoVariable offset.
Selection none_if_offsets_only(const Selection& s) {
  return s.value < kNoVariable / 2 ? Selection{-DBL_MAX, -1} : s;
}

template <bool kUpdate>
Selection update_and_select_up_portable(double* f, const double* up, const float* k_i,
                                        const float* k_j, double b_i, double b_j, std::size_t len) {
  Selection out{-DBL_MAX, -1};
  update_and_select_up_scalar<kUpdate>(f, up, k_i, k_j, b_i, b_j, 0, len, out);
  return none_if_offsets_only(out);
}

// conjugate_update_and_select_up over [begin, len), continuing from `out`.
void conjugate_scalar(double* f, const double* up, const float* k_i, const float* k_j, double* kd,
                      double lambda, double t, std::size_t begin, std::size_t len, Selection& out) {
  for (std::size_t k = begin; k < len; ++k) {
    const double q = (static_cast<double>(k_i[k]) - static_cast<double>(k_j[k])) + lambda * kd[k];
    kd[k] = q;
    f[k] += t * q;
    const double v = up[k] - f[k];
    if (v >= out.value) out = {v, static_cast<std::int64_t>(k)};
  }
}

Selection conjugate_portable(double* f, const double* up, const float* k_i, const float* k_j,
                             double* kd, double lambda, double t, std::size_t len) {
  Selection out{-DBL_MAX, -1};
  conjugate_scalar(f, up, k_i, k_j, kd, lambda, t, 0, len, out);
  return none_if_offsets_only(out);
}

#if FOGDRIFT_HAVE_AVX2_GATHER
// Merging per-lane results of the vectorised loops (arrays of `lanes` values; index −1: none):
// the last maximiser, and the best gain num/den (cross-multiplied, the larger index on ties).
void merge_max(const double* value, const double* index, int lanes, Selection& out) {
  for (int t = 0; t < lanes; ++t) {
    if (index[t] < 0) continue;
    const auto idx = static_cast<std::int64_t>(index[t]);
    if (value[t] > out.value || (value[t] == out.value && idx > out.index)) out = {value[t], idx};
  }
}

void merge_gain(const double* num, const double* den, const double* index, const double* g_max2,
                int lanes, SelectionJ& out, double& num_max, double& den_max) {
  for (int t = 0; t < lanes; ++t) {
    out.g_max2 = std::max(out.g_max2, g_max2[t]);
    if (index[t] < 0) continue;
    const auto idx = static_cast<std::int64_t>(index[t]);
    const double lhs = num[t] * den_max, rhs = num_max * den[t];
    if (lhs > rhs || (lhs == rhs && idx > out.index)) {
      num_max = num[t];
      den_max = den[t];
      out.index = idx;
    }
  }
}
#endif

// select_low over [begin, len), continuing from `out` and the best gain so far num/den; the
// portable version, and the tail of the vectorised one.
void select_low_scalar(const double* f, const double* low, const float* k_i, const double* qd,
                       double qd_i, double g_max, double tau, std::size_t begin, std::size_t len,
                       SelectionJ& out, double& best_num, double& best_den) {
  for (std::size_t k = begin; k < len; ++k) {
    const double yg = f[k] + low[k];
    out.g_max2 = yg > out.g_max2 ? yg : out.g_max2;
    const double grad_diff = g_max + yg;
    if (!(grad_diff > 0)) continue;
    const double num = grad_diff * grad_diff, den = curvature(qd_i, qd[k], k_i[k], tau);
    if (num * best_den >= best_num * den) {
      best_num = num;
      best_den = den;
      out.index = static_cast<std::int64_t>(k);
    }
  }
}

SelectionJ select_low_portable(const double* f, const double* low, const float* k_i,
                               const double* qd, double qd_i, double g_max, double tau,
                               std::size_t len) {
  SelectionJ out;
  out.g_max2 = -DBL_MAX;
  double best_num = 0, best_den = 1;  // the best gain so far, (G_max + y·G)² / curvature
  select_low_scalar(f, low, k_i, qd, qd_i, g_max, tau, 0, len, out, best_num, best_den);
  return out;
}

#if FOGDRIFT_HAVE_AVX2_GATHER
// AVX2 versions of the selections: four variables at a time, each lane remembering its last
// maximiser (minimiser), lanes merged so that the overall last one wins, as in LIBSVM.
// GCC does not if-convert the portable loops, hence the intrinsics.
__attribute__((target("avx2"))) inline __m256d load_y(const std::int8_t* y) {
  std::int32_t packed;
  std::memcpy(&packed, y, sizeof packed);
  return _mm256_cvtepi32_pd(_mm_cvtepi8_epi32(_mm_cvtsi32_si128(packed)));
}

// Masks (all-ones 64-bit lanes) of I_up and I_low for four variables.
__attribute__((target("avx2"))) inline void load_masks(const std::int8_t* y,
                                                       const std::uint8_t* status, __m256d& up,
                                                       __m256d& low) {
  std::int32_t py, ps;
  std::memcpy(&py, y, sizeof py);
  std::memcpy(&ps, status, sizeof ps);
  const __m128i yy = _mm_cvtepi8_epi32(_mm_cvtsi32_si128(py));
  const __m128i ss = _mm_cvtepu8_epi32(_mm_cvtsi32_si128(ps));
  const __m128i pos = _mm_cmpgt_epi32(yy, _mm_setzero_si128());
  const __m128i at_upper = _mm_cmpeq_epi32(ss, _mm_set1_epi32(kUpperBound));
  const __m128i at_lower = _mm_cmpeq_epi32(ss, _mm_set1_epi32(kLowerBound));
  // y > 0: up ⇔ not at upper, low ⇔ not at lower; y < 0: the other way round.
  const __m128i up32 =
      _mm_andnot_si128(_mm_blendv_epi8(at_lower, at_upper, pos), _mm_set1_epi32(-1));
  const __m128i low32 =
      _mm_andnot_si128(_mm_blendv_epi8(at_upper, at_lower, pos), _mm_set1_epi32(-1));
  up = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(up32));
  low = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(low32));
}

// The last maximiser over four lanes, each holding its own last maximiser (index −1: none).
__attribute__((target("avx2"))) Selection merge_lanes_max(__m256d best, __m256d best_index) {
  alignas(32) double bv[4], bi[4];
  _mm256_store_pd(bv, best);
  _mm256_store_pd(bi, best_index);
  Selection out{-DBL_MAX, -1};
  merge_max(bv, bi, 4, out);
  return out;
}

__attribute__((target("avx2"))) Selection select_i_avx2(const double* g, const std::int8_t* y,
                                                        const std::uint8_t* status,
                                                        std::size_t len) {
  __m256d best = _mm256_set1_pd(-DBL_MAX);
  __m256d best_index = _mm256_set1_pd(-1.0);
  __m256d index = _mm256_setr_pd(0, 1, 2, 3);
  const __m256d four = _mm256_set1_pd(4.0);
  const __m256d floor = _mm256_set1_pd(-DBL_MAX);
  std::size_t t = 0;
  for (; t + 4 <= len; t += 4) {
    __m256d up, low;
    load_masks(y + t, status + t, up, low);
    const __m256d v =
        _mm256_mul_pd(_mm256_sub_pd(_mm256_setzero_pd(), load_y(y + t)), _mm256_loadu_pd(g + t));
    const __m256d c = _mm256_blendv_pd(floor, v, up);
    const __m256d take = _mm256_and_pd(_mm256_cmp_pd(c, best, _CMP_GE_OQ), up);
    best = _mm256_blendv_pd(best, c, take);
    best_index = _mm256_blendv_pd(best_index, index, take);
    index = _mm256_add_pd(index, four);
  }
  Selection out = merge_lanes_max(best, best_index);
  for (; t < len; ++t) {
    if (!in_up(y[t], status[t])) continue;
    const double v = -static_cast<double>(y[t]) * g[t];
    if (v >= out.value) out = {v, static_cast<std::int64_t>(t)};
  }
  return out;
}

__attribute__((target("avx2"))) SelectionJ select_j_avx2(const double* g, const std::int8_t* y,
                                                         const std::uint8_t* status,
                                                         const float* k_i, const double* qd,
                                                         double qd_i, double g_max, double tau,
                                                         std::size_t len) {
  __m256d g_max2 = _mm256_set1_pd(-DBL_MAX);
  __m256d best = _mm256_set1_pd(DBL_MAX);
  __m256d best_index = _mm256_set1_pd(-1.0);
  __m256d index = _mm256_setr_pd(0, 1, 2, 3);
  const __m256d four = _mm256_set1_pd(4.0);
  const __m256d gm = _mm256_set1_pd(g_max);
  const __m256d qdi = _mm256_set1_pd(qd_i);
  const __m256d two = _mm256_set1_pd(2.0);
  const __m256d tau4 = _mm256_set1_pd(tau);
  const __m256d zero = _mm256_setzero_pd();
  const __m256d sign = _mm256_set1_pd(-0.0);
  std::size_t j = 0;
  for (; j + 4 <= len; j += 4) {
    __m256d up, low;
    load_masks(y + j, status + j, up, low);
    const __m256d yj = load_y(y + j);
    const __m256d yg = _mm256_mul_pd(yj, _mm256_loadu_pd(g + j));
    g_max2 = _mm256_max_pd(g_max2, _mm256_blendv_pd(_mm256_set1_pd(-DBL_MAX), yg, low));
    const __m256d gd = _mm256_add_pd(gm, yg);
    const __m256d kij = _mm256_cvtps_pd(_mm_loadu_ps(k_i + j));
    const __m256d quad =
        _mm256_sub_pd(_mm256_add_pd(qdi, _mm256_loadu_pd(qd + j)), _mm256_mul_pd(two, kij));
    const __m256d denom = _mm256_blendv_pd(tau4, quad, _mm256_cmp_pd(quad, zero, _CMP_GT_OQ));
    const __m256d obj = _mm256_div_pd(_mm256_xor_pd(_mm256_mul_pd(gd, gd), sign), denom);
    const __m256d ok = _mm256_and_pd(low, _mm256_cmp_pd(gd, zero, _CMP_GT_OQ));
    const __m256d take = _mm256_and_pd(_mm256_cmp_pd(obj, best, _CMP_LE_OQ), ok);
    best = _mm256_blendv_pd(best, obj, take);
    best_index = _mm256_blendv_pd(best_index, index, take);
    index = _mm256_add_pd(index, four);
  }
  alignas(32) double bv[4], bi[4], m2[4];
  _mm256_store_pd(bv, best);
  _mm256_store_pd(bi, best_index);
  _mm256_store_pd(m2, g_max2);
  SelectionJ out;
  out.g_max2 = std::max(std::max(m2[0], m2[1]), std::max(m2[2], m2[3]));
  double obj_min = DBL_MAX;
  for (int k = 0; k < 4; ++k) {
    if (bi[k] < 0) continue;
    const auto idx = static_cast<std::int64_t>(bi[k]);
    if (bv[k] < obj_min || (bv[k] == obj_min && idx > out.index)) {
      obj_min = bv[k];
      out.index = idx;
    }
  }
  for (; j < len; ++j) {
    if (!in_low(y[j], status[j])) continue;
    const double yg = static_cast<double>(y[j]) * g[j];
    out.g_max2 = std::max(out.g_max2, yg);
    const double grad_diff = g_max + yg;
    if (!(grad_diff > 0)) continue;
    const double obj = objective_decrease(grad_diff, qd_i, qd[j], k_i[j], tau);
    if (obj <= obj_min) {
      obj_min = obj;
      out.index = static_cast<std::int64_t>(j);
    }
  }
  return out;
}

// The pair solver's loops (see loops.hpp), four samples at a time in the same way.

// The running last maximum of v over four lanes (samples k … k+3), and the merge of two sets of
// lanes at the end.
__attribute__((target("avx2"))) inline void keep_last_max(__m256d v, std::size_t k, __m256d& best,
                                                          __m256d& best_index) {
  const __m256d take = _mm256_cmp_pd(v, best, _CMP_GE_OQ);
  best = _mm256_blendv_pd(best, v, take);
  const __m256d index =
      _mm256_add_pd(_mm256_set1_pd(static_cast<double>(k)), _mm256_setr_pd(0, 1, 2, 3));
  best_index = _mm256_blendv_pd(best_index, index, take);
}

__attribute__((target("avx2"))) inline Selection merge_two_sets(const __m256d best[2],
                                                                const __m256d best_index[2]) {
  Selection out = merge_lanes_max(best[0], best_index[0]);
  const Selection other = merge_lanes_max(best[1], best_index[1]);
  if (other.index >= 0 &&
      (other.value > out.value || (other.value == out.value && other.index > out.index)))
    out = other;
  return out;
}

// One block of four for update_and_select_up_avx2: the update, then the running last maximum.
template <bool kUpdate>
__attribute__((target("avx2"))) inline void up_block(double* f, const double* up, const float* k_i,
                                                     const float* k_j, __m256d bi, __m256d bj,
                                                     std::size_t k, __m256d& best,
                                                     __m256d& best_index) {
  __m256d fk = _mm256_loadu_pd(f + k);
  if constexpr (kUpdate) {
    const __m256d ki = _mm256_cvtps_pd(_mm_loadu_ps(k_i + k));
    const __m256d kj = _mm256_cvtps_pd(_mm_loadu_ps(k_j + k));
    fk = _mm256_add_pd(fk, _mm256_add_pd(_mm256_mul_pd(ki, bi), _mm256_mul_pd(kj, bj)));
    _mm256_storeu_pd(f + k, fk);
  }
  keep_last_max(_mm256_sub_pd(_mm256_loadu_pd(up + k), fk), k, best, best_index);
}

// Two independent sets of lanes, so that one set's compare-and-blend chain does not stall the
// next block.
template <bool kUpdate>
__attribute__((target("avx2"))) Selection update_and_select_up_avx2(double* f, const double* up,
                                                                    const float* k_i,
                                                                    const float* k_j, double b_i,
                                                                    double b_j, std::size_t len) {
  __m256d best[2] = {_mm256_set1_pd(-DBL_MAX), _mm256_set1_pd(-DBL_MAX)};
  __m256d best_index[2] = {_mm256_set1_pd(-1.0), _mm256_set1_pd(-1.0)};
  const __m256d bi = _mm256_set1_pd(b_i);
  const __m256d bj = _mm256_set1_pd(b_j);
  std::size_t k = 0;
  for (; k + 8 <= len; k += 8) {
    up_block<kUpdate>(f, up, k_i, k_j, bi, bj, k, best[0], best_index[0]);
    up_block<kUpdate>(f, up, k_i, k_j, bi, bj, k + 4, best[1], best_index[1]);
  }
  Selection out = merge_two_sets(best, best_index);
  update_and_select_up_scalar<kUpdate>(f, up, k_i, k_j, b_i, b_j, k, len, out);
  return none_if_offsets_only(out);
}

// conjugate_update_and_select_up four samples at a time, in two sets of lanes as above.
__attribute__((target("avx2"))) inline void conjugate_block(double* f, const double* up,
                                                            const float* k_i, const float* k_j,
                                                            double* kd, __m256d lambda, __m256d t,
                                                            std::size_t k, __m256d& best,
                                                            __m256d& best_index) {
  const __m256d ki = _mm256_cvtps_pd(_mm_loadu_ps(k_i + k));
  const __m256d kj = _mm256_cvtps_pd(_mm_loadu_ps(k_j + k));
  const __m256d q =
      _mm256_add_pd(_mm256_sub_pd(ki, kj), _mm256_mul_pd(lambda, _mm256_loadu_pd(kd + k)));
  _mm256_storeu_pd(kd + k, q);
  const __m256d fk = _mm256_add_pd(_mm256_loadu_pd(f + k), _mm256_mul_pd(t, q));
  _mm256_storeu_pd(f + k, fk);
  keep_last_max(_mm256_sub_pd(_mm256_loadu_pd(up + k), fk), k, best, best_index);
}

__attribute__((target("avx2"))) Selection conjugate_avx2(double* f, const double* up,
                                                         const float* k_i, const float* k_j,
                                                         double* kd, double lambda, double t,
                                                         std::size_t len) {
  __m256d best[2] = {_mm256_set1_pd(-DBL_MAX), _mm256_set1_pd(-DBL_MAX)};
  __m256d best_index[2] = {_mm256_set1_pd(-1.0), _mm256_set1_pd(-1.0)};
  const __m256d l = _mm256_set1_pd(lambda);
  const __m256d tv = _mm256_set1_pd(t);
  std::size_t k = 0;
  for (; k + 8 <= len; k += 8) {
    conjugate_block(f, up, k_i, k_j, kd, l, tv, k, best[0], best_index[0]);
    conjugate_block(f, up, k_i, k_j, kd, l, tv, k + 4, best[1], best_index[1]);
  }
  Selection out = merge_two_sets(best, best_index);
  conjugate_scalar(f, up, k_i, k_j, kd, lambda, t, k, len, out);
  return none_if_offsets_only(out);
}

// Compares gains by cross-multiplication, num·best_den ≥ best_num·den, instead of dividing (the
// division was the slowest instruction of the loop), in four independent sets of lanes so that
// the compare-and-blend chain of one set does not stall the next block.
struct GainLanes {
  __m256d num, den, index;
};

__attribute__((target("avx2"))) inline void gain_block(const double* f, const double* low,
                                                       const float* k_i, const double* qd,
                                                       std::size_t k, __m256d gm, __m256d qdi,
                                                       __m256d tau, __m256d& g_max2,
                                                       GainLanes& best) {
  const __m256d two = _mm256_set1_pd(2.0);
  const __m256d zero = _mm256_setzero_pd();
  const __m256d yg = _mm256_add_pd(_mm256_loadu_pd(f + k), _mm256_loadu_pd(low + k));
  g_max2 = _mm256_max_pd(g_max2, yg);
  const __m256d gd = _mm256_add_pd(gm, yg);
  const __m256d kik = _mm256_cvtps_pd(_mm_loadu_ps(k_i + k));
  const __m256d quad =
      _mm256_sub_pd(_mm256_add_pd(qdi, _mm256_loadu_pd(qd + k)), _mm256_mul_pd(two, kik));
  const __m256d den = _mm256_blendv_pd(tau, quad, _mm256_cmp_pd(quad, zero, _CMP_GT_OQ));
  const __m256d num = _mm256_mul_pd(gd, gd);
  const __m256d better =
      _mm256_cmp_pd(_mm256_mul_pd(num, best.den), _mm256_mul_pd(best.num, den), _CMP_GE_OQ);
  const __m256d take = _mm256_and_pd(better, _mm256_cmp_pd(gd, zero, _CMP_GT_OQ));
  best.num = _mm256_blendv_pd(best.num, num, take);
  best.den = _mm256_blendv_pd(best.den, den, take);
  const __m256d index =
      _mm256_add_pd(_mm256_set1_pd(static_cast<double>(k)), _mm256_setr_pd(0, 1, 2, 3));
  best.index = _mm256_blendv_pd(best.index, index, take);
}

__attribute__((target("avx2"))) SelectionJ select_low_avx2(const double* f, const double* low,
                                                           const float* k_i, const double* qd,
                                                           double qd_i, double g_max, double tau,
                                                           std::size_t len) {
  const __m256d gm = _mm256_set1_pd(g_max);
  const __m256d qdi = _mm256_set1_pd(qd_i);
  __m256d g_max2[4];
  GainLanes best[4];
  for (int s = 0; s < 4; ++s) {
    g_max2[s] = _mm256_set1_pd(-DBL_MAX);
    best[s] = {_mm256_setzero_pd(), _mm256_set1_pd(1.0), _mm256_set1_pd(-1.0)};
  }
  const __m256d tau4 = _mm256_set1_pd(tau);
  std::size_t k = 0;
  for (; k + 16 <= len; k += 16)
    for (int s = 0; s < 4; ++s)
      gain_block(f, low, k_i, qd, k + 4 * s, gm, qdi, tau4, g_max2[s], best[s]);
  SelectionJ out;
  out.g_max2 = -DBL_MAX;
  double num_max = 0, den_max = 1;
  for (int s = 0; s < 4; ++s) {
    alignas(32) double bn[4], bd[4], bi[4], m2[4];
    _mm256_store_pd(bn, best[s].num);
    _mm256_store_pd(bd, best[s].den);
    _mm256_store_pd(bi, best[s].index);
    _mm256_store_pd(m2, g_max2[s]);
    merge_gain(bn, bd, bi, m2, 4, out, num_max, den_max);
  }
  select_low_scalar(f, low, k_i, qd, qd_i, g_max, tau, k, len, out, num_max, den_max);
  return out;
}

// AVX-512 versions of the pair loops: eight samples a vector, two independent lane sets.
// GCC 12 warns inside its own AVX-512 headers that their undefined pass-through operand may be
// used uninitialised (GCC bug 105593); it is not.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
__attribute__((target("avx512f"))) inline __m512d iota8(std::size_t k) {
  return _mm512_add_pd(_mm512_set1_pd(static_cast<double>(k)),
                       _mm512_setr_pd(0, 1, 2, 3, 4, 5, 6, 7));
}

__attribute__((target("avx512f"))) inline void keep_last_max(__m512d v, __m512d at, __m512d& best,
                                                             __m512d& best_index) {
  const __mmask8 take = _mm512_cmp_pd_mask(v, best, _CMP_GE_OQ);
  best = _mm512_mask_blend_pd(take, best, v);
  best_index = _mm512_mask_blend_pd(take, best_index, at);
}

__attribute__((target("avx512f"))) inline Selection merge_two_sets(const __m512d best[2],
                                                                   const __m512d best_index[2]) {
  Selection out{-DBL_MAX, -1};
  for (int s = 0; s < 2; ++s) {
    alignas(64) double bv[8], bx[8];
    _mm512_store_pd(bv, best[s]);
    _mm512_store_pd(bx, best_index[s]);
    merge_max(bv, bx, 8, out);
  }
  return out;
}

__attribute__((target("avx512f"))) Selection conjugate_avx512(double* f, const double* up,
                                                              const float* k_i, const float* k_j,
                                                              double* kd, double lambda, double t,
                                                              std::size_t len) {
  __m512d best[2] = {_mm512_set1_pd(-DBL_MAX), _mm512_set1_pd(-DBL_MAX)};
  __m512d best_index[2] = {_mm512_set1_pd(-1.0), _mm512_set1_pd(-1.0)};
  const __m512d l = _mm512_set1_pd(lambda);
  const __m512d tv = _mm512_set1_pd(t);
  std::size_t k = 0;
  __m512d idx[2] = {iota8(0), iota8(8)};
  const __m512d sixteen = _mm512_set1_pd(16.0);
  for (; k + 16 <= len; k += 16) {
    for (int s = 0; s < 2; ++s) {
      const std::size_t at = k + 8 * static_cast<std::size_t>(s);
      const __m512d ki = _mm512_cvtps_pd(_mm256_loadu_ps(k_i + at));
      const __m512d kj = _mm512_cvtps_pd(_mm256_loadu_ps(k_j + at));
      const __m512d q =
          _mm512_add_pd(_mm512_sub_pd(ki, kj), _mm512_mul_pd(l, _mm512_loadu_pd(kd + at)));
      _mm512_storeu_pd(kd + at, q);
      const __m512d fk = _mm512_add_pd(_mm512_loadu_pd(f + at), _mm512_mul_pd(tv, q));
      _mm512_storeu_pd(f + at, fk);
      keep_last_max(_mm512_sub_pd(_mm512_loadu_pd(up + at), fk), idx[s], best[s], best_index[s]);
      idx[s] = _mm512_add_pd(idx[s], sixteen);
    }
  }
  Selection out = merge_two_sets(best, best_index);
  conjugate_scalar(f, up, k_i, k_j, kd, lambda, t, k, len, out);
  return none_if_offsets_only(out);
}

template <bool kUpdate>
__attribute__((target("avx512f"))) Selection update_and_select_up_avx512(
    double* f, const double* up, const float* k_i, const float* k_j, double b_i, double b_j,
    std::size_t len) {
  __m512d best[2] = {_mm512_set1_pd(-DBL_MAX), _mm512_set1_pd(-DBL_MAX)};
  __m512d best_index[2] = {_mm512_set1_pd(-1.0), _mm512_set1_pd(-1.0)};
  const __m512d bi = _mm512_set1_pd(b_i);
  const __m512d bj = _mm512_set1_pd(b_j);
  std::size_t k = 0;
  __m512d idx[2] = {iota8(0), iota8(8)};
  const __m512d sixteen = _mm512_set1_pd(16.0);
  for (; k + 16 <= len; k += 16) {
    for (int s = 0; s < 2; ++s) {
      const std::size_t at = k + 8 * static_cast<std::size_t>(s);
      __m512d fk = _mm512_loadu_pd(f + at);
      if constexpr (kUpdate) {
        const __m512d ki = _mm512_cvtps_pd(_mm256_loadu_ps(k_i + at));
        const __m512d kj = _mm512_cvtps_pd(_mm256_loadu_ps(k_j + at));
        fk = _mm512_add_pd(fk, _mm512_add_pd(_mm512_mul_pd(ki, bi), _mm512_mul_pd(kj, bj)));
        _mm512_storeu_pd(f + at, fk);
      }
      keep_last_max(_mm512_sub_pd(_mm512_loadu_pd(up + at), fk), idx[s], best[s], best_index[s]);
      idx[s] = _mm512_add_pd(idx[s], sixteen);
    }
  }
  Selection out = merge_two_sets(best, best_index);
  update_and_select_up_scalar<kUpdate>(f, up, k_i, k_j, b_i, b_j, k, len, out);
  return none_if_offsets_only(out);
}

__attribute__((target("avx512f"))) SelectionJ select_low_avx512(const double* f, const double* low,
                                                                const float* k_i, const double* qd,
                                                                double qd_i, double g_max,
                                                                double tau, std::size_t len) {
  const __m512d gm = _mm512_set1_pd(g_max);
  const __m512d qdi = _mm512_set1_pd(qd_i);
  const __m512d two = _mm512_set1_pd(2.0);
  const __m512d tau8 = _mm512_set1_pd(tau);
  const __m512d zero = _mm512_setzero_pd();
  __m512d g_max2[2], num[2], den[2], index[2];
  for (int s = 0; s < 2; ++s) {
    g_max2[s] = _mm512_set1_pd(-DBL_MAX);
    num[s] = zero;
    den[s] = _mm512_set1_pd(1.0);
    index[s] = _mm512_set1_pd(-1.0);
  }
  std::size_t k = 0;
  __m512d idx[2] = {iota8(0), iota8(8)};
  const __m512d sixteen = _mm512_set1_pd(16.0);
  for (; k + 16 <= len; k += 16) {
    for (int s = 0; s < 2; ++s) {
      const std::size_t at = k + 8 * static_cast<std::size_t>(s);
      const __m512d yg = _mm512_add_pd(_mm512_loadu_pd(f + at), _mm512_loadu_pd(low + at));
      g_max2[s] = _mm512_max_pd(g_max2[s], yg);
      const __m512d gd = _mm512_add_pd(gm, yg);
      const __m512d kik = _mm512_cvtps_pd(_mm256_loadu_ps(k_i + at));
      const __m512d quad =
          _mm512_sub_pd(_mm512_add_pd(qdi, _mm512_loadu_pd(qd + at)), _mm512_mul_pd(two, kik));
      const __m512d d =
          _mm512_mask_blend_pd(_mm512_cmp_pd_mask(quad, zero, _CMP_GT_OQ), tau8, quad);
      const __m512d n = _mm512_mul_pd(gd, gd);
      const __mmask8 take =
          _mm512_cmp_pd_mask(_mm512_mul_pd(n, den[s]), _mm512_mul_pd(num[s], d), _CMP_GE_OQ) &
          _mm512_cmp_pd_mask(gd, zero, _CMP_GT_OQ);
      num[s] = _mm512_mask_blend_pd(take, num[s], n);
      den[s] = _mm512_mask_blend_pd(take, den[s], d);
      index[s] = _mm512_mask_blend_pd(take, index[s], idx[s]);
      idx[s] = _mm512_add_pd(idx[s], sixteen);
    }
  }
  SelectionJ out;
  out.g_max2 = -DBL_MAX;
  double num_max = 0, den_max = 1;
  for (int s = 0; s < 2; ++s) {
    alignas(64) double bn[8], bd[8], bx[8], m2[8];
    _mm512_store_pd(bn, num[s]);
    _mm512_store_pd(bd, den[s]);
    _mm512_store_pd(bx, index[s]);
    _mm512_store_pd(m2, g_max2[s]);
    merge_gain(bn, bd, bx, m2, 8, out, num_max, den_max);
  }
  select_low_scalar(f, low, k_i, qd, qd_i, g_max, tau, k, len, out, num_max, den_max);
  return out;
}
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#endif
}  // namespace

Selection select_i(const double* g, const std::int8_t* y, const std::uint8_t* status,
                   std::size_t len) {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (kHasAvx2) return select_i_avx2(g, y, status, len);
#endif
  return select_i_portable(g, y, status, len);
}

SelectionJ select_j(const double* g, const std::int8_t* y, const std::uint8_t* status,
                    const float* k_i, const double* qd, double qd_i, double g_max, double tau,
                    std::size_t len) {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (kHasAvx2) return select_j_avx2(g, y, status, k_i, qd, qd_i, g_max, tau, len);
#endif
  return select_j_portable(g, y, status, k_i, qd, qd_i, g_max, tau, len);
}

Selection select_i_reference(const double* g, const std::int8_t* y, const std::uint8_t* status,
                             std::size_t len) {
  return select_i_portable(g, y, status, len);
}
SelectionJ select_j_reference(const double* g, const std::int8_t* y, const std::uint8_t* status,
                              const float* k_i, const double* qd, double qd_i, double g_max,
                              double tau, std::size_t len) {
  return select_j_portable(g, y, status, k_i, qd, qd_i, g_max, tau, len);
}

Selection select_up(const double* f, const double* up, std::size_t len) {
  // The fused loop without its update; f is only read.
  double* g = const_cast<double*>(f);
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (kHasAvx512) return update_and_select_up_avx512<false>(g, up, nullptr, nullptr, 0.0, 0.0, len);
  if (kHasAvx2) return update_and_select_up_avx2<false>(g, up, nullptr, nullptr, 0.0, 0.0, len);
#endif
  return update_and_select_up_portable<false>(g, up, nullptr, nullptr, 0.0, 0.0, len);
}

Selection update_and_select_up(double* f, const double* up, const float* k_i, const float* k_j,
                               double b_i, double b_j, std::size_t len) {
  return update_and_select_up_with(best_isa(), f, up, k_i, k_j, b_i, b_j, len);
}

Selection conjugate_update_and_select_up(double* f, const double* up, const float* k_i,
                                         const float* k_j, double* kd, double lambda, double t,
                                         std::size_t len) {
  return conjugate_update_and_select_up_with(best_isa(), f, up, k_i, k_j, kd, lambda, t, len);
}

Selection conjugate_update_and_select_up_with([[maybe_unused]] Isa isa, double* f, const double* up,
                                              const float* k_i, const float* k_j, double* kd,
                                              double lambda, double t, std::size_t len) {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (isa == Isa::avx512 && kHasAvx512)
    return conjugate_avx512(f, up, k_i, k_j, kd, lambda, t, len);
  if (isa == Isa::avx2 && kHasAvx2) return conjugate_avx2(f, up, k_i, k_j, kd, lambda, t, len);
#endif
  return conjugate_portable(f, up, k_i, k_j, kd, lambda, t, len);
}

SelectionJ select_low(const double* f, const double* low, const float* k_i, const double* qd,
                      double qd_i, double g_max, double tau, std::size_t len) {
  return select_low_with(best_isa(), f, low, k_i, qd, qd_i, g_max, tau, len);
}

FOGDRIFT_CLONES
void add_row(double* g, const float* k_row, double a, std::size_t begin, std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) g[k] += a * static_cast<double>(k_row[k]);
}

Isa best_isa() {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (kHasAvx512) return Isa::avx512;
  if (kHasAvx2) return Isa::avx2;
#endif
  return Isa::portable;
}

bool available(Isa isa) {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (isa == Isa::avx2) return kHasAvx2;
  if (isa == Isa::avx512) return kHasAvx512;
#endif
  return isa == Isa::portable;
}

Selection update_and_select_up_with([[maybe_unused]] Isa isa, double* f, const double* up,
                                    const float* k_i, const float* k_j, double b_i, double b_j,
                                    std::size_t len) {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (isa == Isa::avx512 && kHasAvx512)
    return update_and_select_up_avx512<true>(f, up, k_i, k_j, b_i, b_j, len);
  if (isa == Isa::avx2 && kHasAvx2)
    return update_and_select_up_avx2<true>(f, up, k_i, k_j, b_i, b_j, len);
#endif
  return update_and_select_up_portable<true>(f, up, k_i, k_j, b_i, b_j, len);
}

SelectionJ select_low_with([[maybe_unused]] Isa isa, const double* f, const double* low,
                           const float* k_i, const double* qd, double qd_i, double g_max,
                           double tau, std::size_t len) {
#if FOGDRIFT_HAVE_AVX2_GATHER
  if (isa == Isa::avx512 && kHasAvx512)
    return select_low_avx512(f, low, k_i, qd, qd_i, g_max, tau, len);
  if (isa == Isa::avx2 && kHasAvx2) return select_low_avx2(f, low, k_i, qd, qd_i, g_max, tau, len);
#endif
  return select_low_portable(f, low, k_i, qd, qd_i, g_max, tau, len);
}

}  // namespace fogdrift::svr::detail
