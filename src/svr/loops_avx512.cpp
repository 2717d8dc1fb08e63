// The AVX-512 table of the SVR engine's inner loops (loops.hpp): the RBF rows on sixteen lanes of
// floats and the pair solver's loops (add_row among them) on eight lanes of doubles, written with
// AVX-512F intrinsics; LIBSVM's selections and the other elementwise loops are the AVX2 ones
// (loops_avx2.cpp). Every function computes what its portable version computes, bit for bit (see
// loops_avx2.cpp); loops_test checks each against the portable one.
#include "svr/loops.hpp"
#include "svr/loops_scalar.hpp"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>

#include <cstring>

// GCC 12 warns inside its own AVX-512 headers that their undefined pass-through operand may be
// (at -O2) or is (at -Og, the sanitizer build) used uninitialised (GCC bug 105593); it is not.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif

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

#define FOGDRIFT_AVX512 __attribute__((target("avx512f,fma")))

// --- kernel rows ---------------------------------------------------------------------------------
// Four groups of columns side by side: each group's steps are a chain of dependent operations, and
// independent chains keep the vector units busy (docs/svr.md, "Where the speed comes from").

// LIBSVM's RBF rows (loops_scalar.hpp, libsvm_rbf_row): in double, eight lanes a vector. GCC does
// not vectorise exp_core's loop for AVX-512 by itself.

// exp_core on G vectors of eight lanes, rounded to float, step by step over the vectors as in
// exp_to_float_avx2 (loops_avx2.cpp): the same bits whatever G, and G > 1 gives the processor
// independent chains of Horner steps instead of one chain whose every step waits on the last.
template <std::size_t G>
FOGDRIFT_AVX512 inline void exp_to_float_avx512(__m512d (&x)[G], __m256 (&out)[G]) {
  const __m512d shifter = _mm512_set1_pd(kShifter);
  const __m512d low_half = _mm512_load_pd(kExp2Sixteenths);
  const __m512d high_half = _mm512_load_pd(kExp2Sixteenths + 8);
  __m512d t[G], p[G];
  for (std::size_t g = 0; g < G; ++g) {
    x[g] = _mm512_min_pd(_mm512_max_pd(x[g], _mm512_set1_pd(-700.0)), _mm512_set1_pd(700.0));
    t[g] = _mm512_add_pd(_mm512_mul_pd(x[g], _mm512_set1_pd(16.0 * kLog2e)), shifter);
    const __m512d n = _mm512_sub_pd(t[g], shifter);
    x[g] = _mm512_sub_pd(_mm512_sub_pd(x[g], _mm512_mul_pd(n, _mm512_set1_pd(kLn2Hi / 16.0))),
                         _mm512_mul_pd(n, _mm512_set1_pd(kLn2Lo / 16.0)));
    p[g] = _mm512_set1_pd(kExpCoefficients[0]);
  }
  for (std::size_t c = 1; c < std::size(kExpCoefficients); ++c) {
    const __m512d coefficient = _mm512_set1_pd(kExpCoefficients[c]);
    for (std::size_t g = 0; g < G; ++g)
      p[g] = _mm512_add_pd(_mm512_mul_pd(p[g], x[g]), coefficient);
  }
  for (std::size_t g = 0; g < G; ++g) {
    const __m512i k = _mm512_sub_epi64(_mm512_castpd_si512(t[g]), _mm512_castpd_si512(shifter));
    const __m512d scale = _mm512_castsi512_pd(
        _mm512_slli_epi64(_mm512_add_epi64(_mm512_srai_epi64(k, 4), _mm512_set1_epi64(1023)), 52));
    // The permutation reads the low four bits of k: bit 3 picks the table's half.
    const __m512d sixteenths = _mm512_permutex2var_pd(low_half, k, high_half);
    out[g] = _mm512_cvtpd_ps(_mm512_mul_pd(_mm512_mul_pd(p[g], sixteenths), scale));
  }
}

