#include "fogdrift/svr/smo_solver.hpp"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <climits>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

#include "svr/loops.hpp"
#include "svr/pair_solver.hpp"
#include "svr/smo_parts.hpp"

namespace fogdrift::svr {
namespace {

using detail::kFree;
using detail::kLowerBound;
using detail::kUpperBound;

using detail::kTau;

// The solver's state in LIBSVM's permuted order: the first `active` variables are not shrunk.
class Smo {
 public:
  Smo(KernelCache& q, std::span<const double> target, double c, double epsilon,
      const SolverOptions& options)
      : n_(q.size()),
        len_(2 * q.size()),
        c_(c),
        tolerance_(options.tolerance),
        shrinking_(options.shrinking),
        index_(2 * q.size()),
        rows_(q, index_.data(), 2 * q.size(), q.size(), options.solver_order_cache_mb) {
    y_.resize(len_);
    p_.resize(len_);
    active_set_.resize(len_);
    qd_.resize(len_);
    for (std::size_t k = 0; k < n_; ++k) {
      y_[k] = 1;
      y_[k + n_] = -1;
      p_[k] = epsilon - target[k];
      p_[k + n_] = epsilon + target[k];
      index_[k] = index_[k + n_] = static_cast<std::int32_t>(k);
      qd_[k] = qd_[k + n_] = q.diagonal(k);
    }
    for (std::size_t k = 0; k < len_; ++k) active_set_[k] = static_cast<std::int32_t>(k);
    alpha_.assign(len_, 0.0);
    status_.assign(len_, kLowerBound);
    g_.assign(p_.begin(), p_.end());
    g_bar_.assign(len_, 0.0);
    active_ = len_;
    const std::int64_t len = static_cast<std::int64_t>(len_);
    max_iterations_ =
        options.max_iterations > 0
            ? options.max_iterations
            : std::max<std::int64_t>(10000000, len > INT_MAX / 100 ? INT_MAX : 100 * len);
  }

  // Starts from a previous solution of the same data, scaled to this C (see the header).
  void warm_start(const DualSolution& w, bool same_kernel, double epsilon) {
    const double s = c_ / w.c;
    for (std::size_t k = 0; k < len_; ++k) {
      const double a = w.alpha[k];
      alpha_[k] = a >= w.c ? c_ : (a <= 0 ? 0.0 : std::min(c_, s * a));
      update_status(k);
    }
    if (same_kernel && w.gradient.size() == len_ && w.gradient_bar.size() == len_) {
      gradient_reused_ = true;
      for (std::size_t k = 0; k < len_; ++k) {
        // p differs from the previous fit's only through ε: p_prev = p + (ε_prev − ε).
        const double p_prev = p_[k] + (w.epsilon - epsilon);
        g_[k] = s * (w.gradient[k] - p_prev) + p_[k];
        g_bar_[k] = s * w.gradient_bar[k];
      }
      return;
    }
    // LIBSVM's initial gradient for a non-zero α: G = p + Σ α_i Q_i, Ḡ = Σ_{α_i = C} C·Q_i.
    for (std::size_t i = 0; i < len_; ++i) {
      if (status_[i] == kLowerBound) continue;
      const float* row = row_in_order(i, len_);
      loops_.add_scaled(g_.data(), y_.data(), row, alpha_[i] * y_[i], 0, len_);
      if (status_[i] == kUpperBound)
        loops_.add_scaled(g_bar_.data(), y_.data(), row, c_ * y_[i], 0, len_);
    }
  }

  SolverSummary run() {
    SolverSummary summary;
    std::int64_t iter = 0;
    std::int64_t counter = static_cast<std::int64_t>(std::min<std::size_t>(len_, 1000)) + 1;
    std::int64_t i = -1, j = -1;
    while (iter < max_iterations_) {
      if (--counter == 0) {
        counter = static_cast<std::int64_t>(std::min<std::size_t>(len_, 1000));
        if (shrinking_) {
          shrink();
          rows_.apply_swaps();
        }
      }
      if (!select_working_set(i, j)) {
        reconstruct_gradient();
        active_ = len_;
        if (!select_working_set(i, j)) break;
        counter = 1;  // shrink at the next iteration
      }
      ++iter;
      step(static_cast<std::size_t>(i), static_cast<std::size_t>(j));
    }
    if (iter >= max_iterations_) {
      summary.status = SolverStatus::iteration_limit;
      if (active_ < len_) {
        reconstruct_gradient();
        active_ = len_;
      }
    }
    summary.iterations = iter;
    summary.rho = calculate_rho();
    double v = 0;
    for (std::size_t k = 0; k < len_; ++k) v += alpha_[k] * (g_[k] + p_[k]);
    summary.objective = v / 2;
    summary.max_violation = violation();
    summary.gradient_reused = gradient_reused_;
    return summary;
  }

