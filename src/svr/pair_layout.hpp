// The pair layout of the dual for the SMO skeleton (smo.hpp), which the pair solver runs
// (pair_solver.cpp; see solve_epsilon_svr in smo_solver.hpp for what it computes and why).
//
// LIBSVM's 2l variables come in pairs, α⁺_k and α⁻_k of sample k, whose gradients are tied:
// G⁺_k = f_k + ε and G⁻_k = ε − f_k with f = Kβ − z, β = α⁺ − α⁻. This layout keeps f (l doubles)
// instead of G (2l), kernel rows of l entries instead of 2l, and its units are the samples: for
// each, the better of its two variables in I_up (I_low) is known from the bounds alone
// (loops.hpp). The working-set rule, the two-variable step, reconstruction and stopping rule
// are LIBSVM's, applied to the variable each sample offers; the skeleton's shrinking shrinks a
// sample when both of its variables would be. The gradient update and the next iteration's first
// selection share one pass. Ties can break differently from LIBSVM, so the path through the dual
// differs in detail while meeting the same stopping rule.
//
// Conjugate steps (Torres-Barrán, Alaíz & Dorronsoro, "Faster SVM training via conjugate SMO",
// arXiv:2003.08719, 2020). After a step that reached the line minimum, the next working
// pair's direction u is made Q-conjugate to the previous direction d: d' = u + λ·d with
// λ = −uᵀQd / dᵀQd, and the step goes to the minimum along d', t = −∇ᵀd' / d'ᵀQd'. The solver
// keeps Qd over the active samples (one more vector), so the update costs one pass as before;
// d itself touches only the few samples of the last steps. A conjugate step is taken only when
// it stays strictly inside the box; otherwise the ordinary two-variable step is taken and the
// direction forgotten. On the benchmark data it halves the iterations at C = 100 (N = 6000,
// σ = 1: 286,000 to about 140,000); the working pair, stopping rule, shrinking and ρ are
// unchanged, so the solution meets the same tolerance.
#pragma once

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "svr/free_set_step.hpp"
#include "svr/loops.hpp"
#include "svr/smo.hpp"
#include "svr/workspace_state.hpp"

namespace fogdrift::svr::detail {

class PairLayout {
 public:
  // A working pair: the sample whose variable enters from I_up, the one from I_low, and row i
  // over the active samples, which stays valid through the step (a row asked for later evicts
  // the least recently used).
  struct WorkingSet {
    std::size_t i = 0, j = 0;
    const float* k_i = nullptr;
  };

  PairLayout(KernelCache& q, std::span<const double> target, double c, double epsilon,
             const SolverOptions& options)
      : n_(q.size()),
        c_(c),
        epsilon_(epsilon),
        tolerance_(options.tolerance),
        conjugate_(options.conjugate),
        newton_(options.newton),
        workspace_(q.workspace().state()),
        order_(take_order(q, options)),
        index_(order_->index),
        rows_(*order_->rows),
        rows_before_(rows_.rows_computed()) {
    take_arrays();
    const Data& data = q.training_set().data();
    for (std::size_t k = 0; k < n_; ++k) {
      const auto sample = static_cast<std::size_t>(index_[k]);
      z_[k] = target[sample];
      qd_[k] = q.diagonal(sample);
      cap_[k] = c * data.weight_of(sample);
    }
    uniform_qd_ = std::all_of(qd_.begin(), qd_.end(), [&](double v) { return v == qd_[0]; });
    std::fill(a_.begin(), a_.end(), 0.0);
    std::fill(b_.begin(), b_.end(), 0.0);
    for (std::size_t k = 0; k < n_; ++k) f_[k] = -z_[k];
    std::fill(gbar_.begin(), gbar_.end(), 0.0);
    for (std::size_t k = 0; k < n_; ++k) refresh(k);
    if (conjugate_) {
      std::fill(da_.begin(), da_.end(), 0.0);
      std::fill(db_.begin(), db_.end(), 0.0);
      std::fill(kd_.begin(), kd_.end(), 0.0);
      std::fill(in_support_.begin(), in_support_.end(), std::uint8_t{0});
    }
  }