// 8G columns from j of an RBF row, the G groups of eight computed side by side; `mask` selects
// the columns of each group that exist (the others read nothing and compute a harmless value).
template <std::size_t G>
FOGDRIFT_AVX512 inline void libsvm_rbf_columns_avx512(const double* xi, __m512d sq_i,
                                                      const double* xt, std::size_t stride,
                                                      const double* sq, std::size_t d,
                                                      __m512d minus_gamma, std::size_t j,
                                                      __mmask8 mask, __m256 (&out)[G]) {
  __m512d x[G];
  for (std::size_t g = 0; g < G; ++g) x[g] = _mm512_setzero_pd();
  for (std::size_t f = 0; f < d; ++f) {
    const __m512d a = _mm512_set1_pd(xi[f]);
    const double* column = xt + f * stride + j;
    for (std::size_t g = 0; g < G; ++g)
      x[g] = _mm512_add_pd(x[g], _mm512_mul_pd(a, _mm512_maskz_loadu_pd(mask, column + 8 * g)));
  }
  const __m512d two = _mm512_set1_pd(2.0);
  for (std::size_t g = 0; g < G; ++g) {
    const __m512d dist = _mm512_sub_pd(
        _mm512_add_pd(sq_i, _mm512_maskz_loadu_pd(mask, sq + j + 8 * g)), _mm512_mul_pd(two, x[g]));
    x[g] = _mm512_mul_pd(minus_gamma, dist);
  }
  exp_to_float_avx512(x, out);
}

// Groups of eight columns computed side by side: two and eight were slower than four.
constexpr std::size_t kLibsvmGroups = 4;

FOGDRIFT_AVX512 void libsvm_rbf_row_avx512(const double* xi, double sq_i, const double* xt,
                                           std::size_t stride, const double* sq, std::size_t n,
                                           std::size_t d, double gamma, float* out) {
  const __m512d sqi = _mm512_set1_pd(sq_i);
  const __m512d minus_gamma = _mm512_set1_pd(-gamma);
  std::size_t j = 0;
  for (; j + 8 * kLibsvmGroups <= n; j += 8 * kLibsvmGroups) {
    __m256 v[kLibsvmGroups];
    libsvm_rbf_columns_avx512(xi, sqi, xt, stride, sq, d, minus_gamma, j, 0xFF, v);
    for (std::size_t g = 0; g < kLibsvmGroups; ++g) _mm256_storeu_ps(out + j + 8 * g, v[g]);
  }
  for (; j + 8 <= n; j += 8) {
    __m256 v[1];
    libsvm_rbf_columns_avx512(xi, sqi, xt, stride, sq, d, minus_gamma, j, 0xFF, v);
    _mm256_storeu_ps(out + j, v[0]);
  }
  if (j < n) {
    alignas(32) float tail[8];
    const auto mask = static_cast<__mmask8>((1u << (n - j)) - 1u);
    __m256 v[1];
    libsvm_rbf_columns_avx512(xi, sqi, xt, stride, sq, d, minus_gamma, j, mask, v);
    _mm256_store_ps(tail, v[0]);
    std::memcpy(out + j, tail, (n - j) * sizeof(float));
  }
}

// The RBF rows in float (loops_scalar.hpp, rbf_row): sixteen lanes a vector.

