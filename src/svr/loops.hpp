// The inner loops of the SMO solvers and of kernel-row evaluation, as one table of functions per
// instruction set, one file per instruction set:
//   loops_portable.cpp  the portable C++ (loops_scalar.hpp), for any processor;
//   loops_avx2.cpp      AVX2: hand-vectorised selections and RBF rows, the rest vectorised by
//                       the compiler;
//   loops_avx512.cpp    AVX-512F: the pair solver's loops on eight lanes of doubles and the RBF
//                       rows on sixteen of floats, the rest as in AVX2.
// loops.cpp chooses the table once, at the first call: the fastest the processor has, or the one
// the environment variable FOGDRIFT_ISA names (docs/reliability.md, "Same bits everywhere").
//
// Every table computes the same numbers bit for bit: the same products and sums in the same
// order, each rounded as a scalar (IEEE arithmetic rounds a lane as it rounds a scalar), and the
// same element chosen on ties. So a fit takes the same path through the dual, and writes the
// same model, on every processor (loops_test and cli_test check it). The files are compiled with
//  * -ffp-contract=off: no fused multiply-add the code does not write, so every product and sum
//    rounds exactly as in LIBSVM's scalar C++ and the solvers walk the same path through the
//    dual; the RBF rows' fused multiply-adds are written out (kernel_exp, loops_scalar.hpp), the
//    same in every table;
//  * -ffinite-math-only -fno-signed-zeros: lets the compiler vectorise the max/min reductions of
//    the working-set selection. The inputs are finite by validation, and sentinels are ±DBL_MAX.
// Internal header: not installed, not part of the API.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace fogdrift::svr::detail {

/// Bound status of a dual variable (LIBSVM's alpha_status).
enum : std::uint8_t { kLowerBound = 0, kUpperBound = 1, kFree = 2 };

/// LIBSVM's RBF kernel's exponential: e^x for x ≤ 0, accurate to about one unit in the last
/// place of a double and rounded to float. Agrees with (float)std::exp(x) except, very rarely,
/// when std::exp(x) lies within 2 ulp of a float rounding boundary. Exposed for its test.
float exp_to_float(double x);

/// The RBF kernel's exponential in float, e^y for y ≤ 0 (loops_scalar.hpp, kernel_exp): within
/// two float steps of e^y, the same float in every table. Exposed for its test.
float kernel_exp(float y);

/// The result of a maximisation over variables: the value and the last index reaching it (−1:
/// none qualified).
struct Selection {
  double value = 0;
  std::int64_t index = -1;
};

/// The second half of a working-set selection: the index chosen and max {y_j·G_j : j ∈ I_low}
/// for the stopping rule.
struct SelectionJ {
  double g_max2 = 0;
  std::int64_t index = -1;
};

// The pair solver (smo_solver.hpp) keeps one gradient per sample, f_k = (Kβ)_k − z_k with
// β = α⁺ − α⁻: LIBSVM's two gradients are G⁺_k = f_k + ε and G⁻_k = ε − f_k. For sample k, the
// best of its variables in I_up has −y·G = up_k − f_k and the best in I_low has y·G = f_k + low_k,
// where the offsets up_k, low_k ∈ {+ε, −ε} depend only on the bounds of α⁺_k and α⁻_k, and are
// kNoVariable when neither variable qualifies.

/// Offset of a sample with no variable in I_up (I_low). Finite, so that the loops may assume
/// finite values; far below any gradient (|f| < 1e50 by far for finite C and targets).
constexpr double kNoVariable = -1e100;

/// The rows rbf_rows computes side by side: each column read feeds this many rows.
constexpr std::size_t kRowsAtOnce = 4;

/// The instruction sets the loops are built for.
enum class Isa { portable, avx2, avx512 };

/// "portable", "avx2", "avx512": the names FOGDRIFT_ISA takes.
std::string_view isa_name(Isa isa);