  // Starts from a previous solution of the same data scaled to this C (warm_alpha), as the LIBSVM
  // layout does.
  void warm_start(const DualSolution& w, const Data& data, bool same_kernel) {
    warm_ = true;
    for (std::size_t k = 0; k < n_; ++k) {  // position k holds sample index_[k]
      const auto sample = static_cast<std::size_t>(index_[k]);
      const double cap_prev = w.c * data.weight_of(sample);
      a_[k] = warm_alpha(w.alpha[sample], cap_prev, cap_[k]);
      b_[k] = warm_alpha(w.alpha[sample + n_], cap_prev, cap_[k]);
      refresh(k);
    }
    if (same_kernel && w.gradient.size() == 2 * n_ && w.gradient_bar.size() == 2 * n_) {
      gradient_reused_ = true;
      const double s = c_ / w.c;
      for (std::size_t k = 0; k < n_; ++k) {
        const auto sample = static_cast<std::size_t>(index_[k]);
        // f_prev = G⁺_prev − ε_prev, and f + z = Kβ scales with β.
        f_[k] = s * ((w.gradient[sample] - w.epsilon) + z_[k]) - z_[k];
        gbar_[k] = s * w.gradient_bar[sample];
      }
      return;
    }
    for (std::size_t k = 0; k < n_; ++k) {
      const double beta = a_[k] - b_[k];
      const double bound = (a_[k] >= cap_[k] ? cap_[k] : 0.0) - (b_[k] >= cap_[k] ? cap_[k] : 0.0);
      if (beta == 0 && bound == 0) continue;
      const float* row = rows_.row(index_[k], n_);
      if (beta != 0) loops_.add_row(f_.data(), row, beta, 0, n_);
      if (bound != 0) loops_.add_row(gbar_.data(), row, bound, 0, n_);
    }
  }

  // Leaves the order and its rows in the workspace for the next fit on this cache.
  void keep_order(const KernelCache& q) {
    workspace_.order = std::move(order_);
    workspace_.order_cache = &q;
  }

  void export_solution(DualSolution& out) const {
    out.alpha.assign(2 * n_, 0.0);
    out.gradient.assign(2 * n_, 0.0);
    out.gradient_bar.assign(2 * n_, 0.0);
    for (std::size_t p = 0; p < n_; ++p) {
      const auto k = static_cast<std::size_t>(index_[p]);
      out.alpha[k] = a_[p];
      out.alpha[k + n_] = b_[p];
      out.gradient[k] = f_[p] + epsilon_;
      out.gradient[k + n_] = epsilon_ - f_[p];
      out.gradient_bar[k] = gbar_[p];
      out.gradient_bar[k + n_] = -gbar_[p];
    }
  }

  // The layout's side of the skeleton (smo.hpp); its units are samples.

  std::size_t units() const { return n_; }

  // WSS 2 over the active samples; false when optimal within the tolerance. The first choice,
  // i, comes from the last step's fused update when nothing has changed since.
  bool select(std::size_t active, WorkingSet& ws) {
    if (!up_current_) up_next_ = loops_.select_up(f_.data(), up_.data(), active);
    up_current_ = true;
    const Selection& up = up_next_;
    if (up.index < 0) return false;
    ws.i = static_cast<std::size_t>(up.index);
    ws.k_i = rows_.row(index_[ws.i], active);
    const SelectionJ low =
        loops_.select_low(f_.data(), low_.data(), ws.k_i, uniform_qd_ ? nullptr : qd_.data(),
                          qd_[ws.i], up.value, kTau, active);
    if (up.value + low.g_max2 < tolerance_ || low.index < 0) return false;
    ws.j = static_cast<std::size_t>(low.index);
    return true;
  }

  void step(const WorkingSet& ws, std::size_t active) {
    up_next_ = step_pair(ws.i, ws.j, ws.k_i, active);
  }

  // Shrinking reorders the samples, and Kd is kept for the active ones only.
  void active_set_changing() { forget_direction(); }

  void reordered() {
    rows_.apply_swaps();
    up_current_ = false;
  }

  // m(α) and M(α) over the first `len` samples: max −y·G over I_up, max y·G over I_low.
  Extremes extremes(std::size_t len) const {
    Extremes e;
    for (std::size_t k = 0; k < len; ++k) {
      if (up_[k] != kNoVariable) e.up = std::max(e.up, up_[k] - f_[k]);
      if (low_[k] != kNoVariable) e.low = std::max(e.low, f_[k] + low_[k]);
    }
    return e;
  }