  void export_solution(DualSolution& out) const {
    out.alpha.assign(len_, 0.0);
    out.gradient.assign(len_, 0.0);
    out.gradient_bar.assign(len_, 0.0);
    for (std::size_t k = 0; k < len_; ++k) {
      out.alpha[active_set_[k]] = alpha_[k];
      out.gradient[active_set_[k]] = g_[k];
      out.gradient_bar[active_set_[k]] = g_bar_[k];
    }
  }

 private:
  const detail::Loops& loops_ = detail::loops();  // the inner loops of one instruction set
  std::size_t n_, len_;
  double c_;
  double tolerance_;
  bool shrinking_;
  std::int64_t max_iterations_ = 0;
  std::size_t active_ = 0;
  bool unshrunk_ = false;
  bool gradient_reused_ = false;
  std::vector<std::int8_t> y_;
  std::vector<double> p_, alpha_, g_, g_bar_, qd_;
  std::vector<std::uint8_t> status_;
  std::vector<std::int32_t> index_, active_set_;

  detail::OrderedRows rows_;

  bool is_upper(std::size_t k) const { return status_[k] == kUpperBound; }
  bool is_lower(std::size_t k) const { return status_[k] == kLowerBound; }
  bool is_free(std::size_t k) const { return status_[k] == kFree; }
  void update_status(std::size_t k) {
    status_[k] = alpha_[k] >= c_ ? kUpperBound : (alpha_[k] <= 0 ? kLowerBound : kFree);
  }

  // The kernel row of variable k in solver order, first `len` entries at least; unsigned
  // (Q_kj = y_k·y_j·K).
  const float* row_in_order(std::size_t k, std::size_t len) { return rows_.row(index_[k], len); }

  void swap_index(std::size_t a, std::size_t b) {
    rows_.swapped(a, b);
    std::swap(y_[a], y_[b]);
    std::swap(index_[a], index_[b]);
    std::swap(qd_[a], qd_[b]);
    std::swap(g_[a], g_[b]);
    std::swap(status_[a], status_[b]);
    std::swap(alpha_[a], alpha_[b]);
    std::swap(p_[a], p_[b]);
    std::swap(active_set_[a], active_set_[b]);
    std::swap(g_bar_[a], g_bar_[b]);
  }

  // WSS 2 of Fan, Chen & Lin (2005) over the active set; false when optimal within tolerance.
  bool select_working_set(std::int64_t& out_i, std::int64_t& out_j) {
    const auto si = loops_.select_i(g_.data(), y_.data(), status_.data(), active_);
    if (si.index < 0) return false;
    const std::size_t i = static_cast<std::size_t>(si.index);
    const float* k_i = row_in_order(i, active_);
    const auto sj = loops_.select_j(g_.data(), y_.data(), status_.data(), k_i, qd_.data(), qd_[i],
                                    si.value, kTau, active_);
    if (si.value + sj.g_max2 < tolerance_ || sj.index < 0) return false;
    out_i = si.index;
    out_j = sj.index;
    return true;
  }

  // m(α) − M(α) over all variables (for the summary).
  double violation() const {
    double up = -DBL_MAX, low = -DBL_MAX;
    for (std::size_t t = 0; t < len_; ++t) {
      const double yg = y_[t] * g_[t];
      if (y_[t] > 0 ? !is_upper(t) : !is_lower(t)) up = std::max(up, -yg);
      if (y_[t] > 0 ? !is_lower(t) : !is_upper(t)) low = std::max(low, yg);
    }
    return up == -DBL_MAX || low == -DBL_MAX ? 0.0 : std::max(0.0, up + low);
  }

  // The analytic solution of the two-variable subproblem, clipped to the box (LIBSVM's update).
  void step(std::size_t i, std::size_t j) {
    const float* k_i = row_in_order(i, active_);
    const float* k_j = row_in_order(j, active_);
    const double old_i = alpha_[i], old_j = alpha_[j];
    // LIBSVM's curvature Q_ii + Q_jj ∓ 2Q_ij is K_ii + K_jj − 2K_ij in both branches.
    detail::two_variable_step(alpha_[i], alpha_[j], y_[i], y_[j], g_[i], g_[j],
                              qd_[i] + qd_[j] - 2 * k_i[j], c_);
    const double d_i = alpha_[i] - old_i, d_j = alpha_[j] - old_j;
    loops_.update_gradient(g_.data(), y_.data(), k_i, k_j, y_[i] * d_i, y_[j] * d_j, active_);

    const bool upper_i = is_upper(i), upper_j = is_upper(j);
    update_status(i);
    update_status(j);
    if (upper_i != is_upper(i)) update_g_bar(i, upper_i ? -c_ : c_);
    if (upper_j != is_upper(j)) update_g_bar(j, upper_j ? -c_ : c_);
  }

  void update_g_bar(std::size_t k, double scale) {
    const float* row = row_in_order(k, len_);
    loops_.add_scaled(g_bar_.data(), y_.data(), row, scale * y_[k], 0, len_);
  }