// kernel_exp (loops_scalar.hpp) on G vectors of sixteen floats, step by step over the vectors as
// in kernel_exp_avx2 (loops_avx2.cpp): the same bits whatever G.
template <std::size_t G>
FOGDRIFT_AVX512 inline void kernel_exp_avx512(__m512 (&y)[G]) {
  const __m512 shifter = _mm512_set1_ps(kShifterF);
  const __m512 eighths = _mm512_load_ps(kExp2Eighths);
  __m512 t[G], p[G];
  for (std::size_t g = 0; g < G; ++g) {
    y[g] = _mm512_max_ps(y[g], _mm512_set1_ps(kKernelExponentMin));
    t[g] = _mm512_fmadd_ps(y[g], _mm512_set1_ps(kEighthsPerNat), shifter);
    const __m512 n = _mm512_sub_ps(t[g], shifter);
    y[g] = _mm512_fmadd_ps(n, _mm512_set1_ps(-kLn2LoEighth),
                           _mm512_fmadd_ps(n, _mm512_set1_ps(-kLn2HiEighth), y[g]));
    p[g] = _mm512_set1_ps(kExpCoefficientsF[0]);
  }
  for (std::size_t c = 1; c < std::size(kExpCoefficientsF); ++c) {
    const __m512 coefficient = _mm512_set1_ps(kExpCoefficientsF[c]);
    for (std::size_t g = 0; g < G; ++g) p[g] = _mm512_fmadd_ps(p[g], y[g], coefficient);
  }
  for (std::size_t g = 0; g < G; ++g) {
    const __m512i k = _mm512_sub_epi32(_mm512_castps_si512(t[g]), _mm512_castps_si512(shifter));
    const __m512 scale = _mm512_castsi512_ps(
        _mm512_slli_epi32(_mm512_add_epi32(_mm512_srai_epi32(k, 3), _mm512_set1_epi32(127)), 23));
    // The permutation reads the low four bits of k; the table holds its eight entries twice.
    const __m512 part = _mm512_permutexvar_ps(k, eighths);
    y[g] = _mm512_mul_ps(_mm512_mul_ps(p[g], part), scale);
  }
}

// 16G columns from j of an RBF row, the G groups of sixteen computed side by side; `mask` selects
// the columns of each group that exist (the others read nothing and compute a harmless value).
template <std::size_t G>
FOGDRIFT_AVX512 inline void rbf_columns_avx512(const float* xi, const float* xt, std::size_t stride,
                                               std::size_t d, __m512 minus_gamma, std::size_t j,
                                               __mmask16 mask, __m512 (&out)[G]) {
  for (std::size_t g = 0; g < G; ++g) out[g] = _mm512_setzero_ps();
  for (std::size_t f = 0; f < d; ++f) {
    const __m512 a = _mm512_set1_ps(xi[f]);
    const float* column = xt + f * stride + j;
    for (std::size_t g = 0; g < G; ++g) {
      const __m512 diff = _mm512_sub_ps(a, _mm512_maskz_loadu_ps(mask, column + 16 * g));
      out[g] = _mm512_fmadd_ps(diff, diff, out[g]);
    }
  }
  for (std::size_t g = 0; g < G; ++g) out[g] = _mm512_mul_ps(minus_gamma, out[g]);
  kernel_exp_avx512(out);
}

// Groups of sixteen columns computed side by side.
constexpr std::size_t kGroups = 4;

FOGDRIFT_AVX512 void rbf_row_avx512(const float* xi, const float* xt, std::size_t stride,
                                    std::size_t n, std::size_t d, double gamma, float* out) {
  const __m512 minus_gamma = _mm512_set1_ps(-static_cast<float>(gamma));
  std::size_t j = 0;
  for (; j + 16 * kGroups <= n; j += 16 * kGroups) {
    __m512 v[kGroups];
    rbf_columns_avx512(xi, xt, stride, d, minus_gamma, j, 0xFFFF, v);
    for (std::size_t g = 0; g < kGroups; ++g) _mm512_storeu_ps(out + j + 16 * g, v[g]);
  }
  for (; j + 16 <= n; j += 16) {
    __m512 v[1];
    rbf_columns_avx512(xi, xt, stride, d, minus_gamma, j, 0xFFFF, v);
    _mm512_storeu_ps(out + j, v[0]);
  }
  if (j < n) {
    const auto mask = static_cast<__mmask16>((1u << (n - j)) - 1u);
    __m512 v[1];
    rbf_columns_avx512(xi, xt, stride, d, minus_gamma, j, mask, v);
    _mm512_mask_storeu_ps(out + j, mask, v[0]);
  }
}