/// One instruction set's loops. Columns of kernel rows are given feature-major: feature f of
/// column j at xt[f·stride + j] (stride ≥ n), in float for the RBF kernel and in double for the
/// linear one; row i is `xi` (d values, contiguous).
///
/// The solver works with kernel rows in its permuted variable order, unsigned: K_r[index[j]].
/// The signs of Q_ij = y_i·y_j·K_ij are applied inside the loops; every sign flip is exact, so
/// the results are bit for bit those of LIBSVM's signed rows.
struct Loops {
  Isa isa;

  /// One row of the RBF kernel as LIBSVM computes it (KernelArithmetic::libsvm, the default):
  /// out[j] = (float) exp(−γ·((‖x_i‖² + ‖x_j‖²) − 2·x_i·x_j)) in double,
  /// the expression and rounding LIBSVM uses, from the double features `xt` and their squared
  /// norms `sq`. A row of a subset of columns is the same floats as the full row's.
  void (*libsvm_rbf_row)(const double* xi, double sq_i, const double* xt, std::size_t stride,
                         const double* sq, std::size_t n, std::size_t d, double gamma, float* out);
  /// One row of the RBF kernel in float (KernelArithmetic::single, the searches'): out[j] =
  /// kernel_exp(−γ·Σ_f (x_if − x_jf)²), all in float (γ rounded to float; loops_scalar.hpp). A row
  /// of a subset of columns is the same floats as the full row's.
  void (*rbf_row)(const float* xi, const float* xt, std::size_t stride, std::size_t n,
                  std::size_t d, double gamma, float* out);
  /// `m` rows of rbf_row over the same columns (row r: the d features at xs + r·d, its values at
  /// out + r·ld), the same floats as m calls of rbf_row; the columns are read once for every
  /// kRowsAtOnce rows rather than once a row (the held-out predictions of a search, svr.cpp).
  void (*rbf_rows)(const float* xs, std::size_t m, const float* xt, std::size_t stride,
                   std::size_t n, std::size_t d, double gamma, float* out, std::size_t ld);
  /// One row of the linear kernel: out[j] = (float) x_i·x_j.
  void (*linear_row)(const double* xi, const double* xt, std::size_t stride, std::size_t n,
                     std::size_t d, float* out);
  /// Squared distances of row i to n columns, as rbf_row forms them: Σ_f (x_if − x_jf)².
  void (*distance_row)(const float* xi, const float* xt, std::size_t stride, std::size_t n,
                       std::size_t d, float* out);
  /// One RBF row from squared distances as distance_row gives them: out[j] =
  /// kernel_exp(−γ·dist[j]), the same floats as rbf_row.
  void (*rbf_row_from_distances)(const float* dist, std::size_t n, double gamma, float* out);

  /// g[k] += y_k·(K_i[k]·a_i + K_j[k]·a_j) for k < len, with a_i = y_i·Δα_i, a_j = y_j·Δα_j: the
  /// gradient update after one SMO step (LIBSVM: G[k] += Q_i[k]·Δα_i + Q_j[k]·Δα_j).
  void (*update_gradient)(double* g, const std::int8_t* y, const float* k_i, const float* k_j,
                          double a_i, double a_j, std::size_t len);
  /// g[k] += y_k·(a·K[k]) for begin ≤ k < end (with a = y_i·scale: g += scale·Q_i).
  void (*add_scaled)(double* g, const std::int8_t* y, const float* k_row, double a,
                     std::size_t begin, std::size_t end);
  /// g[k] += a·K[k] for begin ≤ k < end.
  void (*add_row)(double* g, const float* k_row, double a, std::size_t begin, std::size_t end);

