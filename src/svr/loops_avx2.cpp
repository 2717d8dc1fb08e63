// The AVX2 table of the SVR engine's inner loops (loops.hpp). The selections are written with
// intrinsics, four lanes of doubles at a time, and the RBF rows eight lanes of floats at a time
// (with AVX2's fused multiply-adds, as the portable rows write them); the elementwise loops are the
// portable ones (loops_scalar.hpp) inlined into functions built for AVX2, which the compiler
// vectorises. Every function computes what its portable version computes, bit for bit: the same
// operations in the same order, no fused multiply-add but the RBF rows' own, and on ties the same
// index (each lane keeps its own last maximiser and the lanes are merged so that the overall last
// one wins, as in LIBSVM). loops_test checks each against the portable one.
#include "svr/loops.hpp"
#include "svr/loops_scalar.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include <cstring>

namespace fogdrift::svr::detail {
namespace {

using scalar::kEighthsPerNat;
using scalar::kExp2Eighths;
using scalar::kExp2Sixteenths;
using scalar::kExpCoefficients;
using scalar::kExpCoefficientsF;
using scalar::kKernelExponentMin;
using scalar::kLn2Hi;
using scalar::kLn2HiEighth;
using scalar::kLn2Lo;
using scalar::kLn2LoEighth;
using scalar::kLog2e;
using scalar::kShifter;
using scalar::kShifterF;
using scalar::merge_gain;
using scalar::merge_max;
using scalar::none_if_offsets_only;

#define FOGDRIFT_AVX2 __attribute__((target("avx2")))
// The RBF rows also use fused multiply-adds (loops_scalar.hpp, kernel_exp); every processor with
// AVX2 that fogdrift has met has FMA too, and avx2_loops() requires both.
#define FOGDRIFT_AVX2_FMA __attribute__((target("avx2,fma")))

// --- kernel rows ---------------------------------------------------------------------------------

// LIBSVM's RBF rows (loops_scalar.hpp, libsvm_rbf_row): in double, four lanes a vector.

// exp_core (loops_scalar.hpp) on G vectors of four lanes, rounded to float into out[0, 4G), step
// by step over the vectors: each vector's operations are exp_core's in its order, so the results
// are the same bits whatever G, but G > 1 gives the processor independent chains. One vector
// alone is a chain of dependent steps (the Horner steps of exp_core) that leaves the vector units
// waiting on each step's latency. GCC does not vectorise exp_core's loop this well by itself: its
// own AVX2 version ran at half the speed of this code.
template <std::size_t G>
FOGDRIFT_AVX2 inline void exp_to_float_avx2(__m256d (&x)[G], float* out) {
  const __m256d shifter = _mm256_set1_pd(kShifter);
  __m256d t[G], p[G];
  for (std::size_t g = 0; g < G; ++g) {
    x[g] = _mm256_min_pd(_mm256_max_pd(x[g], _mm256_set1_pd(-700.0)), _mm256_set1_pd(700.0));
    t[g] = _mm256_add_pd(_mm256_mul_pd(x[g], _mm256_set1_pd(16.0 * kLog2e)), shifter);
    const __m256d n = _mm256_sub_pd(t[g], shifter);
    x[g] = _mm256_sub_pd(_mm256_sub_pd(x[g], _mm256_mul_pd(n, _mm256_set1_pd(kLn2Hi / 16.0))),
                         _mm256_mul_pd(n, _mm256_set1_pd(kLn2Lo / 16.0)));
    p[g] = _mm256_set1_pd(kExpCoefficients[0]);
  }
  for (std::size_t c = 1; c < std::size(kExpCoefficients); ++c) {
    const __m256d coefficient = _mm256_set1_pd(kExpCoefficients[c]);
    for (std::size_t g = 0; g < G; ++g)
      p[g] = _mm256_add_pd(_mm256_mul_pd(p[g], x[g]), coefficient);
  }
  for (std::size_t g = 0; g < G; ++g) {
    const __m256i k = _mm256_sub_epi64(_mm256_castpd_si256(t[g]), _mm256_castpd_si256(shifter));
    // ⌊k/16⌋ without AVX2's missing 64-bit arithmetic shift: k + 2^20 is positive (|k| < 2^15),
    // and 2^16 − 1023 restores the bias after the logical shift.
    const __m256i e =
        _mm256_add_epi64(_mm256_srli_epi64(_mm256_add_epi64(k, _mm256_set1_epi64x(1 << 20)), 4),
                         _mm256_set1_epi64x(1023 - (1 << 16)));
    const __m256d scale = _mm256_castsi256_pd(_mm256_slli_epi64(e, 52));
    const __m256d sixteenths = _mm256_i64gather_pd(
        kExp2Sixteenths, _mm256_and_si256(k, _mm256_set1_epi64x(15)), sizeof(double));
    _mm_storeu_ps(out + 4 * g,
                  _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_mul_pd(p[g], sixteenths), scale)));
  }
}

