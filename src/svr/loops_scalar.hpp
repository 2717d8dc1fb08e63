// The portable bodies of the SVR engine's inner loops (loops.hpp), as inline functions. The
// portable table (loops_portable.cpp) is these functions; the AVX2 and AVX-512 files reuse them
// for the elementwise loops, which the compiler vectorises when they are inlined into a function
// built for that instruction set, and for the tails of their hand-vectorised loops.
//
// Only the loops_*.cpp files include this header, and they are all compiled with the same flags
// (src/CMakeLists.txt), so every out-of-line copy of these functions is the same code. None of
// them may use an instruction set beyond the baseline on its own: an ISA is only ever switched on
// by a `target` attribute on the caller. Internal header: not installed.
#pragma once

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "svr/loops.hpp"

namespace fogdrift::svr::detail::scalar {

#define FOGDRIFT_INLINE inline __attribute__((always_inline))

// --- LIBSVM's RBF kernel: in double, rounded to float ------------------------------------------

constexpr double kLog2e = 1.4426950408889634074;
// ln 2 split so that n·kLn2Hi is exact for |n| < 2^20 (Cody & Waite range reduction).
constexpr double kLn2Hi = 6.93147180369123816490e-01;
constexpr double kLn2Lo = 1.90821492927058770002e-10;
constexpr double kShifter = 6755399441055744.0;  // 1.5·2^52: adding it rounds to an integer

/// 2^(j/16) for j = 0 … 15, each the double nearest the exact value.
alignas(64) constexpr double kExp2Sixteenths[16] = {
    0x1.0000000000000p+0, 0x1.0b5586cf9890fp+0, 0x1.172b83c7d517bp+0, 0x1.2387a6e756238p+0,
    0x1.306fe0a31b715p+0, 0x1.3dea64c123422p+0, 0x1.4bfdad5362a27p+0, 0x1.5ab07dd485429p+0,
    0x1.6a09e667f3bcdp+0, 0x1.7a11473eb0187p+0, 0x1.8ace5422aa0dbp+0, 0x1.9c49182a3f090p+0,
    0x1.ae89f995ad3adp+0, 0x1.c199bdd85529cp+0, 0x1.d5818dcfba487p+0, 0x1.ea4afa2a490dap+0};

/// The Taylor coefficients of e^r, 1/6! down to 1/0!, for Horner's rule.
constexpr double kExpCoefficients[] = {1.0 / 720.0, 1.0 / 120.0, 1.0 / 24.0, 1.0 / 6.0,
                                       0.5,         1.0,         1.0};

/// e^x through e^x = 2^(n/16)·e^r, n = round(16·x/ln 2), |r| ≤ ln 2 / 32: 2^(n/16) is 2^⌊n/16⌋
/// (built in the exponent bits) times 2^((n mod 16)/16) from kExp2Sixteenths, and e^r is the
/// Taylor series to degree 6, whose truncation error r^7/7! < 4.4e-16 relative. With the
/// table's and the arithmetic's roundings the result is within a few 1e-16 of e^x, against the
/// 3e-8 half-step of the float every caller rounds it to, so the float is e^x correctly rounded
/// unless e^x lies within about 1e-15 of the midpoint between two floats: on 6·10^7 random x in
/// [−745, 0] every float equals std::exp's (docs/svr.md, "Where the speed comes from"). The
/// reduction to a sixteenth of ln 2 replaced one to ln 2 / 2 with a polynomial of degree 11, for
/// a third less work per exponential. Branch-free so that loops around it vectorise; the vector
/// versions compute the same operations lane by lane.
FOGDRIFT_INLINE double exp_core(double x) {
  x = x < -700.0 ? -700.0 : x;  // e^-700 is 0 in float; keeps 2^⌊n/16⌋ a normal double
  x = x > 700.0 ? 700.0 : x;
  const double t = x * (16.0 * kLog2e) + kShifter;
  const double n = t - kShifter;
  const double r = (x - n * (kLn2Hi / 16.0)) - n * (kLn2Lo / 16.0);
  double p = kExpCoefficients[0];
  for (std::size_t c = 1; c < std::size(kExpCoefficients); ++c) p = p * r + kExpCoefficients[c];
  const std::int64_t k = std::bit_cast<std::int64_t>(t) - std::bit_cast<std::int64_t>(kShifter);
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>((k >> 4) + 1023) << 52);
  return (p * kExp2Sixteenths[k & 15]) * scale;
}