// 16G columns from j of R rows (xs + r·d) side by side: each column vector loaded once for the
// R rows, each entry computed as rbf_columns_avx512 computes it.
template <std::size_t R, std::size_t G>
FOGDRIFT_AVX512 inline void rbf_columns_of_rows_avx512(const float* xs, const float* xt,
                                                       std::size_t stride, std::size_t d,
                                                       __m512 minus_gamma, std::size_t j,
                                                       __mmask16 mask, float* out, std::size_t ld) {
  __m512 x[R][G];
  for (std::size_t r = 0; r < R; ++r)
    for (std::size_t g = 0; g < G; ++g) x[r][g] = _mm512_setzero_ps();
  for (std::size_t f = 0; f < d; ++f) {
    const float* column = xt + f * stride + j;
    __m512 c[G];
    for (std::size_t g = 0; g < G; ++g) c[g] = _mm512_maskz_loadu_ps(mask, column + 16 * g);
    for (std::size_t r = 0; r < R; ++r) {
      const __m512 a = _mm512_set1_ps(xs[r * d + f]);
      for (std::size_t g = 0; g < G; ++g) {
        const __m512 diff = _mm512_sub_ps(a, c[g]);
        x[r][g] = _mm512_fmadd_ps(diff, diff, x[r][g]);
      }
    }
  }
  for (std::size_t r = 0; r < R; ++r) {
    for (std::size_t g = 0; g < G; ++g) x[r][g] = _mm512_mul_ps(minus_gamma, x[r][g]);
    kernel_exp_avx512(x[r]);
    for (std::size_t g = 0; g < G; ++g)
      _mm512_mask_storeu_ps(out + r * ld + j + 16 * g, mask, x[r][g]);
  }
}

template <std::size_t R>
FOGDRIFT_AVX512 void rbf_rows_of_avx512(const float* xs, const float* xt, std::size_t stride,
                                        std::size_t n, std::size_t d, double gamma, float* out,
                                        std::size_t ld) {
  const __m512 minus_gamma = _mm512_set1_ps(-static_cast<float>(gamma));
  std::size_t j = 0;
  for (; j + 32 <= n; j += 32)
    rbf_columns_of_rows_avx512<R, 2>(xs, xt, stride, d, minus_gamma, j, 0xFFFF, out, ld);
  for (; j + 16 <= n; j += 16)
    rbf_columns_of_rows_avx512<R, 1>(xs, xt, stride, d, minus_gamma, j, 0xFFFF, out, ld);
  if (j < n)
    rbf_columns_of_rows_avx512<R, 1>(xs, xt, stride, d, minus_gamma, j,
                                     static_cast<__mmask16>((1u << (n - j)) - 1u), out, ld);
}

// Up to kRowsAtOnce rows side by side, by how many are left (scalar::rbf_rows_by).
constexpr scalar::RowsOf kRowsOfAVX512[kRowsAtOnce] = {
    rbf_rows_of_avx512<1>, rbf_rows_of_avx512<2>, rbf_rows_of_avx512<3>, rbf_rows_of_avx512<4>};

void rbf_rows_avx512(const float* xs, std::size_t m, const float* xt, std::size_t stride,
                     std::size_t n, std::size_t d, double gamma, float* out, std::size_t ld) {
  scalar::rbf_rows_by(kRowsOfAVX512, xs, m, xt, stride, n, d, gamma, out, ld);
}

FOGDRIFT_AVX512 void rbf_row_from_distances_avx512(const float* dist, std::size_t n, double gamma,
                                                   float* out) {
  const __m512 minus_gamma = _mm512_set1_ps(-static_cast<float>(gamma));
  std::size_t j = 0;
  for (; j + 16 <= n; j += 16) {
    __m512 y[1] = {_mm512_mul_ps(minus_gamma, _mm512_loadu_ps(dist + j))};
    kernel_exp_avx512(y);
    _mm512_storeu_ps(out + j, y[0]);
  }
  scalar::rbf_row_from_distances(dist + j, n - j, gamma, out + j);
}

