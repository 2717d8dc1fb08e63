// The inner loops of the SMO solver and of kernel-row evaluation, kept in one translation unit so
// that they can be compiled for AVX2 next to a portable version (GCC's target_clones picks one at
// load time) and with the floating-point flags they need:
//  * -ffp-contract=off: no fused multiply-add, so every product and sum rounds exactly as in
//    LIBSVM's scalar C++ and the engine walks the same path through the dual.
//  * -ffinite-math-only -fno-signed-zeros: lets the compiler vectorise the max/min reductions of
//    the working-set selection. The inputs are finite by validation, and sentinels are ±DBL_MAX.
// Internal header: not installed, not part of the API.
#pragma once

#include <cstddef>
#include <cstdint>

namespace fogdrift::svr::detail {

/// Bound status of a dual variable (LIBSVM's alpha_status).
enum : std::uint8_t { kLowerBound = 0, kUpperBound = 1, kFree = 2 };

/// e^x for x ≤ 0, accurate to about one unit in the last place of a double and rounded to float.
/// Agrees with (float)std::exp(x) except, very rarely, when std::exp(x) lies within 2 ulp of a
/// float rounding boundary. Exposed for its test.
float exp_to_float(double x);

/// One row of the RBF kernel over n columns: out[j] = (float) exp(−γ·((‖x_i‖² + ‖x_j‖²) −
/// 2·x_i·x_j)), the expression and rounding LIBSVM uses. `xt` holds the columns feature-major
/// (feature f of column j at xt[f·stride + j]; stride ≥ n), `sq` their squared norms, `xi` row i
/// (d values, contiguous). A row of a subset of columns is the same floats as the full row's.
void rbf_row(const double* xi, double sq_i, const double* xt, std::size_t stride, const double* sq,
             std::size_t n, std::size_t d, double gamma, float* out);

/// One row of the linear kernel: out[j] = (float) x_i·x_j, columns as in rbf_row.
void linear_row(const double* xi, const double* xt, std::size_t stride, std::size_t n,
                std::size_t d, float* out);

/// One RBF row from precomputed squared distances: out[j] = exp(−γ·dist[j]).
void rbf_row_from_distances(const float* dist, std::size_t n, double gamma, float* out);

/// Squared distances of row i to all rows, as LIBSVM forms them: (‖x_i‖² + ‖x_j‖²) − 2·x_i·x_j.
void distance_row(const double* xi, double sq_i, const double* xt, const double* sq, std::size_t n,
                  std::size_t d, float* out);

// The solver works with kernel rows in its permuted variable order, unsigned: K_r[index[j]]. The
// signs of Q_ij = y_i·y_j·K_ij are applied inside the loops below; every sign flip is exact, so
// the results are bit for bit those of LIBSVM's signed rows.

/// out[j] = row[index[j]] for begin ≤ j < end.
void gather(const float* row, const std::int32_t* index, std::size_t begin, std::size_t end,
            float* out);

/// g[k] += y_k·(K_i[k]·a_i + K_j[k]·a_j) for k < len, with a_i = y_i·Δα_i, a_j = y_j·Δα_j: the
/// gradient update after one SMO step (LIBSVM: G[k] += Q_i[k]·Δα_i + Q_j[k]·Δα_j).
void update_gradient(double* g, const std::int8_t* y, const float* k_i, const float* k_j,
                     double a_i, double a_j, std::size_t len);

/// g[k] += y_k·(a·K[k]) for begin ≤ k < end (with a = y_i·scale: g += scale·Q_i).
void add_scaled(double* g, const std::int8_t* y, const float* k_row, double a, std::size_t begin,
                std::size_t end);

/// First half of LIBSVM's second-order working-set selection: the last index t of
/// argmax {−y_t·G_t : t ∈ I_up}. Returns −1 when I_up is empty.
struct Selection {
  double value = 0;
  std::int64_t index = -1;
};
Selection select_i(const double* g, const std::int8_t* y, const std::uint8_t* status,
                   std::size_t len);

/// Second half: with G_max = −y_i·G_i, the last index j ∈ I_low with G_max + y_j·G_j > 0 that
/// minimises −(G_max + y_j·G_j)² / (QD_i + QD_j − 2·K_ij) (τ for a non-positive denominator;
/// LIBSVM writes the denominator QD_i + QD_j − 2·y_i·y_j·Q_ij, the same number); also returns
/// max {y_j·G_j : j ∈ I_low} for the stopping rule. `k_i` is row i in solver order.
struct SelectionJ {
  double g_max2 = 0;
  std::int64_t index = -1;
};
SelectionJ select_j(const double* g, const std::int8_t* y, const std::uint8_t* status,
                    const float* k_i, const double* qd, double qd_i, double g_max, double tau,
                    std::size_t len);

/// The portable versions of the two selections, for the test that checks the vectorised ones.
Selection select_i_reference(const double* g, const std::int8_t* y, const std::uint8_t* status,
                             std::size_t len);
SelectionJ select_j_reference(const double* g, const std::int8_t* y, const std::uint8_t* status,
                              const float* k_i, const double* qd, double qd_i, double g_max,
                              double tau, std::size_t len);

// The pair solver (smo_solver.hpp) keeps one gradient per sample, f_k = (Kβ)_k − z_k with
// β = α⁺ − α⁻: LIBSVM's two gradients are G⁺_k = f_k + ε and G⁻_k = ε − f_k. For sample k, the
// best of its variables in I_up has −y·G = up_k − f_k and the best in I_low has y·G = f_k + low_k,
// where the offsets up_k, low_k ∈ {+ε, −ε} depend only on the bounds of α⁺_k and α⁻_k, and are
// kNoVariable when neither variable qualifies.

/// Offset of a sample with no variable in I_up (I_low). Finite, so that the loops may assume
/// finite values; far below any gradient (|f| < 1e50 by far for finite C and targets).
constexpr double kNoVariable = -1e100;

/// The last argmax over k < len of up[k] − f[k]; index −1 when every offset is kNoVariable.
Selection select_up(const double* f, const double* up, std::size_t len);

/// The pair solver's gradient update fused with the next select_up: f[k] += K_i[k]·b_i +
/// K_j[k]·b_j (b = Δβ of the step's two samples; K_j = K_i and b_j = 0 when they are one
/// sample), then the select_up of the updated f. One pass over the active samples instead of two.
Selection update_and_select_up(double* f, const double* up, const float* k_i, const float* k_j,
                               double b_i, double b_j, std::size_t len);

/// Second-order selection over samples: with G_max from select_up, a k with
/// G_max + f_k + low_k > 0 that maximises the gain (G_max + f_k + low_k)² / (QD_i + QD_k − 2·K_ik)
/// (τ for a non-positive denominator), compared by cross-multiplication (so among equal gains it
/// is not always the last); also returns max_k f_k + low_k for the stopping rule.
SelectionJ select_low(const double* f, const double* low, const float* k_i, const double* qd,
                      double qd_i, double g_max, double tau, std::size_t len);

/// The pair solver's conjugate step (pair_solver.cpp) fused with the next select_up: for k < len,
/// kd[k] = (K_i[k] − K_j[k]) + λ·kd[k] (the kernel times the new direction d' = u + λ·d, from K·d
/// in place), f[k] += t·kd[k], then the select_up of the updated f. With λ = 0 and t = 0 it only
/// records K_i − K_j.
Selection conjugate_update_and_select_up(double* f, const double* up, const float* k_i,
                                         const float* k_j, double* kd, double lambda, double t,
                                         std::size_t len);

/// g[k] += a·K[k] for begin ≤ k < end.
void add_row(double* g, const float* k_row, double a, std::size_t begin, std::size_t end);

/// The instruction sets the pair loops and the RBF rows are built for; the fastest the processor
/// has is used. Exposed, with the functions below, for the test that checks every version
/// against the portable one.
enum class Isa { portable, avx2, avx512 };
bool available(Isa isa);
Isa best_isa();  ///< the fastest this processor has (portable in sanitizer builds)
/// rbf_row and rbf_row_from_distances in one version; every version gives the same floats.
void rbf_row_with(Isa isa, const double* xi, double sq_i, const double* xt, std::size_t stride,
                  const double* sq, std::size_t n, std::size_t d, double gamma, float* out);
void rbf_row_from_distances_with(Isa isa, const float* dist, std::size_t n, double gamma,
                                 float* out);
Selection update_and_select_up_with(Isa isa, double* f, const double* up, const float* k_i,
                                    const float* k_j, double b_i, double b_j, std::size_t len);
Selection conjugate_update_and_select_up_with(Isa isa, double* f, const double* up,
                                              const float* k_i, const float* k_j, double* kd,
                                              double lambda, double t, std::size_t len);
SelectionJ select_low_with(Isa isa, const double* f, const double* low, const float* k_i,
                           const double* qd, double qd_i, double g_max, double tau,
                           std::size_t len);

}  // namespace fogdrift::svr::detail