// --- the RBF kernel's arithmetic, in float (docs/svr.md, "The kernel in float") ---------------
// Every RBF row of every table is K_ij = kernel_exp(−γ·Σ_f (x_if − x_jf)²), all in float: the
// differences of the features rounded to float, the squares summed in feature order with fused
// multiply-adds, and the exponential below. Sixteen lanes of floats per AVX-512 vector instead of
// eight of doubles, and no cancellation in the distance of near samples (LIBSVM forms it as
// ‖x_i‖² + ‖x_j‖² − 2·x_i·x_j).

constexpr float kShifterF = 12582912.0f;  // 1.5·2^23: adding it rounds to an integer
/// 8 / ln 2, rounded to float.
constexpr float kEighthsPerNat = 0x1.715476p+3f;
// ln 2 / 8 split so that n·kLn2HiEighth is exact for |n| < 2^15 (Cody & Waite range reduction).
constexpr float kLn2HiEighth = 0.693359375f / 8.0f;
constexpr float kLn2LoEighth = -0x1.bd0106p-16f;
/// −γ·d² is clamped here: e^−87 is below every kernel value that can matter (float's smallest
/// normal is e^−87.3), and 2^⌊n/8⌋ stays a normal float.
constexpr float kKernelExponentMin = -87.0f;

/// 2^(j/8) for j = 0 … 7, each the float nearest the exact value, twice over (an AVX-512
/// permutation reads sixteen entries by the low four bits of its index).
alignas(64) constexpr float kExp2Eighths[16] = {
    0x1.000000p+0f, 0x1.172b84p+0f, 0x1.306fe0p+0f, 0x1.4bfdaep+0f, 0x1.6a09e6p+0f, 0x1.8ace54p+0f,
    0x1.ae89fap+0f, 0x1.d5818ep+0f, 0x1.000000p+0f, 0x1.172b84p+0f, 0x1.306fe0p+0f, 0x1.4bfdaep+0f,
    0x1.6a09e6p+0f, 0x1.8ace54p+0f, 0x1.ae89fap+0f, 0x1.d5818ep+0f};

/// The Taylor coefficients of e^r, 1/4! down to 1/0!, for Horner's rule.
constexpr float kExpCoefficientsF[] = {1.0f / 24.0f, 1.0f / 6.0f, 0.5f, 1.0f, 1.0f};

/// e^y for kKernelExponentMin ≤ y ≤ 0 in float: e^y = 2^(n/8)·e^r with n = round(8·y/ln 2) and
/// |r| ≤ ln 2 / 16; 2^(n/8) is 2^⌊n/8⌋ (built in the exponent bits) times 2^((n mod 8)/8) from
/// kExp2Eighths, and e^r the Taylor series to degree 4, whose truncation error r^5/5! < 1.3e-9
/// is far under a float's half-step of 3e-8. Each step is a fused multiply-add or one rounded
/// operation, the same in every table, so every table gives the same float; it is within two
/// float steps of e^y (tested against std::exp in double: loops_test).
FOGDRIFT_INLINE float kernel_exp(float y) {
  y = y < kKernelExponentMin ? kKernelExponentMin : y;
  const float t = __builtin_fmaf(y, kEighthsPerNat, kShifterF);
  const float n = t - kShifterF;
  const float r = __builtin_fmaf(n, -kLn2LoEighth, __builtin_fmaf(n, -kLn2HiEighth, y));
  float p = kExpCoefficientsF[0];
  for (std::size_t c = 1; c < std::size(kExpCoefficientsF); ++c)
    p = __builtin_fmaf(p, r, kExpCoefficientsF[c]);
  const std::int32_t k = std::bit_cast<std::int32_t>(t) - std::bit_cast<std::int32_t>(kShifterF);
  const float scale = std::bit_cast<float>(static_cast<std::uint32_t>((k >> 3) + 127) << 23);
  return (p * kExp2Eighths[k & 7]) * scale;
}

constexpr std::size_t kBlock = 256;  // columns per block: the accumulators stay in L1