// --- the pair solver's loops: eight samples a vector, two independent sets of lanes --------------

// Each set of lanes keeps, per lane, the best value and the start k of the sixteen samples it
// was found in (one broadcast a step for both sets, not an index vector per set); the merge adds
// the lane's own offset, 8·set + lane.
FOGDRIFT_AVX512 inline void keep_last_max(__m512d v, __m512d at, __m512d& best,
                                          __m512d& best_start) {
  const __mmask8 take = _mm512_cmp_pd_mask(v, best, _CMP_GE_OQ);
  best = _mm512_mask_blend_pd(take, best, v);
  best_start = _mm512_mask_blend_pd(take, best_start, at);
}

// The sample indices of set s's lanes from their starts (−1 stays −1: none).
FOGDRIFT_AVX512 inline __m512d lane_indices(__m512d start, int s) {
  const __m512d offset =
      _mm512_add_pd(_mm512_set1_pd(8.0 * s), _mm512_setr_pd(0, 1, 2, 3, 4, 5, 6, 7));
  const __mmask8 some = _mm512_cmp_pd_mask(start, _mm512_setzero_pd(), _CMP_GE_OQ);
  return _mm512_mask_add_pd(start, some, start, offset);
}

FOGDRIFT_AVX512 inline Selection merge_two_sets(const __m512d best[2],
                                                const __m512d best_start[2]) {
  Selection out{-DBL_MAX, -1};
  for (int s = 0; s < 2; ++s) {
    alignas(64) double bv[8], bx[8];
    _mm512_store_pd(bv, best[s]);
    _mm512_store_pd(bx, lane_indices(best_start[s], s));
    merge_max(bv, bx, 8, out);
  }
  return out;
}

FOGDRIFT_AVX512 Selection conjugate_avx512(double* f, const double* up, const float* k_i,
                                           const float* k_j, double* kd, double lambda, double t,
                                           std::size_t len) {
  __m512d best[2] = {_mm512_set1_pd(-DBL_MAX), _mm512_set1_pd(-DBL_MAX)};
  __m512d best_start[2] = {_mm512_set1_pd(-1.0), _mm512_set1_pd(-1.0)};
  const __m512d l = _mm512_set1_pd(lambda);
  const __m512d tv = _mm512_set1_pd(t);
  std::size_t k = 0;
  for (; k + 16 <= len; k += 16) {
    const __m512d at = _mm512_set1_pd(static_cast<double>(k));
    for (int s = 0; s < 2; ++s) {
      const std::size_t from = k + 8 * static_cast<std::size_t>(s);
      const __m512d ki = _mm512_cvtps_pd(_mm256_loadu_ps(k_i + from));
      const __m512d kj = _mm512_cvtps_pd(_mm256_loadu_ps(k_j + from));
      const __m512d q =
          _mm512_add_pd(_mm512_sub_pd(ki, kj), _mm512_mul_pd(l, _mm512_loadu_pd(kd + from)));
      _mm512_storeu_pd(kd + from, q);
      const __m512d fk = _mm512_add_pd(_mm512_loadu_pd(f + from), _mm512_mul_pd(tv, q));
      _mm512_storeu_pd(f + from, fk);
      keep_last_max(_mm512_sub_pd(_mm512_loadu_pd(up + from), fk), at, best[s], best_start[s]);
    }
  }
  Selection out = merge_two_sets(best, best_start);
  scalar::conjugate_tail(f, up, k_i, k_j, kd, lambda, t, k, len, out);
  return none_if_offsets_only(out);
}

