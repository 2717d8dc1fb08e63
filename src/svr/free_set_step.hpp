// The free-set Newton step of the pair solver (docs/svr.md, "Newton steps on the free set").
// Internal header.
//
// At large C the SMO steps zigzag: on the C = 1000 edge of the paper's search box a fit of 5,000
// rows takes 400,000-600,000 two-variable steps, while only 150-250 samples are free (strictly
// inside their box) and the rest sit at a bound. With the bound samples held, the dual restricted
// to the free ones is a small equality-constrained quadratic in the change Δ of their β:
//
//   minimise  rᵀΔ + ½ ΔᵀKΔ   subject to  Σ Δ = 0  and  lo ≤ Δ ≤ hi,
//
// r the gradient of the dual in β (f + ε for a free α⁺, f − ε for a free α⁻), K their kernel
// block, [lo, hi] what keeps every variable in [0, C]. free_set_step solves it by the primal
// active-set method: the Newton direction of the equality-constrained problem (a Cholesky
// factor of K, two solves and the multiplier that keeps Σ Δ = 0), an exact line search that
// stops at the first bound, that variable fixed at its bound and removed from the factor by a
// rank-one update, and again, until a step reaches the minimum or the budget of removals is
// spent. Every step is a descent step that keeps Σ β = 0 and the box, so the SMO loop resumes
// from a better feasible point; its stopping rule is unchanged.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fogdrift::svr::detail {

/// Where a free variable ends: still free, or fixed at the lower or the upper end of its box.
enum class FreeSetEnd : std::int8_t { lower = -1, free = 0, upper = 1 };

struct FreeSetStep {
  Eigen::VectorXd delta;         ///< Δ per free sample, 0 when nothing was done
  std::vector<FreeSetEnd> ends;  ///< per free sample: lower means Δ = lo exactly, upper Δ = hi
  std::size_t removals = 0;      ///< variables fixed at a bound
  bool reached_minimum = false;  ///< the last step was not stopped by a bound
  bool moved = false;            ///< at least one step was taken
};

/// The step described above. `k` is symmetric positive semi-definite (m × m, m ≥ 2); its
/// diagonal is raised by the smallest of 1e-7, 1e-6, … 1e-2 times its mean that makes a Cholesky
/// factor exist (the kernel block of nearby samples is nearly singular in floats). lo ≤ 0 ≤ hi.
/// At most `max_removals` variables are fixed at a bound.
FreeSetStep free_set_step(const Eigen::MatrixXd& k, const Eigen::VectorXd& r,
                          const Eigen::VectorXd& lo, const Eigen::VectorXd& hi,
                          std::size_t max_removals);

/// The arithmetic of a free_set_step on m variables with `removals` removals, in operations:
/// m³/3 for the factor and about 6m² for each step (the pair solver weighs it against its SMO
/// steps' work).
double free_set_step_work(std::size_t m, std::size_t removals);

}  // namespace fogdrift::svr::detail