/// acc[j] = x_i·x_{j0+j} for j < m, summed over features in order (LIBSVM's order), from the
/// feature-major copy `xt` (feature f of column j at xt[f·stride + j]).
FOGDRIFT_INLINE void dot_block(const double* xi, const double* xt, std::size_t stride,
                               std::size_t d, std::size_t j0, std::size_t m, double* acc) {
  for (std::size_t j = 0; j < m; ++j) acc[j] = 0.0;
  for (std::size_t f = 0; f < d; ++f) {
    const double xf = xi[f];
    const double* col = xt + f * stride + j0;
    for (std::size_t j = 0; j < m; ++j) acc[j] += xf * col[j];
  }
}

// --- kernel rows ---------------------------------------------------------------------------------

/// dist[j] = Σ_f (x_if − x_jf)² for j < m, in feature order, from the float feature-major copy
/// `xt` (feature f of column j at xt[f·stride + j]).
FOGDRIFT_INLINE void distance_block(const float* xi, const float* xt, std::size_t stride,
                                    std::size_t d, std::size_t j0, std::size_t m, float* dist) {
  for (std::size_t j = 0; j < m; ++j) dist[j] = 0.0f;
  for (std::size_t f = 0; f < d; ++f) {
    const float xf = xi[f];
    const float* col = xt + f * stride + j0;
    for (std::size_t j = 0; j < m; ++j) {
      const float diff = xf - col[j];
      dist[j] = __builtin_fmaf(diff, diff, dist[j]);
    }
  }
}

FOGDRIFT_INLINE void libsvm_rbf_row(const double* xi, double sq_i, const double* xt,
                                    std::size_t stride, const double* sq, std::size_t n,
                                    std::size_t d, double gamma, float* out) {
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

FOGDRIFT_INLINE void rbf_row(const float* xi, const float* xt, std::size_t stride, std::size_t n,
                             std::size_t d, double gamma, float* out) {
  const float minus_gamma = -static_cast<float>(gamma);
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - j0);
    distance_block(xi, xt, stride, d, j0, m, out + j0);
    for (std::size_t j = 0; j < m; ++j) out[j0 + j] = kernel_exp(minus_gamma * out[j0 + j]);
  }
}

/// A vector table's rows of R + 1 rows side by side (entry R), for rbf_rows_by.
using RowsOf = void (*)(const float* xs, const float* xt, std::size_t stride, std::size_t n,
                        std::size_t d, double gamma, float* out, std::size_t ld);

/// rbf_rows by groups of up to kRowsAtOnce rows, each group by `rows_of`'s entry for its size.
inline void rbf_rows_by(const RowsOf (&rows_of)[kRowsAtOnce], const float* xs, std::size_t m,
                        const float* xt, std::size_t stride, std::size_t n, std::size_t d,
                        double gamma, float* out, std::size_t ld) {
  for (std::size_t r = 0; r < m; r += kRowsAtOnce)
    rows_of[std::min(kRowsAtOnce, m - r) - 1](xs + r * d, xt, stride, n, d, gamma, out + r * ld,
                                              ld);
}

FOGDRIFT_INLINE void rbf_rows(const float* xs, std::size_t m, const float* xt, std::size_t stride,
                              std::size_t n, std::size_t d, double gamma, float* out,
                              std::size_t ld) {
  for (std::size_t r = 0; r < m; ++r) rbf_row(xs + r * d, xt, stride, n, d, gamma, out + r * ld);
}

FOGDRIFT_INLINE void linear_row(const double* xi, const double* xt, std::size_t stride,
                                std::size_t n, std::size_t d, float* out) {
  double acc[kBlock];
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock) {
    const std::size_t m = std::min(kBlock, n - j0);
    dot_block(xi, xt, stride, d, j0, m, acc);
    for (std::size_t j = 0; j < m; ++j) out[j0 + j] = static_cast<float>(acc[j]);
  }
}

FOGDRIFT_INLINE void distance_row(const float* xi, const float* xt, std::size_t stride,
                                  std::size_t n, std::size_t d, float* out) {
  for (std::size_t j0 = 0; j0 < n; j0 += kBlock)
    distance_block(xi, xt, stride, d, j0, std::min(kBlock, n - j0), out + j0);
}

FOGDRIFT_INLINE void rbf_row_from_distances(const float* dist, std::size_t n, double gamma,
                                            float* out) {
  const float minus_gamma = -static_cast<float>(gamma);
  for (std::size_t j = 0; j < n; ++j) out[j] = kernel_exp(minus_gamma * dist[j]);
}

// --- gradient updates ----------------------------------------------------------------------------