// 4G columns from `xt`, `sq` (pointing at the first of them) into out[0, 4G), the distances'
// sums and exponentials of the G groups of four computed side by side. Four groups took a row of
// 4,000 samples × 12 features from 5.3 to 4.1-4.5 ns a pair on an AVX2-only AMD EPYC; two or
// three gained nothing measurable, eight less than four (docs/svr.md, "Where the speed comes
// from").
template <std::size_t G>
FOGDRIFT_AVX2 inline void libsvm_rbf_columns_avx2(const double* xi, __m256d sq_i, const double* xt,
                                                  std::size_t stride, const double* sq,
                                                  std::size_t d, __m256d minus_gamma, float* out) {
  __m256d x[G];
  for (std::size_t g = 0; g < G; ++g) x[g] = _mm256_setzero_pd();
  for (std::size_t f = 0; f < d; ++f) {
    const __m256d a = _mm256_set1_pd(xi[f]);
    const double* column = xt + f * stride;
    for (std::size_t g = 0; g < G; ++g)
      x[g] = _mm256_add_pd(x[g], _mm256_mul_pd(a, _mm256_loadu_pd(column + 4 * g)));
  }
  const __m256d two = _mm256_set1_pd(2.0);
  for (std::size_t g = 0; g < G; ++g) {
    const __m256d dist =
        _mm256_sub_pd(_mm256_add_pd(sq_i, _mm256_loadu_pd(sq + 4 * g)), _mm256_mul_pd(two, x[g]));
    x[g] = _mm256_mul_pd(minus_gamma, dist);
  }
  exp_to_float_avx2(x, out);
}

constexpr std::size_t kGroups = 4;

FOGDRIFT_AVX2 void libsvm_rbf_row_avx2(const double* xi, double sq_i, const double* xt,
                                       std::size_t stride, const double* sq, std::size_t n,
                                       std::size_t d, double gamma, float* out) {
  const __m256d sqi = _mm256_set1_pd(sq_i);
  const __m256d minus_gamma = _mm256_set1_pd(-gamma);
  std::size_t j = 0;
  for (; j + 4 * kGroups <= n; j += 4 * kGroups)
    libsvm_rbf_columns_avx2<kGroups>(xi, sqi, xt + j, stride, sq + j, d, minus_gamma, out + j);
  for (; j + 4 <= n; j += 4)
    libsvm_rbf_columns_avx2<1>(xi, sqi, xt + j, stride, sq + j, d, minus_gamma, out + j);
  scalar::libsvm_rbf_row(xi, sq_i, xt + j, stride, sq + j, n - j, d, gamma, out + j);
}

// The RBF rows in float (loops_scalar.hpp, rbf_row): eight lanes a vector.