  // LIBSVM's be_shrunk for both variables of sample k.
  bool be_shrunk(std::size_t k, const Extremes& e) const {
    const double g_plus = f_[k] + epsilon_, g_minus = epsilon_ - f_[k];
    const bool plus = a_[k] >= cap_[k] ? -g_plus > e.up : (a_[k] <= 0 ? g_plus > e.low : false);
    if (!plus) return false;
    return b_[k] >= cap_[k] ? -g_minus > e.low : (b_[k] <= 0 ? g_minus > e.up : false);
  }

  void swap(std::size_t p, std::size_t q) {
    std::swap(index_[p], index_[q]);
    rows_.swapped(p, q);
    std::swap(z_[p], z_[q]);
    std::swap(qd_[p], qd_[q]);
    std::swap(cap_[p], cap_[q]);
    std::swap(a_[p], a_[q]);
    std::swap(b_[p], b_[q]);
    std::swap(f_[p], f_[q]);
    std::swap(gbar_[p], gbar_[q]);
    std::swap(up_[p], up_[q]);
    std::swap(low_[p], low_[q]);
  }

  // f of the shrunk samples from Ḡ and the free variables (LIBSVM's reconstruct_gradient). A
  // shrunk sample has both variables at a bound, so every free variable is active.
  void reconstruct_gradient(std::size_t active) {
    up_current_ = false;
    if (active == n_) return;
    for (std::size_t k = active; k < n_; ++k) f_[k] = gbar_[k] - z_[k];
    std::size_t nr_free = 0;
    for (std::size_t k = 0; k < active; ++k)
      if (free_part(k) != 0) ++nr_free;
    if (nr_free * n_ > 2 * active * (n_ - active)) {
      for (std::size_t k = active; k < n_; ++k) {
        const float* row = rows_.row(index_[k], active);
        double fk = f_[k];
        for (std::size_t q = 0; q < active; ++q) {
          const double phi = free_part(q);
          if (phi != 0) fk += phi * row[q];
        }
        f_[k] = fk;
      }
    } else {
      for (std::size_t q = 0; q < active; ++q) {
        const double phi = free_part(q);
        if (phi != 0) loops_.add_row(f_.data(), rows_.row(index_[q], n_), phi, active, n_);
      }
    }
  }

  // Both variables of sample k: α⁺ (y = +1, y·G⁺ = f + ε) and α⁻ (y = −1, y·G⁻ = f − ε).
  void add_rho_terms(std::size_t k, RhoBounds& bounds) const {
    bounds.add(f_[k] + epsilon_, true, bound_of(a_[k], cap_[k]));
    bounds.add(f_[k] - epsilon_, false, bound_of(b_[k], cap_[k]));
  }

  // α⁺(G⁺ + p⁺) + α⁻(G⁻ + p⁻), with G⁺ + p⁺ = f − z + 2ε and G⁻ + p⁻ = z − f + 2ε.
  double objective_term(std::size_t k) const {
    return a_[k] * ((f_[k] - z_[k]) + 2 * epsilon_) + b_[k] * ((z_[k] - f_[k]) + 2 * epsilon_);
  }

  // After a shrinking round, `iterations` SMO steps since the last one: a Newton step on the free
  // samples (free_set_step.hpp; docs/svr.md, "Newton steps on the free set", has the
  // measurements behind these rules), once the SMO steps have made as many iterations as there
  // are samples (the fits that converge sooner, at small C, need none) or at once after a warm
  // start (its free set is near the final one), and while the Newton steps' work, counted at
  // kNewtonWorkWeight of a sample pass per operation, and the kernel rows they read stay below
  // the SMO steps' work (iterations × active samples).
  // (pair_layout_newton.cpp).
  void between_rounds(std::size_t active, std::int64_t iterations);

  bool gradient_reused() const { return gradient_reused_; }
  std::int64_t conjugate_steps() const { return conjugate_steps_; }
  std::int64_t newton_steps() const { return newton_steps_; }
  std::int64_t rows_computed() const { return rows_.rows_computed() - rows_before_; }