template <bool kUpdate>
FOGDRIFT_AVX512 Selection update_and_select_up_avx512(scalar::Gradient<kUpdate> f, const double* up,
                                                      const float* k_i, const float* k_j,
                                                      double b_i, double b_j, std::size_t len) {
  __m512d best[2] = {_mm512_set1_pd(-DBL_MAX), _mm512_set1_pd(-DBL_MAX)};
  __m512d best_start[2] = {_mm512_set1_pd(-1.0), _mm512_set1_pd(-1.0)};
  const __m512d bi = _mm512_set1_pd(b_i);
  const __m512d bj = _mm512_set1_pd(b_j);
  std::size_t k = 0;
  for (; k + 16 <= len; k += 16) {
    const __m512d at = _mm512_set1_pd(static_cast<double>(k));
    for (int s = 0; s < 2; ++s) {
      const std::size_t from = k + 8 * static_cast<std::size_t>(s);
      __m512d fk = _mm512_loadu_pd(f + from);
      if constexpr (kUpdate) {
        const __m512d ki = _mm512_cvtps_pd(_mm256_loadu_ps(k_i + from));
        const __m512d kj = _mm512_cvtps_pd(_mm256_loadu_ps(k_j + from));
        fk = _mm512_add_pd(fk, _mm512_add_pd(_mm512_mul_pd(ki, bi), _mm512_mul_pd(kj, bj)));
        _mm512_storeu_pd(f + from, fk);
      }
      keep_last_max(_mm512_sub_pd(_mm512_loadu_pd(up + from), fk), at, best[s], best_start[s]);
    }
  }
  Selection out = merge_two_sets(best, best_start);
  scalar::update_and_select_up_tail<kUpdate>(f, up, k_i, k_j, b_i, b_j, k, len, out);
  return none_if_offsets_only(out);
}

// The gain of scalar::select_low_tail in two sets of eight lanes, with the fewest vector
// operations a sample: the loop is bound by the two ports that execute 512-bit operations, not by
// memory (0.52 ns a sample at N = 3,000 before this form, 21 such operations a set). QD_i + QD_k
// is one number when every QD_k equals QD_i (kUniform: one array fewer to read); 2·K_ik is exact,
// so the fused multiply-add rounds QD_i + QD_k − 2·K_ik as the portable loop does; the
// curvature's floor at τ is one max (scalar::pair_curvature); the test G_max + y·G > 0 masks the
// comparison of gains instead of being and-ed with it.
template <bool kUniform>
FOGDRIFT_AVX512 SelectionJ select_low_lanes_avx512(const double* f, const double* low,
                                                   const float* k_i, const double* qd, double qd_i,
                                                   double g_max, double tau, std::size_t len) {
  const __m512d gm = _mm512_set1_pd(g_max);
  const __m512d qd_sum = _mm512_set1_pd(kUniform ? qd_i + qd_i : qd_i);
  const __m512d two = _mm512_set1_pd(2.0);
  const __m512d tau8 = _mm512_set1_pd(tau);
  const __m512d zero = _mm512_setzero_pd();
  __m512d g_max2[2], num[2], den[2], start[2];
  for (int s = 0; s < 2; ++s) {
    g_max2[s] = _mm512_set1_pd(-DBL_MAX);
    num[s] = zero;
    den[s] = _mm512_set1_pd(1.0);
    start[s] = _mm512_set1_pd(-1.0);
  }
  std::size_t k = 0;
  for (; k + 16 <= len; k += 16) {
    const __m512d at = _mm512_set1_pd(static_cast<double>(k));
    for (int s = 0; s < 2; ++s) {
      const std::size_t from = k + 8 * static_cast<std::size_t>(s);
      const __m512d yg = _mm512_add_pd(_mm512_loadu_pd(f + from), _mm512_loadu_pd(low + from));
      g_max2[s] = _mm512_max_pd(g_max2[s], yg);
      const __m512d gd = _mm512_add_pd(gm, yg);
      const __m512d kik = _mm512_cvtps_pd(_mm256_loadu_ps(k_i + from));
      const __m512d sum = kUniform ? qd_sum : _mm512_add_pd(qd_sum, _mm512_loadu_pd(qd + from));
      const __m512d d = _mm512_max_pd(_mm512_fnmadd_pd(two, kik, sum), tau8);
      const __m512d n = _mm512_mul_pd(gd, gd);
      const __mmask8 take =
          _mm512_mask_cmp_pd_mask(_mm512_cmp_pd_mask(gd, zero, _CMP_GT_OQ),
                                  _mm512_mul_pd(n, den[s]), _mm512_mul_pd(num[s], d), _CMP_GE_OQ);
      num[s] = _mm512_mask_blend_pd(take, num[s], n);
      den[s] = _mm512_mask_blend_pd(take, den[s], d);
      start[s] = _mm512_mask_blend_pd(take, start[s], at);
    }
  }
  SelectionJ out;
  out.g_max2 = -DBL_MAX;
  double num_max = 0, den_max = 1;
  for (int s = 0; s < 2; ++s) {
    alignas(64) double bn[8], bd[8], bx[8], m2[8];
    _mm512_store_pd(bn, num[s]);
    _mm512_store_pd(bd, den[s]);
    _mm512_store_pd(bx, lane_indices(start[s], s));
    _mm512_store_pd(m2, g_max2[s]);
    merge_gain(bn, bd, bx, m2, 8, out, num_max, den_max);
  }
  scalar::select_low_tail(f, low, k_i, qd, qd_i, g_max, tau, k, len, out, num_max, den_max);
  return out;
}