FOGDRIFT_INLINE void update_gradient(double* g, const std::int8_t* y, const float* k_i,
                                     const float* k_j, double a_i, double a_j, std::size_t len) {
  for (std::size_t k = 0; k < len; ++k)
    g[k] += static_cast<double>(y[k]) *
            (static_cast<double>(k_i[k]) * a_i + static_cast<double>(k_j[k]) * a_j);
}

FOGDRIFT_INLINE void add_scaled(double* g, const std::int8_t* y, const float* k_row, double a,
                                std::size_t begin, std::size_t end) {
  for (std::size_t k = begin; k < end; ++k)
    g[k] += static_cast<double>(y[k]) * (a * static_cast<double>(k_row[k]));
}

FOGDRIFT_INLINE void add_row(double* g, const float* k_row, double a, std::size_t begin,
                             std::size_t end) {
  for (std::size_t k = begin; k < end; ++k) g[k] += a * static_cast<double>(k_row[k]);
}

// --- LIBSVM's working-set selection (2l variables) -----------------------------------------------

/// t ∈ I_up: α_t may grow along y_t (LIBSVM: y=+1 not at the upper bound, y=−1 not at the lower).
/// Written with & and | rather than ?: or && so that the loops have no branches.
inline bool in_up(std::int8_t y, std::uint8_t s) {
  return ((y > 0) & (s != kUpperBound)) | ((y < 0) & (s != kLowerBound));
}
inline bool in_low(std::int8_t y, std::uint8_t s) {
  return ((y > 0) & (s != kLowerBound)) | ((y < 0) & (s != kUpperBound));
}

/// The curvature of the two-variable subproblem, τ when not positive (LIBSVM's quad_coef).
inline double curvature(double qd_i, double qd_j, float k_ij, double tau) {
  const double quad = (qd_i + qd_j) - 2.0 * static_cast<double>(k_ij);
  return quad > 0 ? quad : tau;
}

/// The pair solver's curvature, from QD_i + QD_k: τ when it is not above τ (a curvature in
/// (0, τ] is as degenerate as zero; this is what a vector max computes in one instruction, NaN
/// included). 2·K_ik is exact, so a fused multiply-add computes the same difference.
inline double pair_curvature(double qd_sum, float k_ik, double tau) {
  const double quad = qd_sum - 2.0 * static_cast<double>(k_ik);
  return quad > tau ? quad : tau;
}

inline double objective_decrease(double grad_diff, double qd_i, double qd_j, float k_ij,
                                 double tau) {
  return -(grad_diff * grad_diff) / curvature(qd_i, qd_j, k_ij, tau);
}

