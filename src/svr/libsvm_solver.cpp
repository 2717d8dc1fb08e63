// LIBSVM's layout of ε-SVR's dual for the SMO skeleton (smo.hpp): 2l variables α = (α⁺, α⁻) with
// signs y = (+1…, −1…), Q_ij = y_i·y_j·K(x_i mod l, x_j mod l) and p = (ε − z, ε + z), each with
// its own gradient G = Qα + p, status and kernel-row entry, kept in LIBSVM's permuted order (the
// first `active` variables are not shrunk). On the same data it visits svm-train's working sets
// one for one.
#include "svr/libsvm_solver.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "svr/loops.hpp"
#include "svr/rows.hpp"
#include "svr/smo.hpp"
#include "svr/workspace_state.hpp"

namespace fogdrift::svr::detail {
namespace {

class LibsvmLayout {
 public:
  struct WorkingSet {
    std::size_t i = 0, j = 0;
  };

  LibsvmLayout(KernelCache& q, std::span<const double> target, double c, double epsilon,
               const SolverOptions& options)
      : n_(q.size()),
        len_(2 * q.size()),
        c_(c),
        epsilon_(epsilon),
        tolerance_(options.tolerance),
        index_(2 * q.size()),
        rows_(q, index_.data(), 2 * q.size(), q.size(), options.solver_order_cache_mb,
              &q.workspace().state().blocks) {
    y_.resize(len_);
    p_.resize(len_);
    active_set_.resize(len_);
    qd_.resize(len_);
    cap_.resize(len_);
    const Data& data = q.training_set().data();
    for (std::size_t k = 0; k < n_; ++k) {
      cap_[k] = cap_[k + n_] = c * data.weight_of(k);
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
  }

  // Starts from a previous solution of the same data scaled to this C (warm_alpha). With the same
  // kernel the gradient is rescaled too; p differs from the previous fit's only through ε:
  // p_prev = p + (ε_prev − ε).
  void warm_start(const DualSolution& w, const Data& data, bool same_kernel) {
    for (std::size_t k = 0; k < len_; ++k) {  // no shrinking yet: variable k is LIBSVM's k
      alpha_[k] = warm_alpha(w.alpha[k], w.c * data.weight_of(k % n_), cap_[k]);
      update_status(k);
    }
    if (same_kernel && w.gradient.size() == len_ && w.gradient_bar.size() == len_) {
      gradient_reused_ = true;
      const double s = c_ / w.c;
      for (std::size_t k = 0; k < len_; ++k) {
        const double p_prev = p_[k] + (w.epsilon - epsilon_);
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
        loops_.add_scaled(g_bar_.data(), y_.data(), row, cap_[i] * y_[i], 0, len_);
    }
  }

  bool gradient_reused() const { return gradient_reused_; }

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

  // The layout's side of the skeleton (smo.hpp).

  std::size_t units() const { return len_; }

  // WSS 2 of Fan, Chen & Lin (2005) over the active set; false when optimal within tolerance.
  bool select(std::size_t active, WorkingSet& ws) {
    const auto si = loops_.select_i(g_.data(), y_.data(), status_.data(), active);
    if (si.index < 0) return false;
    const auto i = static_cast<std::size_t>(si.index);
    const float* k_i = row_in_order(i, active);
    const auto sj = loops_.select_j(g_.data(), y_.data(), status_.data(), k_i, qd_.data(), qd_[i],
                                    si.value, kTau, active);
    if (si.value + sj.g_max2 < tolerance_ || sj.index < 0) return false;
    ws.i = i;
    ws.j = static_cast<std::size_t>(sj.index);
    return true;
  }

  // The analytic solution of the two-variable subproblem, clipped to the box (LIBSVM's update).
  void step(const WorkingSet& ws, std::size_t active) {
    const std::size_t i = ws.i, j = ws.j;
    const float* k_i = row_in_order(i, active);
    const float* k_j = row_in_order(j, active);
    const double old_i = alpha_[i], old_j = alpha_[j];
    // LIBSVM's curvature Q_ii + Q_jj ∓ 2Q_ij is K_ii + K_jj − 2K_ij in both branches.
    two_variable_step(alpha_[i], alpha_[j], y_[i], y_[j], g_[i], g_[j],
                      qd_[i] + qd_[j] - 2 * k_i[j], cap_[i], cap_[j]);
    const double d_i = alpha_[i] - old_i, d_j = alpha_[j] - old_j;
    loops_.update_gradient(g_.data(), y_.data(), k_i, k_j, y_[i] * d_i, y_[j] * d_j, active);

    const bool upper_i = is_upper(i), upper_j = is_upper(j);
    update_status(i);
    update_status(j);
    if (upper_i != is_upper(i)) update_g_bar(i, upper_i ? -cap_[i] : cap_[i]);
    if (upper_j != is_upper(j)) update_g_bar(j, upper_j ? -cap_[j] : cap_[j]);
  }

  void active_set_changing() {}
  void reordered() { rows_.apply_swaps(); }

  Extremes extremes(std::size_t len) const {
    Extremes e;
    for (std::size_t t = 0; t < len; ++t) {
      const double yg = y_[t] * g_[t];
      if (y_[t] > 0 ? !is_upper(t) : !is_lower(t)) e.up = std::max(e.up, -yg);
      if (y_[t] > 0 ? !is_lower(t) : !is_upper(t)) e.low = std::max(e.low, yg);
    }
    return e;
  }

  bool be_shrunk(std::size_t k, const Extremes& e) const {
    if (is_upper(k)) return y_[k] == 1 ? -g_[k] > e.up : -g_[k] > e.low;
    if (is_lower(k)) return y_[k] == 1 ? g_[k] > e.low : g_[k] > e.up;
    return false;
  }

  void swap(std::size_t a, std::size_t b) {
    rows_.swapped(a, b);
    std::swap(y_[a], y_[b]);
    std::swap(index_[a], index_[b]);
    std::swap(qd_[a], qd_[b]);
    std::swap(cap_[a], cap_[b]);
    std::swap(g_[a], g_[b]);
    std::swap(status_[a], status_[b]);
    std::swap(alpha_[a], alpha_[b]);
    std::swap(p_[a], p_[b]);
    std::swap(active_set_[a], active_set_[b]);
    std::swap(g_bar_[a], g_bar_[b]);
  }

  // G of the shrunk variables from Ḡ and the free variables (LIBSVM's reconstruct_gradient).
  void reconstruct_gradient(std::size_t active) {
    if (active == len_) return;
    for (std::size_t j = active; j < len_; ++j) g_[j] = g_bar_[j] + p_[j];
    std::size_t nr_free = 0;
    for (std::size_t j = 0; j < active; ++j)
      if (is_free(j)) ++nr_free;
    if (nr_free * len_ > 2 * active * (len_ - active)) {
      for (std::size_t i = active; i < len_; ++i) {
        const float* row = row_in_order(i, active);
        double gi = g_[i];
        for (std::size_t j = 0; j < active; ++j) {
          if (!is_free(j)) continue;
          const double q = y_[i] == y_[j] ? row[j] : -row[j];
          gi += alpha_[j] * q;
        }
        g_[i] = gi;
      }
    } else {
      for (std::size_t i = 0; i < active; ++i) {
        if (!is_free(i)) continue;
        const float* row = row_in_order(i, len_);
        loops_.add_scaled(g_.data(), y_.data(), row, alpha_[i] * y_[i], active, len_);
      }
    }
  }

  void add_rho_terms(std::size_t k, RhoBounds& bounds) const {
    bounds.add(y_[k] * g_[k], y_[k] == 1, static_cast<Bound>(status_[k]));
  }

  double objective_term(std::size_t k) const { return alpha_[k] * (g_[k] + p_[k]); }

 private:
  const Loops& loops_ = loops();  // the inner loops of one instruction set
  std::size_t n_, len_;
  double c_, epsilon_, tolerance_;
  bool gradient_reused_ = false;
  std::vector<std::int8_t> y_;
  std::vector<double> p_, alpha_, g_, g_bar_, qd_;
  std::vector<double> cap_;           // C·weight of the variable's sample: its upper bound
  std::vector<std::uint8_t> status_;  // kLowerBound, kUpperBound or kFree (loops.hpp)
  std::vector<std::int32_t> index_, active_set_;
  OrderedRows rows_;

  bool is_upper(std::size_t k) const { return status_[k] == kUpperBound; }
  bool is_lower(std::size_t k) const { return status_[k] == kLowerBound; }
  bool is_free(std::size_t k) const { return status_[k] == kFree; }
  void update_status(std::size_t k) {
    status_[k] = static_cast<std::uint8_t>(bound_of(alpha_[k], cap_[k]));
  }

  // The kernel row of variable k in solver order, first `len` entries at least; unsigned
  // (Q_kj = y_k·y_j·K).
  const float* row_in_order(std::size_t k, std::size_t len) { return rows_.row(index_[k], len); }

  void update_g_bar(std::size_t k, double scale) {
    const float* row = row_in_order(k, len_);
    loops_.add_scaled(g_bar_.data(), y_.data(), row, scale * y_[k], 0, len_);
  }
};

}  // namespace

SolverSummary solve_libsvm_path(KernelCache& q, std::span<const double> target, double c,
                                double epsilon, const SolverOptions& options, DualSolution& out,
                                const DualSolution* warm) {
  LibsvmLayout layout(q, target, c, epsilon, options);
  if (warm != nullptr)
    layout.warm_start(*warm, q.training_set().data(), warm->kernel == q.kernel());
  SolverSummary summary = Smo<LibsvmLayout>(layout, options, q.size()).run();
  layout.export_solution(out);
  summary.gradient_reused = layout.gradient_reused();
  return summary;
}

}  // namespace fogdrift::svr::detail