  /// First half of LIBSVM's second-order working-set selection: the last index t of
  /// argmax {−y_t·G_t : t ∈ I_up}. Returns −1 when I_up is empty.
  Selection (*select_i)(const double* g, const std::int8_t* y, const std::uint8_t* status,
                        std::size_t len);
  /// Second half: with G_max = −y_i·G_i, the last index j ∈ I_low with G_max + y_j·G_j > 0 that
  /// minimises −(G_max + y_j·G_j)² / (QD_i + QD_j − 2·K_ij) (τ for a non-positive denominator;
  /// LIBSVM writes the denominator QD_i + QD_j − 2·y_i·y_j·Q_ij, the same number); also returns
  /// max {y_j·G_j : j ∈ I_low} for the stopping rule. `k_i` is row i in solver order.
  SelectionJ (*select_j)(const double* g, const std::int8_t* y, const std::uint8_t* status,
                         const float* k_i, const double* qd, double qd_i, double g_max, double tau,
                         std::size_t len);

  /// The pair solver's first selection: the last argmax over k < len of up[k] − f[k]; index −1
  /// when every offset is kNoVariable.
  Selection (*select_up)(const double* f, const double* up, std::size_t len);
  /// The pair solver's gradient update fused with the next select_up: f[k] += K_i[k]·b_i +
  /// K_j[k]·b_j (b = Δβ of the step's two samples; K_j = K_i and b_j = 0 when they are one
  /// sample), then the select_up of the updated f. One pass over the active samples, not two.
  Selection (*update_and_select_up)(double* f, const double* up, const float* k_i, const float* k_j,
                                    double b_i, double b_j, std::size_t len);
  /// The pair solver's conjugate step (pair_solver.cpp) fused with the next select_up: for
  /// k < len, kd[k] = (K_i[k] − K_j[k]) + λ·kd[k] (the kernel times the new direction
  /// d' = u + λ·d, from K·d in place), f[k] += t·kd[k], then the select_up of the updated f.
  /// With λ = 0 and t = 0 it only records K_i − K_j.
  Selection (*conjugate_update_and_select_up)(double* f, const double* up, const float* k_i,
                                              const float* k_j, double* kd, double lambda, double t,
                                              std::size_t len);
  /// Second-order selection over samples: with G_max from select_up, a k with
  /// G_max + f_k + low_k > 0 that maximises the gain (G_max + f_k + low_k)² / (QD_i + QD_k −
  /// 2·K_ik) (τ for a denominator not above τ: scalar::pair_curvature), compared by
  /// cross-multiplication (so among equal gains it is not always the last); also returns
  /// max_k f_k + low_k for the stopping rule. `qd` may be null when every QD_k equals QD_i (the
  /// RBF kernel's diagonal is 1): one array fewer to read.
  SelectionJ (*select_low)(const double* f, const double* low, const float* k_i, const double* qd,
                           double qd_i, double g_max, double tau, std::size_t len);
};

/// The table in use, chosen at the first call: the one FOGDRIFT_ISA names (portable, avx2,
/// avx512), or the fastest this processor has when it is unset, empty or "auto". Throws
/// OptionError naming FOGDRIFT_ISA when it names an unknown set or one the processor lacks; the
/// next call tries again.
const Loops& loops();

/// The table a value of FOGDRIFT_ISA names: "portable", "avx2", "avx512", or "" and "auto" for
/// the fastest this processor has. Throws OptionError naming FOGDRIFT_ISA as loops() does.
const Loops& loops_named(std::string_view name);

/// One instruction set's table; nullptr when this processor (or this build) lacks it.
const Loops* loops_for(Isa isa);

/// The tables, one a file (loops_portable.cpp, loops_avx2.cpp, loops_avx512.cpp). The vector
/// ones return nullptr on processors without the instruction set and in builds for other
/// architectures.
const Loops& portable_loops();
const Loops* avx2_loops();
const Loops* avx512_loops();

/// out[j] = row[index[j]] for begin ≤ j < end. A plain indexed copy on every processor: AVX2's
/// gather instruction is no faster than scalar loads on the processors this was measured on,
/// and rows are gathered rarely (rows.hpp, OrderedRows).
inline void gather(const float* row, const std::int32_t* index, std::size_t begin, std::size_t end,
                   float* out) {
  for (std::size_t j = begin; j < end; ++j) out[j] = row[index[j]];
}

}  // namespace fogdrift::svr::detail