inline Selection select_i(const double* g, const std::int8_t* y, const std::uint8_t* status,
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

/// select_i over [begin, len), continuing from `out`: the tail of a vectorised select_i.
inline void select_i_tail(const double* g, const std::int8_t* y, const std::uint8_t* status,
                          std::size_t begin, std::size_t len, Selection& out) {
  for (std::size_t t = begin; t < len; ++t) {
    if (!in_up(y[t], status[t])) continue;
    const double v = -static_cast<double>(y[t]) * g[t];
    if (v >= out.value) out = {v, static_cast<std::int64_t>(t)};
  }
}

inline SelectionJ select_j(const double* g, const std::int8_t* y, const std::uint8_t* status,
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

/// select_j over [begin, len), continuing from `out` and the smallest objective so far.
inline void select_j_tail(const double* g, const std::int8_t* y, const std::uint8_t* status,
                          const float* k_i, const double* qd, double qd_i, double g_max, double tau,
                          std::size_t begin, std::size_t len, SelectionJ& out, double& obj_min) {
  for (std::size_t j = begin; j < len; ++j) {
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
}

// --- the pair solver's loops (one gradient per sample) -------------------------------------------

/// The gradient array of update_and_select_up: written when it updates, only read when not.
template <bool kUpdate>
using Gradient = std::conditional_t<kUpdate, double*, const double*>;

/// update_and_select_up over [begin, len), continuing from `out`; the portable version, and the
/// tail of the vectorised ones.
template <bool kUpdate>
inline void update_and_select_up_tail(Gradient<kUpdate> f, const double* up, const float* k_i,
                                      const float* k_j, double b_i, double b_j, std::size_t begin,
                                      std::size_t len, Selection& out) {
  for (std::size_t k = begin; k < len; ++k) {
    if constexpr (kUpdate)
      f[k] += static_cast<double>(k_i[k]) * b_i + static_cast<double>(k_j[k]) * b_j;
    const double v = up[k] - f[k];
    if (v >= out.value) out = {v, static_cast<std::int64_t>(k)};
  }
}

/// No sample offers a variable when the best value is a kNoVariable offset.
inline Selection none_if_offsets_only(const Selection& s) {
  return s.value < kNoVariable / 2 ? Selection{-DBL_MAX, -1} : s;
}

inline Selection update_and_select_up(double* f, const double* up, const float* k_i,
                                      const float* k_j, double b_i, double b_j, std::size_t len) {
  Selection out{-DBL_MAX, -1};
  update_and_select_up_tail<true>(f, up, k_i, k_j, b_i, b_j, 0, len, out);
  return none_if_offsets_only(out);
}

inline Selection select_up(const double* f, const double* up, std::size_t len) {
  Selection out{-DBL_MAX, -1};
  update_and_select_up_tail<false>(f, up, nullptr, nullptr, 0.0, 0.0, 0, len, out);
  return none_if_offsets_only(out);
}

/// conjugate_update_and_select_up over [begin, len), continuing from `out`.
inline void conjugate_tail(double* f, const double* up, const float* k_i, const float* k_j,
                           double* kd, double lambda, double t, std::size_t begin, std::size_t len,
                           Selection& out) {
  for (std::size_t k = begin; k < len; ++k) {
    const double q = (static_cast<double>(k_i[k]) - static_cast<double>(k_j[k])) + lambda * kd[k];
    kd[k] = q;
    f[k] += t * q;
    const double v = up[k] - f[k];
    if (v >= out.value) out = {v, static_cast<std::int64_t>(k)};
  }
}

inline Selection conjugate_update_and_select_up(double* f, const double* up, const float* k_i,
                                                const float* k_j, double* kd, double lambda,
                                                double t, std::size_t len) {
  Selection out{-DBL_MAX, -1};
  conjugate_tail(f, up, k_i, k_j, kd, lambda, t, 0, len, out);
  return none_if_offsets_only(out);
}

/// select_low over [begin, len), continuing from `out` and the best gain so far num/den; the
/// portable version, and the tail of the vectorised ones.
inline void select_low_tail(const double* f, const double* low, const float* k_i, const double* qd,
                            double qd_i, double g_max, double tau, std::size_t begin,
                            std::size_t len, SelectionJ& out, double& best_num, double& best_den) {
  for (std::size_t k = begin; k < len; ++k) {
    const double yg = f[k] + low[k];
    out.g_max2 = yg > out.g_max2 ? yg : out.g_max2;
    const double grad_diff = g_max + yg;
    if (!(grad_diff > 0)) continue;
    const double num = grad_diff * grad_diff,
                 den = pair_curvature(qd_i + (qd != nullptr ? qd[k] : qd_i), k_i[k], tau);
    if (num * best_den >= best_num * den) {
      best_num = num;
      best_den = den;
      out.index = static_cast<std::int64_t>(k);
    }
  }
}

inline SelectionJ select_low(const double* f, const double* low, const float* k_i, const double* qd,
                             double qd_i, double g_max, double tau, std::size_t len) {
  SelectionJ out;
  out.g_max2 = -DBL_MAX;
  double best_num = 0, best_den = 1;  // the best gain so far, (G_max + y·G)² / curvature
  select_low_tail(f, low, k_i, qd, qd_i, g_max, tau, 0, len, out, best_num, best_den);
  return out;
}

// --- merging the lanes of a vectorised loop ------------------------------------------------------

/// The last maximiser over `lanes` lanes, each holding its own (index −1: none), into `out`.
inline void merge_max(const double* value, const double* index, int lanes, Selection& out) {
  for (int t = 0; t < lanes; ++t) {
    if (index[t] < 0) continue;
    const auto idx = static_cast<std::int64_t>(index[t]);
    if (value[t] > out.value || (value[t] == out.value && idx > out.index)) out = {value[t], idx};
  }
}

/// The best gain num/den over `lanes` lanes (cross-multiplied, the larger index on ties), and the
/// largest g_max2.
inline void merge_gain(const double* num, const double* den, const double* index,
                       const double* g_max2, int lanes, SelectionJ& out, double& num_max,
                       double& den_max) {
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

#undef FOGDRIFT_INLINE

}  // namespace fogdrift::svr::detail::scalar