 private:
  const Loops& loops_ = loops();  // the inner loops, one instruction set (loops.hpp)
  std::size_t n_;
  double c_, epsilon_, tolerance_;
  bool conjugate_;
  bool newton_;
  bool gradient_reused_ = false;
  Selection up_next_;        // select_up over the active samples, from the last step
  bool up_current_ = false;  // up_next_ is current: no swap or gradient rebuild since
  // The cache's workspace: this fit's arrays, and the order an earlier fit on the cache left.
  WorkspaceState& workspace_;
  // Per sample, in the solver's order (index_ maps a position to the training sample). The order
  // and its rows come from the workspace when an earlier fit on this cache left them there, and
  // go back to it at the end (keep_order).
  std::unique_ptr<SampleOrder> order_;
  std::vector<std::int32_t>& index_;
  OrderedRows& rows_;
  std::int64_t rows_before_;  // rows_.rows_computed() when this fit began
  // The per-sample arrays are views of the workspace's (take_arrays).
  std::span<double> z_, qd_;
  bool uniform_qd_ = false;  // every QD_k the same (the RBF kernel's 1): select_low skips qd_
  std::span<double> cap_;    // C·weight of the sample: the bound of both its variables
  std::span<double> a_, b_;
  std::span<double> f_;     // (Kβ)_k − z_k
  std::span<double> gbar_;  // Σ over variables at the upper bound of C·y·K: LIBSVM's Ḡ⁺
  std::span<double> up_, low_;
  // The last direction, when the last step reached its line minimum: its coefficients per
  // variable (da_ for α⁺, db_ for α⁻; zero outside support_), Kd over the active samples (in β,
  // d_β = da − db) and dᵀKd; there is one when support_ is not empty. Forgotten when it spans
  // more than kMaxSupport samples: conjugacy pays off over a few steps, and a short support keeps
  // each step's bookkeeping small.
  static constexpr std::size_t kMaxSupport = 16;
  double dkd_ = 0;
  std::span<double> da_, db_, kd_;
  std::span<std::uint8_t> in_support_;
  std::vector<std::size_t> support_;
  std::int64_t conjugate_steps_ = 0;
  // Newton steps on the free samples (between_rounds): the free samples of the last round, the
  // work spent on SMO steps (sample passes) and on Newton steps (operations), and the SMO
  // iterations so far. Larger free sets than kMaxNewtonFree are left to the SMO steps: on
  // svr_vs_libsvm's data (N = 6000, ε = 0.1) blocks of 540-1,500 free samples made fits
  // 1.5-2.3 times slower (1.5-1.6 with the removals held to the budget); the paper's blocks are
  // 150-400 (docs/svr.md).
  static constexpr std::size_t kMaxNewtonFree = 400;
  static constexpr double kNewtonWorkWeight = 0.1;
  std::vector<std::size_t> free_;
  double smo_work_ = 0, newton_work_ = 0;
  std::int64_t total_iterations_ = 0;
  bool warm_ = false;  // started from an earlier solution (warm_start)
  std::int64_t newton_steps_ = 0;

  // The order and rows an earlier fit on this cache left, or the identity order with no rows.
  std::unique_ptr<SampleOrder> take_order(KernelCache& q, const SolverOptions& options) {
    std::unique_ptr<SampleOrder> kept = workspace_.take_order(q);
    if (kept && kept->index.size() == q.size()) return kept;
    auto order = std::make_unique<SampleOrder>();
    order->index.resize(q.size());
    for (std::size_t k = 0; k < q.size(); ++k) order->index[k] = static_cast<std::int32_t>(k);
    order->rows = std::make_unique<OrderedRows>(
        q, order->index.data(), q.size(), q.size(), options.solver_order_cache_mb,
        &workspace_.blocks, options.rows_in_order && !q.training_set().has_distances());
    return order;
  }

  // Points the per-sample arrays into the workspace's, grown to this fit's size. Taken fresh for
  // every fit, they came from new pages each time (the allocator returns freed memory at the top
  // of the heap to the system), and page faults are slow on virtual machines: 426 faults for
  // each C path of the bench's 20 fits.
  void take_arrays() {
    std::span<double>* arrays[] = {&z_,    &qd_, &cap_, &a_,  &b_,  &f_,
                                   &gbar_, &up_, &low_, &da_, &db_, &kd_};
    const std::size_t count = conjugate_ ? 12 : 9;  // da_, db_, kd_ only for conjugate steps
    if (workspace_.values.size() < count * n_) workspace_.values.resize(count * n_);
    for (std::size_t a = 0; a < count; ++a)
      *arrays[a] = std::span<double>(workspace_.values.data() + a * n_, n_);
    if (conjugate_) {
      if (workspace_.flags.size() < n_) workspace_.flags.resize(n_);
      in_support_ = std::span<std::uint8_t>(workspace_.flags.data(), n_);
    }
  }

