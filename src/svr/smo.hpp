// The SMO skeleton both solvers share (docs/svr.md, "One skeleton, two layouts"), in LIBSVM 3.24's
// shape: the loop, the shrinking cadence, the one unshrink, the iteration limit, ρ and the
// objective. What differs between the solvers is how the dual's variables are laid out, and that is
// the Layout:
//  * LibsvmLayout (libsvm_solver.cpp): LIBSVM's 2l variables, one gradient and one kernel-row
//    entry each, shrunk one by one;
//  * PairLayout (pair_solver.cpp): the two variables of a sample as one unit, sharing a gradient
//    and a kernel-row entry, shrunk together.
// A layout orders, shrinks and swaps "units" (variables or samples) and provides:
//
//   std::size_t units() const;
//   bool select(std::size_t active, WorkingSet& ws);  // WSS 2 over units [0, active); false
//                                                     // when optimal within the tolerance
//   void step(const WorkingSet& ws, std::size_t active);
//   void active_set_changing();  // before a shrinking round and before the final unshrink
//   void reordered();            // after a shrinking round swapped units
//   Extremes extremes(std::size_t len) const;  // m(α) and M(α) over units [0, len)
//   bool be_shrunk(std::size_t k, const Extremes& e) const;
//   void swap(std::size_t a, std::size_t b);
//   void reconstruct_gradient(std::size_t active);  // of units [active, units())
//   void add_rho_terms(std::size_t k, RhoBounds& bounds) const;
//   double objective_term(std::size_t k) const;    // Σ α(G + p) over the unit's variables
//
// and, optionally, what to do after each shrinking round, told the SMO iterations since the
// last one (the pair layout's Newton steps):
//
//   void between_rounds(std::size_t active, std::int64_t iterations);
//
// Internal header: not installed.
#pragma once

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cstddef>
#include <cstdint>

#include "fogdrift/base/interrupt.hpp"
#include "fogdrift/svr/smo_solver.hpp"
#include "svr/loops.hpp"

namespace fogdrift::svr::detail {

constexpr double kTau = 1e-12;  // LIBSVM's TAU: the curvature used when Q is not positive

/// LIBSVM's analytic solution of the two-variable subproblem in α_i, α_j (signs y_i, y_j,
/// gradients G_i, G_j, curvature `quad` = K_ii + K_jj − 2K_ij), clipped to the box
/// [0, C_i] × [0, C_j] and keeping y_i·α_i + y_j·α_j fixed.
inline void two_variable_step(double& a_i, double& a_j, int y_i, int y_j, double g_i, double g_j,
                              double quad, double c_i, double c_j) {
  if (quad <= 0) quad = kTau;
  if (y_i != y_j) {
    const double delta = (-g_i - g_j) / quad;
    const double diff = a_i - a_j;
    a_i += delta;
    a_j += delta;
    if (diff > 0) {
      if (a_j < 0) {
        a_j = 0;
        a_i = diff;
      }
    } else if (a_i < 0) {
      a_i = 0;
      a_j = -diff;
    }
    if (diff > c_i - c_j) {
      if (a_i > c_i) {
        a_i = c_i;
        a_j = c_i - diff;
      }
    } else if (a_j > c_j) {
      a_j = c_j;
      a_i = c_j + diff;
    }
  } else {
    const double delta = (g_i - g_j) / quad;
    const double sum = a_i + a_j;
    a_i -= delta;
    a_j += delta;
    if (sum > c_i) {
      if (a_i > c_i) {
        a_i = c_i;
        a_j = sum - c_i;
      }
    } else if (a_j < 0) {
      a_j = 0;
      a_i = sum;
    }
    if (sum > c_j) {
      if (a_j > c_j) {
        a_j = c_j;
        a_i = sum - c_j;
      }
    } else if (a_i < 0) {
      a_i = 0;
      a_j = sum;
    }
  }
}

/// A warm start's variable: α of a solution whose bound was C_prev scaled to the bound C by
/// C/C_prev, which keeps the dual feasible (yᵀα = 0 scales) and every bound variable at its
/// bound. With sample weights both bounds carry the variable's weight.
inline double warm_alpha(double alpha, double c_prev, double c) {
  const double s = c / c_prev;
  return alpha >= c_prev ? c : (alpha <= 0 ? 0.0 : std::min(c, s * alpha));
}

/// The iteration limit: the one asked for, or LIBSVM's max(10⁷, 100·2l) for l samples.
inline std::int64_t iteration_limit(std::int64_t requested, std::size_t samples) {
  if (requested > 0) return requested;
  const auto len = 2 * static_cast<std::int64_t>(samples);
  return std::max<std::int64_t>(10000000, len > INT_MAX / 100 ? INT_MAX : 100 * len);
}

/// Where a variable is in its box, coded as the inner loops read it (loops.hpp).
enum class Bound : std::uint8_t { lower = kLowerBound, upper = kUpperBound, free = kFree };

/// LIBSVM's status of a variable α in [0, C]: at the upper bound from C on, at the lower from 0
/// down, free between.
inline Bound bound_of(double alpha, double c) {
  return alpha >= c ? Bound::upper : (alpha <= 0 ? Bound::lower : Bound::free);
}

/// m(α) = max −y·G over I_up and M(α) = max y·G over I_low (LIBSVM's Gmax and Gmax2); the dual
/// is optimal within the tolerance when m + M < tolerance.
struct Extremes {
  double up = -DBL_MAX, low = -DBL_MAX;
};

/// LIBSVM's calculate_rho: ρ is the mean of y·G over the free variables, or, when none is free,
/// the midpoint of the interval the bound variables leave for it.
class RhoBounds {
 public:
  /// One active variable: y·G, whether its sign y is +1, and where it is.
  void add(double yg, bool positive, Bound where) {
    if (where == Bound::free) {
      ++nr_free_;
      sum_free_ += yg;
    } else if ((where == Bound::upper) != positive) {  // upper with y = −1, lower with y = +1
      ub_ = std::min(ub_, yg);
    } else {
      lb_ = std::max(lb_, yg);
    }
  }
  double rho() const {
    return nr_free_ > 0 ? sum_free_ / static_cast<double>(nr_free_) : (ub_ + lb_) / 2;
  }