// kernel_exp (loops_scalar.hpp) on G vectors of eight floats, step by step over the vectors:
// each vector's operations are kernel_exp's in its order, so the results are the same bits
// whatever G, but G > 1 gives the processor independent chains. One vector alone is a chain of
// dependent steps (the Horner steps) that leaves the vector units waiting on each step's latency.
template <std::size_t G>
FOGDRIFT_AVX2_FMA inline void kernel_exp_avx2(__m256 (&y)[G]) {
  const __m256 shifter = _mm256_set1_ps(kShifterF);
  const __m256 eighths = _mm256_load_ps(kExp2Eighths);
  __m256 t[G], p[G];
  for (std::size_t g = 0; g < G; ++g) {
    y[g] = _mm256_max_ps(y[g], _mm256_set1_ps(kKernelExponentMin));
    t[g] = _mm256_fmadd_ps(y[g], _mm256_set1_ps(kEighthsPerNat), shifter);
    const __m256 n = _mm256_sub_ps(t[g], shifter);
    y[g] = _mm256_fmadd_ps(n, _mm256_set1_ps(-kLn2LoEighth),
                           _mm256_fmadd_ps(n, _mm256_set1_ps(-kLn2HiEighth), y[g]));
    p[g] = _mm256_set1_ps(kExpCoefficientsF[0]);
  }
  for (std::size_t c = 1; c < std::size(kExpCoefficientsF); ++c) {
    const __m256 coefficient = _mm256_set1_ps(kExpCoefficientsF[c]);
    for (std::size_t g = 0; g < G; ++g) p[g] = _mm256_fmadd_ps(p[g], y[g], coefficient);
  }
  for (std::size_t g = 0; g < G; ++g) {
    const __m256i k = _mm256_sub_epi32(_mm256_castps_si256(t[g]), _mm256_castps_si256(shifter));
    const __m256 scale = _mm256_castsi256_ps(
        _mm256_slli_epi32(_mm256_add_epi32(_mm256_srai_epi32(k, 3), _mm256_set1_epi32(127)), 23));
    // The permutation reads the low three bits of k.
    const __m256 part = _mm256_permutevar8x32_ps(eighths, k);
    y[g] = _mm256_mul_ps(_mm256_mul_ps(p[g], part), scale);
  }
}

// 8G columns from `xt` (pointing at the first of them) into out[0, 8G), the distances' sums and
// exponentials of the G groups of eight computed side by side, for the same reason.
template <std::size_t G>
FOGDRIFT_AVX2_FMA inline void rbf_columns_avx2(const float* xi, const float* xt, std::size_t stride,
                                               std::size_t d, __m256 minus_gamma, float* out) {
  __m256 x[G];
  for (std::size_t g = 0; g < G; ++g) x[g] = _mm256_setzero_ps();
  for (std::size_t f = 0; f < d; ++f) {
    const __m256 a = _mm256_set1_ps(xi[f]);
    const float* column = xt + f * stride;
    for (std::size_t g = 0; g < G; ++g) {
      const __m256 diff = _mm256_sub_ps(a, _mm256_loadu_ps(column + 8 * g));
      x[g] = _mm256_fmadd_ps(diff, diff, x[g]);
    }
  }
  for (std::size_t g = 0; g < G; ++g) x[g] = _mm256_mul_ps(minus_gamma, x[g]);
  kernel_exp_avx2(x);
  for (std::size_t g = 0; g < G; ++g) _mm256_storeu_ps(out + 8 * g, x[g]);
}

FOGDRIFT_AVX2_FMA void rbf_row_avx2(const float* xi, const float* xt, std::size_t stride,
                                    std::size_t n, std::size_t d, double gamma, float* out) {
  const __m256 minus_gamma = _mm256_set1_ps(-static_cast<float>(gamma));
  std::size_t j = 0;
  for (; j + 8 * kGroups <= n; j += 8 * kGroups)
    rbf_columns_avx2<kGroups>(xi, xt + j, stride, d, minus_gamma, out + j);
  for (; j + 8 <= n; j += 8) rbf_columns_avx2<1>(xi, xt + j, stride, d, minus_gamma, out + j);
  scalar::rbf_row(xi, xt + j, stride, n - j, d, gamma, out + j);
}

// 8G columns of R rows (xs + r·d) side by side: each column vector loaded once for the R rows,
// each entry computed as rbf_columns_avx2 computes it.
template <std::size_t R, std::size_t G>
FOGDRIFT_AVX2_FMA inline void rbf_columns_of_rows_avx2(const float* xs, const float* xt,
                                                       std::size_t stride, std::size_t d,
                                                       __m256 minus_gamma, float* out,
                                                       std::size_t ld) {
  __m256 x[R][G];
  for (std::size_t r = 0; r < R; ++r)
    for (std::size_t g = 0; g < G; ++g) x[r][g] = _mm256_setzero_ps();
  for (std::size_t f = 0; f < d; ++f) {
    const float* column = xt + f * stride;
    __m256 c[G];
    for (std::size_t g = 0; g < G; ++g) c[g] = _mm256_loadu_ps(column + 8 * g);
    for (std::size_t r = 0; r < R; ++r) {
      const __m256 a = _mm256_set1_ps(xs[r * d + f]);
      for (std::size_t g = 0; g < G; ++g) {
        const __m256 diff = _mm256_sub_ps(a, c[g]);
        x[r][g] = _mm256_fmadd_ps(diff, diff, x[r][g]);
      }
    }
  }
  for (std::size_t r = 0; r < R; ++r) {
    for (std::size_t g = 0; g < G; ++g) x[r][g] = _mm256_mul_ps(minus_gamma, x[r][g]);
    kernel_exp_avx2(x[r]);
    for (std::size_t g = 0; g < G; ++g) _mm256_storeu_ps(out + r * ld + 8 * g, x[r][g]);
  }
}