  // G of the shrunk variables from Ḡ and the free variables (LIBSVM's reconstruct_gradient).
  void reconstruct_gradient() {
    if (active_ == len_) return;
    for (std::size_t j = active_; j < len_; ++j) g_[j] = g_bar_[j] + p_[j];
    std::size_t nr_free = 0;
    for (std::size_t j = 0; j < active_; ++j)
      if (is_free(j)) ++nr_free;
    if (nr_free * len_ > 2 * active_ * (len_ - active_)) {
      for (std::size_t i = active_; i < len_; ++i) {
        const float* row = row_in_order(i, active_);
        double gi = g_[i];
        for (std::size_t j = 0; j < active_; ++j) {
          if (!is_free(j)) continue;
          const double q = y_[i] == y_[j] ? row[j] : -row[j];
          gi += alpha_[j] * q;
        }
        g_[i] = gi;
      }
    } else {
      for (std::size_t i = 0; i < active_; ++i) {
        if (!is_free(i)) continue;
        const float* row = row_in_order(i, len_);
        loops_.add_scaled(g_.data(), y_.data(), row, alpha_[i] * y_[i], active_, len_);
      }
    }
  }

  bool be_shrunk(std::size_t k, double g_max1, double g_max2) const {
    if (is_upper(k)) return y_[k] == 1 ? -g_[k] > g_max1 : -g_[k] > g_max2;
    if (is_lower(k)) return y_[k] == 1 ? g_[k] > g_max2 : g_[k] > g_max1;
    return false;
  }

  void shrink() {
    double g_max1 = -DBL_MAX;  // max {−y_i G_i : i ∈ I_up}
    double g_max2 = -DBL_MAX;  // max { y_i G_i : i ∈ I_low}
    for (std::size_t k = 0; k < active_; ++k) {
      if (y_[k] == 1) {
        if (!is_upper(k) && -g_[k] >= g_max1) g_max1 = -g_[k];
        if (!is_lower(k) && g_[k] >= g_max2) g_max2 = g_[k];
      } else {
        if (!is_upper(k) && -g_[k] >= g_max2) g_max2 = -g_[k];
        if (!is_lower(k) && g_[k] >= g_max1) g_max1 = g_[k];
      }
    }
    if (!unshrunk_ && g_max1 + g_max2 <= tolerance_ * 10) {
      unshrunk_ = true;
      reconstruct_gradient();
      active_ = len_;
    }
    for (std::size_t k = 0; k < active_; ++k) {
      if (!be_shrunk(k, g_max1, g_max2)) continue;
      --active_;
      while (active_ > k) {
        if (!be_shrunk(active_, g_max1, g_max2)) {
          swap_index(k, active_);
          break;
        }
        --active_;
      }
    }
  }

  double calculate_rho() const {
    std::size_t nr_free = 0;
    double ub = DBL_MAX, lb = -DBL_MAX, sum_free = 0;
    for (std::size_t k = 0; k < active_; ++k) {
      const double yg = y_[k] * g_[k];
      if (is_upper(k)) {
        if (y_[k] == -1)
          ub = std::min(ub, yg);
        else
          lb = std::max(lb, yg);
      } else if (is_lower(k)) {
        if (y_[k] == 1)
          ub = std::min(ub, yg);
        else
          lb = std::max(lb, yg);
      } else {
        ++nr_free;
        sum_free += yg;
      }
    }
    return nr_free > 0 ? sum_free / static_cast<double>(nr_free) : (ub + lb) / 2;
  }
};

}  // namespace

SolverSummary solve_epsilon_svr(KernelCache& q, std::span<const double> y, double c, double epsilon,
                                const SolverOptions& options, DualSolution& out,
                                const DualSolution* warm) {
  const auto start = std::chrono::steady_clock::now();
  if (y.size() != q.size()) throw std::invalid_argument("solve_epsilon_svr: target size mismatch");
  const std::int64_t rows_before = q.rows_computed();
  const bool warm_started = warm != nullptr && !warm->alpha.empty();
  if (warm_started && warm->alpha.size() != 2 * q.size())
    throw std::invalid_argument("solve_epsilon_svr: warm start from data of another size");
  SolverSummary summary;
  if (options.libsvm_path) {
    Smo smo(q, y, c, epsilon, options);
    if (warm_started) smo.warm_start(*warm, warm->kernel == q.kernel(), epsilon);
    summary = smo.run();
    smo.export_solution(out);
  } else {
    summary = detail::solve_pairs(q, y, c, epsilon, options, out, warm_started ? warm : nullptr);
  }
  out.c = c;
  out.epsilon = epsilon;
  out.kernel = q.kernel();
  summary.warm_started = warm_started;
  summary.kernel_rows += q.rows_computed() - rows_before;  // plus any the solver computed itself
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace fogdrift::svr