 private:
  std::size_t nr_free_ = 0;
  double ub_ = DBL_MAX, lb_ = -DBL_MAX, sum_free_ = 0;
};

/// The solver loop of LIBSVM's Solver::Solve over a Layout (see the top of this file). Fills
/// status, iterations, rho, objective and max_violation of the summary; the layout's solve
/// function adds what only it knows.
template <class Layout>
class Smo {
 public:
  Smo(Layout& layout, const SolverOptions& options, std::size_t samples)
      : layout_(layout),
        units_(layout.units()),
        samples_(samples),
        tolerance_(options.tolerance),
        shrinking_(options.shrinking),
        max_iterations_(iteration_limit(options.max_iterations, samples)),
        active_(units_) {}

  SolverSummary run() {
    SolverSummary summary;
    typename Layout::WorkingSet ws;
    std::int64_t iter = 0;
    // LIBSVM shrinks every min(2l, 1000) iterations; 2l is both layouts' variable count.
    const auto period = static_cast<std::int64_t>(std::min<std::size_t>(2 * samples_, 1000));
    std::int64_t counter = period + 1;
    while (iter < max_iterations_) {
      if (--counter == 0) {
        counter = period;
        check_interrupt();  // base/interrupt.hpp: a host's interrupt, between rounds
        layout_.active_set_changing();
        if (shrinking_) {
          shrink();
          layout_.reordered();
        }
        if constexpr (requires { layout_.between_rounds(active_, iter); })
          layout_.between_rounds(active_, iter - last_round_);
        last_round_ = iter;
      }
      if (!layout_.select(active_, ws)) {
        // Optimal on the active set: check again on all of it before stopping.
        layout_.active_set_changing();
        unshrink();
        if (!layout_.select(active_, ws)) break;
        counter = 1;  // shrink at the next iteration
      }
      ++iter;
      layout_.step(ws, active_);
    }
    if (iter >= max_iterations_) {
      summary.status = SolverStatus::iteration_limit;
      unshrink();
    }
    summary.iterations = iter;
    RhoBounds bounds;
    for (std::size_t k = 0; k < active_; ++k) layout_.add_rho_terms(k, bounds);
    summary.rho = bounds.rho();
    double v = 0;
    for (std::size_t k = 0; k < units_; ++k) v += layout_.objective_term(k);
    summary.objective = v / 2;
    const Extremes e = layout_.extremes(units_);
    summary.max_violation =
        e.up == -DBL_MAX || e.low == -DBL_MAX ? 0.0 : std::max(0.0, e.up + e.low);
    return summary;
  }

 private:
  Layout& layout_;
  std::size_t units_, samples_;
  double tolerance_;
  bool shrinking_;
  std::int64_t max_iterations_;
  std::size_t active_;           // units [0, active_) are not shrunk
  std::int64_t last_round_ = 0;  // the iteration of the last shrinking round
  bool unshrunk_ = false;

  void unshrink() {
    layout_.reconstruct_gradient(active_);
    active_ = units_;
  }

  // LIBSVM's do_shrinking: once, when the violation first falls below 10·tolerance, every unit
  // comes back with its gradient rebuilt; then units that cannot move are moved past the end of
  // the active set.
  void shrink() {
    const Extremes e = layout_.extremes(active_);
    if (!unshrunk_ && e.up + e.low <= tolerance_ * 10) {
      unshrunk_ = true;
      unshrink();
    }
    for (std::size_t k = 0; k < active_; ++k) {
      if (!layout_.be_shrunk(k, e)) continue;
      --active_;
      while (active_ > k) {
        if (!layout_.be_shrunk(active_, e)) {
          layout_.swap(k, active_);
          break;
        }
        --active_;
      }
    }
  }
};

}  // namespace fogdrift::svr::detail