template <std::size_t R>
FOGDRIFT_AVX2_FMA void rbf_rows_of_avx2(const float* xs, const float* xt, std::size_t stride,
                                        std::size_t n, std::size_t d, double gamma, float* out,
                                        std::size_t ld) {
  const __m256 minus_gamma = _mm256_set1_ps(-static_cast<float>(gamma));
  std::size_t j = 0;
  for (; j + 16 <= n; j += 16)
    rbf_columns_of_rows_avx2<R, 2>(xs, xt + j, stride, d, minus_gamma, out + j, ld);
  for (; j + 8 <= n; j += 8)
    rbf_columns_of_rows_avx2<R, 1>(xs, xt + j, stride, d, minus_gamma, out + j, ld);
  for (std::size_t r = 0; r < R; ++r)
    scalar::rbf_row(xs + r * d, xt + j, stride, n - j, d, gamma, out + r * ld + j);
}

// Up to kRowsAtOnce rows side by side, by how many are left (scalar::rbf_rows_by).
constexpr scalar::RowsOf kRowsOfAVX2[kRowsAtOnce] = {rbf_rows_of_avx2<1>, rbf_rows_of_avx2<2>,
                                                     rbf_rows_of_avx2<3>, rbf_rows_of_avx2<4>};

void rbf_rows_avx2(const float* xs, std::size_t m, const float* xt, std::size_t stride,
                   std::size_t n, std::size_t d, double gamma, float* out, std::size_t ld) {
  scalar::rbf_rows_by(kRowsOfAVX2, xs, m, xt, stride, n, d, gamma, out, ld);
}

FOGDRIFT_AVX2_FMA void distance_row_avx2(const float* xi, const float* xt, std::size_t stride,
                                         std::size_t n, std::size_t d, float* out) {
  scalar::distance_row(xi, xt, stride, n, d, out);
}

FOGDRIFT_AVX2_FMA void rbf_row_from_distances_avx2(const float* dist, std::size_t n, double gamma,
                                                   float* out) {
  const __m256 minus_gamma = _mm256_set1_ps(-static_cast<float>(gamma));
  std::size_t j = 0;
  for (; j + 8 <= n; j += 8) {
    __m256 y[1] = {_mm256_mul_ps(minus_gamma, _mm256_loadu_ps(dist + j))};
    kernel_exp_avx2(y);
    _mm256_storeu_ps(out + j, y[0]);
  }
  scalar::rbf_row_from_distances(dist + j, n - j, gamma, out + j);
}

// The elementwise loops, vectorised by the compiler.
FOGDRIFT_AVX2 void linear_row_avx2(const double* xi, const double* xt, std::size_t stride,
                                   std::size_t n, std::size_t d, float* out) {
  scalar::linear_row(xi, xt, stride, n, d, out);
}

FOGDRIFT_AVX2 void update_gradient_avx2(double* g, const std::int8_t* y, const float* k_i,
                                        const float* k_j, double a_i, double a_j, std::size_t len) {
  scalar::update_gradient(g, y, k_i, k_j, a_i, a_j, len);
}

FOGDRIFT_AVX2 void add_scaled_avx2(double* g, const std::int8_t* y, const float* k_row, double a,
                                   std::size_t begin, std::size_t end) {
  scalar::add_scaled(g, y, k_row, a, begin, end);
}

FOGDRIFT_AVX2 void add_row_avx2(double* g, const float* k_row, double a, std::size_t begin,
                                std::size_t end) {
  scalar::add_row(g, k_row, a, begin, end);
}

// --- LIBSVM's selections -------------------------------------------------------------------------
// GCC does not if-convert the portable loops, hence the intrinsics.

FOGDRIFT_AVX2 inline __m256d load_y(const std::int8_t* y) {
  std::int32_t packed;
  std::memcpy(&packed, y, sizeof packed);
  return _mm256_cvtepi32_pd(_mm_cvtepi8_epi32(_mm_cvtsi32_si128(packed)));
}

