// The dual of ε-SVR (docs/method.md eq. 5) solved by sequential minimal optimisation.
//
// With 2l variables α = (α⁺, α⁻), signs y = (+1…, −1…), Q_ij = y_i·y_j·K(x_i mod l, x_j mod l)
// and p = (ε − y_t, ε + y_t), the dual is
//     min ½αᵀQα + pᵀα   subject to  yᵀα = 0,  0 ≤ α_i ≤ C,
// exactly LIBSVM's formulation. Both solvers use LIBSVM 3.24's method: second-order working-set
// selection (Fan, Chen & Lin, JMLR 6, 2005, WSS 2 with τ = 1e-12), the analytic two-variable
// update with clipping, LIBSVM's shrinking (every min(2l, 1000) iterations, with one unshrink when
// the violation first falls below 10·tolerance), gradient reconstruction, the stopping rule
// max_{I_up} −y_iG_i − min_{I_low} −y_jG_j < tolerance, and the bias ρ as the mean of y_iG_i over
// free variables (the midpoint of the feasible interval when none is free).
//
//  * The pair solver (the default) uses that the two variables of a sample share their gradient
//    (G⁺_k + G⁻_k = 2ε): it keeps one gradient and one kernel row entry per sample, half of
//    LIBSVM's, walks l samples instead of 2l variables, and fuses the gradient update with the
//    next selection. Ties can break differently and a sample is shrunk only with both of its
//    variables, so its path differs from LIBSVM's in detail; it stops by the same rule, so its
//    objective agrees with LIBSVM's to about the tolerance (2e-5 relative or better on the
//    benchmark data) and at a tight tolerance its predictions are LIBSVM's. It also takes
//    conjugate steps (SolverOptions::conjugate): the working pair's direction is made
//    Q-conjugate to the last one, which halves the iterations at large C. And after a
//    shrinking round it may solve the free samples' small quadratic directly, the others held
//    at their bounds (SolverOptions::newton; docs/svr.md, "Newton steps on the free set"): on
//    the paper's C = 1000 fits down to a thirtieth of the iterations.
//  * SolverOptions::libsvm_path selects the solver that follows LIBSVM step for step over the 2l
//    variables: on the same data it visits the same working sets, so its model, iteration count
//    and support vectors are LIBSVM's to rounding. `fogdrift svr train --solver libsvm` uses it,
//    for users who audit a model against svm-train; every other caller uses the pair solver.
//
// Both add speed (vectorised loops, fast kernel rows, see kernel.hpp) and warm starts: a previous
// solution of the same data is scaled by C/C_previous, which keeps it feasible and keeps every
// bound variable at its bound; when the kernel is the same, the gradient is rescaled too
// (G = s·(G_prev − p_prev) + p, Ḡ = s·Ḡ_prev) instead of being rebuilt from kernel rows. Either
// solver warm-starts from the other's solution.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "fogdrift/svr/kernel.hpp"

namespace fogdrift::svr {

struct SolverOptions {
  double tolerance = 1e-3;  ///< stopping tolerance on the maximal violating pair (LIBSVM -e)
  bool shrinking = true;    ///< LIBSVM -h
  /// Iteration limit; 0 means LIBSVM's max(10⁷, 100·2l).
  std::int64_t max_iterations = 0;
  /// Memory for kernel rows held in the solver's own variable order, MB (l floats a row for the
  /// pair solver, 2l for the LIBSVM path; at least two rows). fit() and fit_c_path give it all of
  /// Params::cache_mb when the pair solver computes its rows in order (below), 90 % when it reads
  /// them from a distance matrix, and half for the LIBSVM path. The memory is reserved,
  /// committed as rows are written, and kept by the KernelCache's workspace for the next fit
  /// (see Params::cache_mb).
  double solver_order_cache_mb = 100;
  /// Pair solver only: compute kernel rows straight into the solver's order from the features,
  /// and only as far as the active set reaches; false: copy them out of the KernelCache. Ignored
  /// (false) when the TrainingSet keeps a distance matrix. Either way the pair solver leaves its
  /// sample order and these rows in the KernelCache's workspace, and the next fit on that cache
  /// (fit_c_path's next C) starts from them.
  bool rows_in_order = true;
  /// true: the per-variable solver that visits LIBSVM's working sets one for one (the same
  /// iterations and support vectors as LIBSVM, for audits); false: the pair solver, faster.
  bool libsvm_path = false;
  /// Pair solver only: after a step that reached its line minimum, step along a direction
  /// Q-conjugate to it (Torres-Barrán, Alaíz & Dorronsoro, arXiv:2003.08719) when that stays
  /// inside the box. Same working pairs and stopping rule, about half the iterations at large C.
  /// false: the ordinary two-variable step always.
  bool conjugate = true;
  /// Pair solver only: after a shrinking round, a Newton step on the free samples with the
  /// others held at their bounds (docs/svr.md, "Newton steps on the free set"), when the SMO
  /// steps since the last one have done as much work. Same stopping rule; on the C = 1000 fits
  /// of the paper's searches a twelfth to a thirtieth of the iterations. false: SMO steps only.
  bool newton = true;
};

enum class SolverStatus { optimal, iteration_limit };

struct SolverSummary {
  SolverStatus status = SolverStatus::optimal;
  std::int64_t iterations = 0;
  double objective = 0;  ///< dual objective ½αᵀQα + pᵀα at the solution
  double rho = 0;  ///< the model's decision value is Σ(α⁺−α⁻)K − ρ, so the bias b = −ρ
  double max_violation = 0;  ///< final m(α) − M(α), below the tolerance when optimal
  /// Kernel rows computed (cache misses). Rows computed in the solver's order (rows_in_order)
  /// count once for each computation of a row or of the part the active set newly reaches.
  std::int64_t kernel_rows = 0;
  bool warm_started = false;
  bool gradient_reused = false;      ///< warm start reused the previous gradient (same kernel)
  std::int64_t conjugate_steps = 0;  ///< iterations that stepped along a conjugate direction
  std::int64_t newton_steps = 0;     ///< Newton steps on the free samples (SolverOptions::newton)
  double seconds = 0;
};

/// A solution of the dual in LIBSVM's layout (α⁺ then α⁻, training-set order) with the
/// gradient it was found with; enough to warm-start another fit of the same data.
struct DualSolution {
  std::vector<double> alpha;         ///< 2l
  std::vector<double> gradient;      ///< 2l: Qα + p
  std::vector<double> gradient_bar;  ///< 2l: C·Σ_{α_j = C} Q_j
  double c = 0;
  double epsilon = 0;
  Kernel kernel;
};

/// Solves the dual for targets `y` (size l = q.size()). `warm`, when given, must come from the
/// same data. Throws std::invalid_argument for a warm start of another size.
SolverSummary solve_epsilon_svr(KernelCache& q, std::span<const double> y, double c, double epsilon,
                                const SolverOptions& options, DualSolution& out,
                                const DualSolution* warm = nullptr);

}  // namespace fogdrift::svr
