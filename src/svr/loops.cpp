// Inner loops of the SMO solver and of kernel rows. See loops.hpp for why they live here and for
// the floating-point flags this file is compiled with (src/CMakeLists.txt).
#include "svr/loops.hpp"

#include <algorithm>
#include <bit>
#include <cfloat>

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
// feature-major copy `xt` (d × n). Inlined into each caller's AVX2 and portable builds.
inline void dot_block(const double* xi, const double* xt, std::size_t n, std::size_t d,
                      std::size_t j0, std::size_t m, double* acc) {
  for (std::size_t j = 0; j < m; ++j) acc[j] = 0.0;
  for (std::size_t f = 0; f < d; ++f) {
    const double xf = xi[f];
    const double* col = xt + f * n + j0;
    for (std::size_t j = 0; j < m; ++j) acc[j] += xf * col[j];
  }
}

}  // namespace

float exp_to_float(double x) {
  return static_cast<float>(exp_core(x));
}

FOGDRIFT_CLONES
void rbf_row(const double* xi, double sq_i, const double* xt, const double* sq, std::size_t n,
             std::size_t d, double gamma, float* out) {
  double acc[kBlock];
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - j0);
    dot_block(xi, xt, n, d, j0, m, acc);
    for (std::size_t j = 0; j < m; ++j) {
      const double dist = (sq_i + sq[j0 + j]) - 2.0 * acc[j];
      out[j0 + j] = static_cast<float>(exp_core(-gamma * dist));
    }
  }
}

FOGDRIFT_CLONES
void linear_row(const double* xi, const double* xt, std::size_t n, std::size_t d, float* out) {
  double acc[kBlock];
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - j0);
    dot_block(xi, xt, n, d, j0, m, acc);
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

FOGDRIFT_CLONES
void rbf_row_from_distances(const float* dist, std::size_t n, double gamma, float* out) {
  for (std::size_t j = 0; j < n; ++j)
    out[j] = static_cast<float>(exp_core(-gamma * static_cast<double>(dist[j])));
}

#if FOGDRIFT_HAVE_AVX2_GATHER
namespace {
const bool kHasAvx2 = __builtin_cpu_supports("avx2");
}
#endif

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
  alignas(32) double bv[4], bi[4];
  _mm256_store_pd(bv, best);
  _mm256_store_pd(bi, best_index);
  Selection out{-DBL_MAX, -1};
  for (int k = 0; k < 4; ++k) {
    if (bi[k] < 0) continue;
    const auto idx = static_cast<std::int64_t>(bi[k]);
    if (bv[k] > out.value || (bv[k] == out.value && idx > out.index)) out = {bv[k], idx};
  }
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

}  // namespace fogdrift::svr::detail