// Masks (all-ones 64-bit lanes) of I_up and I_low for four variables.
FOGDRIFT_AVX2 inline void load_masks(const std::int8_t* y, const std::uint8_t* status, __m256d& up,
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
FOGDRIFT_AVX2 Selection merge_lanes_max(__m256d best, __m256d best_index) {
  alignas(32) double bv[4], bi[4];
  _mm256_store_pd(bv, best);
  _mm256_store_pd(bi, best_index);
  Selection out{-DBL_MAX, -1};
  merge_max(bv, bi, 4, out);
  return out;
}

FOGDRIFT_AVX2 Selection select_i_avx2(const double* g, const std::int8_t* y,
                                      const std::uint8_t* status, std::size_t len) {
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
  scalar::select_i_tail(g, y, status, t, len, out);
  return out;
}

FOGDRIFT_AVX2 SelectionJ select_j_avx2(const double* g, const std::int8_t* y,
                                       const std::uint8_t* status, const float* k_i,
                                       const double* qd, double qd_i, double g_max, double tau,
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
  scalar::select_j_tail(g, y, status, k_i, qd, qd_i, g_max, tau, j, len, out, obj_min);
  return out;
}

// The pair solver's loops (see loops.hpp), four samples at a time in the same way.

// The running last maximum of v over four lanes (samples k … k+3), and the merge of two sets of
// lanes at the end.
FOGDRIFT_AVX2 inline void keep_last_max(__m256d v, std::size_t k, __m256d& best,
                                        __m256d& best_index) {
  const __m256d take = _mm256_cmp_pd(v, best, _CMP_GE_OQ);
  best = _mm256_blendv_pd(best, v, take);
  const __m256d index =
      _mm256_add_pd(_mm256_set1_pd(static_cast<double>(k)), _mm256_setr_pd(0, 1, 2, 3));
  best_index = _mm256_blendv_pd(best_index, index, take);
}

FOGDRIFT_AVX2 inline Selection merge_two_sets(const __m256d best[2], const __m256d best_index[2]) {
  Selection out = merge_lanes_max(best[0], best_index[0]);
  const Selection other = merge_lanes_max(best[1], best_index[1]);
  if (other.index >= 0 &&
      (other.value > out.value || (other.value == out.value && other.index > out.index)))
    out = other;
  return out;
}

// One block of four for update_and_select_up_avx2: the update, then the running last maximum.
template <bool kUpdate>
FOGDRIFT_AVX2 inline void up_block(scalar::Gradient<kUpdate> f, const double* up, const float* k_i,
                                   const float* k_j, __m256d bi, __m256d bj, std::size_t k,
                                   __m256d& best, __m256d& best_index) {
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
FOGDRIFT_AVX2 Selection update_and_select_up_avx2(scalar::Gradient<kUpdate> f, const double* up,
                                                  const float* k_i, const float* k_j, double b_i,
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
  scalar::update_and_select_up_tail<kUpdate>(f, up, k_i, k_j, b_i, b_j, k, len, out);
  return none_if_offsets_only(out);
}

FOGDRIFT_AVX2 Selection select_up_avx2(const double* f, const double* up, std::size_t len) {
  return update_and_select_up_avx2<false>(f, up, nullptr, nullptr, 0.0, 0.0, len);
}

// conjugate_update_and_select_up four samples at a time, in two sets of lanes as above.
FOGDRIFT_AVX2 inline void conjugate_block(double* f, const double* up, const float* k_i,
                                          const float* k_j, double* kd, __m256d lambda, __m256d t,
                                          std::size_t k, __m256d& best, __m256d& best_index) {
  const __m256d ki = _mm256_cvtps_pd(_mm_loadu_ps(k_i + k));
  const __m256d kj = _mm256_cvtps_pd(_mm_loadu_ps(k_j + k));
  const __m256d q =
      _mm256_add_pd(_mm256_sub_pd(ki, kj), _mm256_mul_pd(lambda, _mm256_loadu_pd(kd + k)));
  _mm256_storeu_pd(kd + k, q);
  const __m256d fk = _mm256_add_pd(_mm256_loadu_pd(f + k), _mm256_mul_pd(t, q));
  _mm256_storeu_pd(f + k, fk);
  keep_last_max(_mm256_sub_pd(_mm256_loadu_pd(up + k), fk), k, best, best_index);
}

FOGDRIFT_AVX2 Selection conjugate_avx2(double* f, const double* up, const float* k_i,
                                       const float* k_j, double* kd, double lambda, double t,
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
  scalar::conjugate_tail(f, up, k_i, k_j, kd, lambda, t, k, len, out);
  return none_if_offsets_only(out);
}

// Compares gains by cross-multiplication, num·best_den ≥ best_num·den, instead of dividing (the
// division was the slowest instruction of the loop), in four independent sets of lanes so that
// the compare-and-blend chain of one set does not stall the next block.
struct GainLanes {
  __m256d num, den, index;
};

// QD_i + QD_k is `qd_sum` when every QD_k equals QD_i (kUniform), else read from qd.
template <bool kUniform>
FOGDRIFT_AVX2_FMA inline void gain_block(const double* f, const double* low, const float* k_i,
                                         const double* qd, std::size_t k, __m256d gm,
                                         __m256d qd_sum, __m256d tau, __m256d& g_max2,
                                         GainLanes& best) {
  const __m256d two = _mm256_set1_pd(2.0);
  const __m256d zero = _mm256_setzero_pd();
  const __m256d yg = _mm256_add_pd(_mm256_loadu_pd(f + k), _mm256_loadu_pd(low + k));
  g_max2 = _mm256_max_pd(g_max2, yg);
  const __m256d gd = _mm256_add_pd(gm, yg);
  const __m256d kik = _mm256_cvtps_pd(_mm_loadu_ps(k_i + k));
  const __m256d sum = kUniform ? qd_sum : _mm256_add_pd(qd_sum, _mm256_loadu_pd(qd + k));
  // scalar::pair_curvature: 2·K_ik is exact, so the fused form rounds as the two steps do.
  const __m256d den = _mm256_max_pd(_mm256_fnmadd_pd(two, kik, sum), tau);
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

template <bool kUniform>
FOGDRIFT_AVX2_FMA SelectionJ select_low_lanes_avx2(const double* f, const double* low,
                                                   const float* k_i, const double* qd, double qd_i,
                                                   double g_max, double tau, std::size_t len) {
  const __m256d gm = _mm256_set1_pd(g_max);
  // With a uniform diagonal QD_i + QD_k is one number, QD_i + QD_i as the portable loop forms it.
  const __m256d qd_sum = _mm256_set1_pd(kUniform ? qd_i + qd_i : qd_i);
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
      gain_block<kUniform>(f, low, k_i, qd, k + 4 * s, gm, qd_sum, tau4, g_max2[s], best[s]);
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
  scalar::select_low_tail(f, low, k_i, qd, qd_i, g_max, tau, k, len, out, num_max, den_max);
  return out;
}

SelectionJ select_low_avx2(const double* f, const double* low, const float* k_i, const double* qd,
                           double qd_i, double g_max, double tau, std::size_t len) {
  return qd == nullptr ? select_low_lanes_avx2<true>(f, low, k_i, qd, qd_i, g_max, tau, len)
                       : select_low_lanes_avx2<false>(f, low, k_i, qd, qd_i, g_max, tau, len);
}

}  // namespace

const Loops* avx2_loops() {
  static constexpr Loops kTable{
      .isa = Isa::avx2,
      .libsvm_rbf_row = libsvm_rbf_row_avx2,
      .rbf_row = rbf_row_avx2,
      .rbf_rows = rbf_rows_avx2,
      .linear_row = linear_row_avx2,
      .distance_row = distance_row_avx2,
      .rbf_row_from_distances = rbf_row_from_distances_avx2,
      .update_gradient = update_gradient_avx2,
      .add_scaled = add_scaled_avx2,
      .add_row = add_row_avx2,
      .select_i = select_i_avx2,
      .select_j = select_j_avx2,
      .select_up = select_up_avx2,
      .update_and_select_up = update_and_select_up_avx2<true>,
      .conjugate_update_and_select_up = conjugate_avx2,
      .select_low = select_low_avx2,
  };
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") ? &kTable : nullptr;
}

}  // namespace fogdrift::svr::detail

#else
namespace fogdrift::svr::detail {
const Loops* avx2_loops() {
  return nullptr;
}
}  // namespace fogdrift::svr::detail
#endif