  // The offsets of loops.hpp: I_up offers α⁻ (−y·G = ε − f) when it can fall, else α⁺ (−ε − f)
  // when it can grow; I_low offers α⁺ (f + ε) when it can fall, else α⁻ (f − ε) when it can grow.
  void refresh(std::size_t k) {
    up_[k] = b_[k] > 0 ? epsilon_ : (a_[k] < cap_[k] ? -epsilon_ : kNoVariable);
    low_[k] = a_[k] > 0 ? epsilon_ : (b_[k] < cap_[k] ? -epsilon_ : kNoVariable);
  }

  // One SMO step on the variable sample i offers to I_up and the one sample j offers to I_low
  // (two different variables, possibly of one sample), with k_i row i over the active samples;
  // returns the next select_up.
  Selection step_pair(std::size_t i, std::size_t j, const float* k_i, std::size_t active) {
    const bool minus_i = b_[i] > 0;  // as refresh() chose
    const bool plus_j = a_[j] > 0;
    double& alpha_i = minus_i ? b_[i] : a_[i];
    double& alpha_j = plus_j ? a_[j] : b_[j];
    const int y_i = minus_i ? -1 : 1, y_j = plus_j ? 1 : -1;
    const double g_i = minus_i ? epsilon_ - f_[i] : f_[i] + epsilon_;
    const double g_j = plus_j ? f_[j] + epsilon_ : epsilon_ - f_[j];
    const double k_ij = k_i[j];
    const double quad = qd_[i] + qd_[j] - 2 * k_ij;
    if (!support_.empty()) {
      Selection next;
      if (i != j &&
          conjugate_step(i, j, k_i, minus_i, plus_j, y_i * g_i - y_j * g_j, quad, active, next))
        return next;
      forget_direction();
    }
    const double old_i = alpha_i, old_j = alpha_j;
    const double c_i = cap_[i], c_j = cap_[j];
    const bool upper_i = old_i >= c_i, upper_j = old_j >= c_j;
    two_variable_step(alpha_i, alpha_j, y_i, y_j, g_i, g_j, quad, c_i, c_j);
    const double d_i = y_i * (alpha_i - old_i), d_j = y_j * (alpha_j - old_j);  // Δβ
    refresh(i);
    refresh(j);
    if (upper_i != (alpha_i >= c_i))  // row i grows in place to n entries
      loops_.add_row(gbar_.data(), rows_.row(index_[i], n_), (upper_i ? -c_i : c_i) * y_i, 0, n_);
    if (upper_j != (alpha_j >= c_j))
      loops_.add_row(gbar_.data(), rows_.row(index_[j], n_), (upper_j ? -c_j : c_j) * y_j, 0, n_);
    if (i == j)
      return loops_.update_and_select_up(f_.data(), up_.data(), k_i, k_i, d_i + d_j, 0, active);
    const float* k_j = rows_.row(index_[j], active);  // evicts the oldest row, never k_i
    const Selection next =
        loops_.update_and_select_up(f_.data(), up_.data(), k_i, k_j, d_i, d_j, active);
    // Clipping sets a variable to a bound, so two free variables mean the step reached the line
    // minimum, and the next direction can be made conjugate to this one (u_β = e_i − e_j).
    if (conjugate_ && quad > 0 && alpha_i > 0 && alpha_i < c_i && alpha_j > 0 && alpha_j < c_j) {
      add_to_support(i);
      add_to_support(j);
      (minus_i ? db_ : da_)[i] = y_i;
      (plus_j ? da_ : db_)[j] = -y_j;
      loops_.conjugate_update_and_select_up(f_.data(), up_.data(), k_i, k_j, kd_.data(), 0.0, 0.0,
                                            active);
      dkd_ = quad;
    }
    return next;
  }