SelectionJ select_low_avx512(const double* f, const double* low, const float* k_i, const double* qd,
                             double qd_i, double g_max, double tau, std::size_t len) {
  return qd == nullptr ? select_low_lanes_avx512<true>(f, low, k_i, qd, qd_i, g_max, tau, len)
                       : select_low_lanes_avx512<false>(f, low, k_i, qd, qd_i, g_max, tau, len);
}

// g += a·K over [begin, end), eight lanes a vector, two vectors an iteration: the product and
// the sum rounded apart, as scalar::add_row rounds them.
FOGDRIFT_AVX512 void add_row_avx512(double* g, const float* k_row, double a, std::size_t begin,
                                    std::size_t end) {
  const __m512d av = _mm512_set1_pd(a);
  std::size_t k = begin;
  for (; k + 16 <= end; k += 16)
    for (std::size_t s = 0; s < 16; s += 8) {
      const __m512d kk = _mm512_cvtps_pd(_mm256_loadu_ps(k_row + k + s));
      _mm512_storeu_pd(g + k + s, _mm512_add_pd(_mm512_loadu_pd(g + k + s), _mm512_mul_pd(av, kk)));
    }
  scalar::add_row(g, k_row, a, k, end);
}

FOGDRIFT_AVX512 Selection select_up_avx512(const double* f, const double* up, std::size_t len) {
  return update_and_select_up_avx512<false>(f, up, nullptr, nullptr, 0.0, 0.0, len);
}

}  // namespace

const Loops* avx512_loops() {
  static const Loops kTable = [] {
    Loops table = avx2_loops() != nullptr ? *avx2_loops() : portable_loops();
    table.isa = Isa::avx512;
    table.libsvm_rbf_row = libsvm_rbf_row_avx512;
    table.rbf_row = rbf_row_avx512;
    table.rbf_rows = rbf_rows_avx512;
    table.rbf_row_from_distances = rbf_row_from_distances_avx512;
    table.select_up = select_up_avx512;
    table.update_and_select_up = update_and_select_up_avx512<true>;
    table.conjugate_update_and_select_up = conjugate_avx512;
    table.select_low = select_low_avx512;
    table.add_row = add_row_avx512;
    return table;
  }();
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && avx2_loops() != nullptr ? &kTable : nullptr;
}

}  // namespace fogdrift::svr::detail

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#else
namespace fogdrift::svr::detail {
const Loops* avx512_loops() {
  return nullptr;
}
}  // namespace fogdrift::svr::detail
#endif