  // The step along d' = u + λ·d, Q-conjugate to the last direction d, where u moves the variable
  // sample i offers to I_up and the one sample j offers to I_low as the ordinary step would
  // (∇ᵀu = g_u < 0, uᵀQu = quad). Returns false, having changed only the stored direction, when
  // the step is not a descent step that keeps every variable strictly inside the box.
  bool conjugate_step(std::size_t i, std::size_t j, const float* k_i, bool minus_i, bool plus_j,
                      double g_u, double quad, std::size_t active, Selection& next) {
    if (!(quad > 0)) return false;
    const double ukd = kd_[i] - kd_[j];
    const double lambda = -ukd / dkd_;
    const double dkd = quad + 2 * lambda * ukd + lambda * lambda * dkd_;
    double g_d = 0;  // ∇ᵀd, zero in exact arithmetic after a line minimum; kept for safety
    for (const std::size_t k : support_)
      g_d += (f_[k] + epsilon_) * da_[k] + (epsilon_ - f_[k]) * db_[k];
    const double slope = g_u + lambda * g_d;
    if (!(dkd > 0) || !(slope < 0)) return false;
    const double t = -slope / dkd;
    for (const std::size_t k : support_) {
      da_[k] *= lambda;
      db_[k] *= lambda;
    }
    add_to_support(i);
    add_to_support(j);
    (minus_i ? db_[i] : da_[i]) += minus_i ? -1.0 : 1.0;  // y_i
    (plus_j ? da_[j] : db_[j]) -= plus_j ? 1.0 : -1.0;    // −y_j
    for (const std::size_t k : support_)
      if (!inside(a_[k], t * da_[k], k) || !inside(b_[k], t * db_[k], k)) return false;
    bool rows_asked = false;  // a variable left its upper bound, and Ḡ took its row
    for (const std::size_t k : support_) {
      rows_asked |= move(a_[k], t * da_[k], 1.0, k);
      rows_asked |= move(b_[k], t * db_[k], -1.0, k);
      refresh(k);
    }
    if (rows_asked) k_i = rows_.row(index_[i], active);  // it may have evicted row i
    const float* k_j = rows_.row(index_[j], active);
    next = loops_.conjugate_update_and_select_up(f_.data(), up_.data(), k_i, k_j, kd_.data(),
                                                 lambda, t, active);
    dkd_ = dkd;
    ++conjugate_steps_;
    if (support_.size() > kMaxSupport) forget_direction();
    return true;
  }

  // Whether a variable of sample k at v moved by delta stays strictly inside [0, C_k] (or does
  // not move).
  bool inside(double v, double delta, std::size_t k) const {
    return delta > 0 ? v + delta < cap_[k] : (delta < 0 ? v + delta > 0 : true);
  }

  // Moves one variable of sample k (sign y) by delta, keeping it in the box and Ḡ current;
  // true when that needed row k.
  bool move(double& alpha, double delta, double y, std::size_t k) {
    if (delta == 0) return false;
    return place(alpha, std::clamp(alpha + delta, 0.0, cap_[k]), y, k);
  }

  // Sets one variable of sample k (sign y) to `value` in [0, C_k], keeping Ḡ current; true when
  // that needed row k.
  bool place(double& alpha, double value, double y, std::size_t k) {
    const double c_k = cap_[k];
    const bool upper = alpha >= c_k;
    alpha = value;
    if (upper == (alpha >= c_k)) return false;
    loops_.add_row(gbar_.data(), rows_.row(index_[k], n_), (upper ? -c_k : c_k) * y, 0, n_);
    return true;
  }

  void add_to_support(std::size_t k) {
    if (in_support_[k]) return;
    in_support_[k] = 1;
    support_.push_back(k);
  }

  void forget_direction() {
    for (const std::size_t k : support_) {
      da_[k] = 0;
      db_[k] = 0;
      in_support_[k] = 0;
    }
    support_.clear();
  }

  // The part of β_k from variables strictly inside the box; the rest is in Ḡ.
  double free_part(std::size_t k) const {
    return (a_[k] > 0 && a_[k] < cap_[k] ? a_[k] : 0.0) -
           (b_[k] > 0 && b_[k] < cap_[k] ? b_[k] : 0.0);
  }
};

}  // namespace fogdrift::svr::detail
