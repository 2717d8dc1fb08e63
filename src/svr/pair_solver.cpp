// The pair solver (see solve_epsilon_svr in smo_solver.hpp for what it computes and why).
//
// LIBSVM's 2l variables come in pairs, α⁺_k and α⁻_k of sample k, whose gradients are tied:
// G⁺_k = f_k + ε and G⁻_k = ε − f_k with f = Kβ − z, β = α⁺ − α⁻. This solver keeps f (l doubles)
// instead of G (2l), kernel rows of l entries instead of 2l, and walks the samples: for each, the
// better of its two variables in I_up (I_low) is known from the bounds alone (loops.hpp). The
// working-set rule, the two-variable step, shrinking, reconstruction, stopping rule and ρ are
// LIBSVM's, applied to the variable each sample offers; a sample is shrunk when both of its
// variables would be. The gradient update and the next iteration's first selection share one
// pass. Ties can break differently from LIBSVM, so the path through the dual differs in detail
// while meeting the same stopping rule.
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
#include "svr/pair_solver.hpp"

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "svr/loops.hpp"
#include "svr/smo_parts.hpp"

namespace fogdrift::svr::detail {
namespace {

// The pair solver's per-sample arrays (11 doubles and a byte per sample), one block per thread
// kept from fit to fit. Allocated for every fit, they came from fresh pages each time (the
// allocator gives freed memory at the top of the heap back to the system), and page faults are
// slow on virtual machines: 426 faults for each C path of the bench's 20 fits. A thread runs one
// fit at a time, so one block per thread is enough.
struct Workspace {
  std::vector<double> values;
  std::vector<std::uint8_t> flags;
};
thread_local Workspace workspace;

class PairSmo {
 public:
  PairSmo(KernelCache& q, std::span<const double> target, double c, double epsilon,
          const SolverOptions& options)
      : n_(q.size()),
        c_(c),
        epsilon_(epsilon),
        tolerance_(options.tolerance),
        shrinking_(options.shrinking),
        conjugate_(options.conjugate),
        order_(take_order(q, options)),
        index_(order_->index),
        rows_(*order_->rows),
        rows_before_(rows_.rows_computed()) {
    take_arrays();
    for (std::size_t k = 0; k < n_; ++k) {
      const auto sample = static_cast<std::size_t>(index_[k]);
      z_[k] = target[sample];
      qd_[k] = q.diagonal(sample);
    }
    std::fill(a_.begin(), a_.end(), 0.0);
    std::fill(b_.begin(), b_.end(), 0.0);
    for (std::size_t k = 0; k < n_; ++k) f_[k] = -z_[k];
    std::fill(gbar_.begin(), gbar_.end(), 0.0);
    for (std::size_t k = 0; k < n_; ++k) refresh(k);
    active_ = n_;
    if (conjugate_) {
      std::fill(da_.begin(), da_.end(), 0.0);
      std::fill(db_.begin(), db_.end(), 0.0);
      std::fill(kd_.begin(), kd_.end(), 0.0);
      std::fill(in_support_.begin(), in_support_.end(), std::uint8_t{0});
    }
    const std::int64_t len = 2 * static_cast<std::int64_t>(n_);
    max_iterations_ =
        options.max_iterations > 0
            ? options.max_iterations
            : std::max<std::int64_t>(10000000, len > INT_MAX / 100 ? INT_MAX : 100 * len);
  }

  // Starts from a previous solution of the same data scaled to this C, as the other solver does.
  void warm_start(const DualSolution& w, bool same_kernel) {
    const double s = c_ / w.c;
    auto scaled = [&](double v) { return v >= w.c ? c_ : (v <= 0 ? 0.0 : std::min(c_, s * v)); };
    for (std::size_t k = 0; k < n_; ++k) {  // position k holds sample index_[k]
      const auto sample = static_cast<std::size_t>(index_[k]);
      a_[k] = scaled(w.alpha[sample]);
      b_[k] = scaled(w.alpha[sample + n_]);
      refresh(k);
    }
    if (same_kernel && w.gradient.size() == 2 * n_ && w.gradient_bar.size() == 2 * n_) {
      gradient_reused_ = true;
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
      const double bound = (a_[k] >= c_ ? c_ : 0.0) - (b_[k] >= c_ ? c_ : 0.0);
      if (beta == 0 && bound == 0) continue;
      const float* row = rows_.row(index_[k], n_);
      if (beta != 0) loops_.add_row(f_.data(), row, beta, 0, n_);
      if (bound != 0) loops_.add_row(gbar_.data(), row, bound, 0, n_);
    }
  }

  SolverSummary run() {
    SolverSummary summary;
    std::int64_t iter = 0;
    const auto period = static_cast<std::int64_t>(std::min<std::size_t>(2 * n_, 1000));
    std::int64_t counter = period + 1;
    Selection up;
    bool up_current = false;  // `up` is select_up of the current f and active set
    std::size_t i = 0, j = 0;
    while (iter < max_iterations_) {
      if (--counter == 0) {
        counter = period;
        forget_direction();  // shrinking reorders the samples, and Qd is kept for the active ones
        if (shrinking_) {
          shrink();
          rows_.apply_swaps();
          up_current = false;
        }
      }
      if (!up_current) up = loops_.select_up(f_.data(), up_.data(), active_);
      const float* k_i = nullptr;
      if (!select_working_set(up, i, j, k_i)) {
        forget_direction();
        reconstruct_gradient();
        active_ = n_;
        up = loops_.select_up(f_.data(), up_.data(), active_);
        if (!select_working_set(up, i, j, k_i)) break;
        counter = 1;  // shrink at the next iteration
      }
      ++iter;
      up = step(i, j, k_i);
      up_current = true;
    }
    if (iter >= max_iterations_) {
      summary.status = SolverStatus::iteration_limit;
      reconstruct_gradient();
      active_ = n_;
    }
    summary.iterations = iter;
    summary.kernel_rows = rows_.rows_computed() - rows_before_;
    summary.rho = calculate_rho();
    double v = 0;
    for (std::size_t k = 0; k < n_; ++k)
      v += a_[k] * ((f_[k] - z_[k]) + 2 * epsilon_) + b_[k] * ((z_[k] - f_[k]) + 2 * epsilon_);
    summary.objective = v / 2;
    summary.max_violation = violation();
    summary.gradient_reused = gradient_reused_;
    summary.conjugate_steps = conjugate_steps_;
    return summary;
  }

  // The order and rows an earlier fit on this cache left, or the identity order with no rows.
  static std::unique_ptr<SampleOrder> take_order(KernelCache& q, const SolverOptions& options) {
    std::unique_ptr<SampleOrder> kept = std::move(q.kept_order());
    if (kept && kept->index.size() == q.size()) return kept;
    auto order = std::make_unique<SampleOrder>();
    order->index.resize(q.size());
    for (std::size_t k = 0; k < q.size(); ++k) order->index[k] = static_cast<std::int32_t>(k);
    order->rows = std::make_unique<OrderedRows>(
        q, order->index.data(), q.size(), q.size(), options.solver_order_cache_mb,
        options.rows_in_order && !q.training_set().has_distances());
    return order;
  }

  std::unique_ptr<SampleOrder> release_order() { return std::move(order_); }

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

 private:
  const Loops& loops_ = loops();  // the inner loops, one instruction set (loops.hpp)
  std::size_t n_;
  double c_, epsilon_, tolerance_;
  bool shrinking_;
  bool conjugate_;
  std::int64_t max_iterations_ = 0;
  std::size_t active_ = 0;  // samples [0, active_) are not shrunk
  bool unshrunk_ = false;
  bool gradient_reused_ = false;
  // Per sample, in the solver's order (index_ maps a position to the training sample). The order
  // and its rows come from the KernelCache when an earlier fit left them there, and go back to
  // it at the end (release_order).
  std::unique_ptr<SampleOrder> order_;
  std::vector<std::int32_t>& index_;
  OrderedRows& rows_;
  std::int64_t rows_before_;  // rows_.rows_computed() when this fit began
  // The per-sample arrays are views of this thread's Workspace (take_arrays).
  std::span<double> z_, qd_, a_, b_;
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

  // Points the per-sample arrays into this thread's workspace, grown to this fit's size.
  void take_arrays() {
    std::span<double>* arrays[] = {&z_, &qd_, &a_, &b_, &f_, &gbar_, &up_, &low_, &da_, &db_, &kd_};
    const std::size_t count = conjugate_ ? 11 : 8;  // da_, db_, kd_ only for conjugate steps
    if (workspace.values.size() < count * n_) workspace.values.resize(count * n_);
    for (std::size_t a = 0; a < count; ++a)
      *arrays[a] = std::span<double>(workspace.values.data() + a * n_, n_);
    if (conjugate_) {
      if (workspace.flags.size() < n_) workspace.flags.resize(n_);
      in_support_ = std::span<std::uint8_t>(workspace.flags.data(), n_);
    }
  }

  // The offsets of loops.hpp: I_up offers α⁻ (−y·G = ε − f) when it can fall, else α⁺ (−ε − f)
  // when it can grow; I_low offers α⁺ (f + ε) when it can fall, else α⁻ (f − ε) when it can grow.
  void refresh(std::size_t k) {
    up_[k] = b_[k] > 0 ? epsilon_ : (a_[k] < c_ ? -epsilon_ : kNoVariable);
    low_[k] = a_[k] > 0 ? epsilon_ : (b_[k] < c_ ? -epsilon_ : kNoVariable);
  }

  // WSS 2 over the active samples; false when optimal within the tolerance. k_i: row i, which
  // stays valid through the step (a row asked for later evicts the least recently used).
  bool select_working_set(const Selection& up, std::size_t& i, std::size_t& j, const float*& k_i) {
    if (up.index < 0) return false;
    i = static_cast<std::size_t>(up.index);
    k_i = rows_.row(index_[i], active_);
    const SelectionJ low =
        loops_.select_low(f_.data(), low_.data(), k_i, qd_.data(), qd_[i], up.value, kTau, active_);
    if (up.value + low.g_max2 < tolerance_ || low.index < 0) return false;
    j = static_cast<std::size_t>(low.index);
    return true;
  }

  // One SMO step on the variable sample i offers to I_up and the one sample j offers to I_low
  // (two different variables, possibly of one sample), with k_i row i over the active samples;
  // returns the next select_up.
  Selection step(std::size_t i, std::size_t j, const float* k_i) {
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
      if (i != j && conjugate_step(i, j, k_i, minus_i, plus_j, y_i * g_i - y_j * g_j, quad, next))
        return next;
      forget_direction();
    }
    const double old_i = alpha_i, old_j = alpha_j;
    const bool upper_i = old_i >= c_, upper_j = old_j >= c_;
    two_variable_step(alpha_i, alpha_j, y_i, y_j, g_i, g_j, quad, c_);
    const double d_i = y_i * (alpha_i - old_i), d_j = y_j * (alpha_j - old_j);  // Δβ
    refresh(i);
    refresh(j);
    if (upper_i != (alpha_i >= c_))  // row i grows in place to n entries
      loops_.add_row(gbar_.data(), rows_.row(index_[i], n_), (upper_i ? -c_ : c_) * y_i, 0, n_);
    if (upper_j != (alpha_j >= c_))
      loops_.add_row(gbar_.data(), rows_.row(index_[j], n_), (upper_j ? -c_ : c_) * y_j, 0, n_);
    if (i == j)
      return loops_.update_and_select_up(f_.data(), up_.data(), k_i, k_i, d_i + d_j, 0, active_);
    const float* k_j = rows_.row(index_[j], active_);  // evicts the oldest row, never k_i
    const Selection next =
        loops_.update_and_select_up(f_.data(), up_.data(), k_i, k_j, d_i, d_j, active_);
    // Clipping sets a variable to a bound, so two free variables mean the step reached the line
    // minimum, and the next direction can be made conjugate to this one (u_β = e_i − e_j).
    if (conjugate_ && quad > 0 && alpha_i > 0 && alpha_i < c_ && alpha_j > 0 && alpha_j < c_) {
      add_to_support(i);
      add_to_support(j);
      (minus_i ? db_ : da_)[i] = y_i;
      (plus_j ? da_ : db_)[j] = -y_j;
      loops_.conjugate_update_and_select_up(f_.data(), up_.data(), k_i, k_j, kd_.data(), 0.0, 0.0,
                                            active_);
      dkd_ = quad;
    }
    return next;
  }

  // The step along d' = u + λ·d, Q-conjugate to the last direction d, where u moves the variable
  // sample i offers to I_up and the one sample j offers to I_low as the ordinary step would
  // (∇ᵀu = g_u < 0, uᵀQu = quad). Returns false, having changed only the stored direction, when
  // the step is not a descent step that keeps every variable strictly inside the box.
  bool conjugate_step(std::size_t i, std::size_t j, const float* k_i, bool minus_i, bool plus_j,
                      double g_u, double quad, Selection& next) {
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
      if (!inside(a_[k], t * da_[k]) || !inside(b_[k], t * db_[k])) return false;
    bool rows_asked = false;  // a variable left its upper bound, and Ḡ took its row
    for (const std::size_t k : support_) {
      rows_asked |= move(a_[k], t * da_[k], 1.0, k);
      rows_asked |= move(b_[k], t * db_[k], -1.0, k);
      refresh(k);
    }
    if (rows_asked) k_i = rows_.row(index_[i], active_);  // it may have evicted row i
    const float* k_j = rows_.row(index_[j], active_);
    next = loops_.conjugate_update_and_select_up(f_.data(), up_.data(), k_i, k_j, kd_.data(),
                                                 lambda, t, active_);
    dkd_ = dkd;
    ++conjugate_steps_;
    if (support_.size() > kMaxSupport) forget_direction();
    return true;
  }

  // Whether a variable at v moved by delta stays strictly inside [0, C] (or does not move).
  bool inside(double v, double delta) const {
    return delta > 0 ? v + delta < c_ : (delta < 0 ? v + delta > 0 : true);
  }

  // Moves one variable of sample k (sign y) by delta, keeping it in the box and Ḡ current;
  // true when that needed row k.
  bool move(double& alpha, double delta, double y, std::size_t k) {
    if (delta == 0) return false;
    const bool upper = alpha >= c_;
    alpha = std::clamp(alpha + delta, 0.0, c_);
    if (upper == (alpha >= c_)) return false;
    loops_.add_row(gbar_.data(), rows_.row(index_[k], n_), (upper ? -c_ : c_) * y, 0, n_);
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

  // LIBSVM's be_shrunk for both variables of sample k.
  bool be_shrunk(std::size_t k, double g_max1, double g_max2) const {
    const double g_plus = f_[k] + epsilon_, g_minus = epsilon_ - f_[k];
    const bool plus = a_[k] >= c_ ? -g_plus > g_max1 : (a_[k] <= 0 ? g_plus > g_max2 : false);
    if (!plus) return false;
    return b_[k] >= c_ ? -g_minus > g_max2 : (b_[k] <= 0 ? g_minus > g_max1 : false);
  }

  void swap_samples(std::size_t p, std::size_t q) {
    std::swap(index_[p], index_[q]);
    rows_.swapped(p, q);
    std::swap(z_[p], z_[q]);
    std::swap(qd_[p], qd_[q]);
    std::swap(a_[p], a_[q]);
    std::swap(b_[p], b_[q]);
    std::swap(f_[p], f_[q]);
    std::swap(gbar_[p], gbar_[q]);
    std::swap(up_[p], up_[q]);
    std::swap(low_[p], low_[q]);
  }

  // m(α) and M(α) over the first `len` samples: max −y·G over I_up, max y·G over I_low.
  std::pair<double, double> extremes(std::size_t len) const {
    double g_max1 = -DBL_MAX, g_max2 = -DBL_MAX;
    for (std::size_t k = 0; k < len; ++k) {
      if (up_[k] != kNoVariable) g_max1 = std::max(g_max1, up_[k] - f_[k]);
      if (low_[k] != kNoVariable) g_max2 = std::max(g_max2, f_[k] + low_[k]);
    }
    return {g_max1, g_max2};
  }

  void shrink() {
    const auto [g_max1, g_max2] = extremes(active_);
    if (!unshrunk_ && g_max1 + g_max2 <= tolerance_ * 10) {
      unshrunk_ = true;
      reconstruct_gradient();
      active_ = n_;
    }
    for (std::size_t k = 0; k < active_; ++k) {
      if (!be_shrunk(k, g_max1, g_max2)) continue;
      --active_;
      while (active_ > k) {
        if (!be_shrunk(active_, g_max1, g_max2)) {
          swap_samples(k, active_);
          break;
        }
        --active_;
      }
    }
  }

  // The part of β_k from variables strictly inside the box; the rest is in Ḡ.
  double free_part(std::size_t k) const {
    return (a_[k] > 0 && a_[k] < c_ ? a_[k] : 0.0) - (b_[k] > 0 && b_[k] < c_ ? b_[k] : 0.0);
  }

  // f of the shrunk samples from Ḡ and the free variables (LIBSVM's reconstruct_gradient). A
  // shrunk sample has both variables at a bound, so every free variable is active.
  void reconstruct_gradient() {
    if (active_ == n_) return;
    for (std::size_t k = active_; k < n_; ++k) f_[k] = gbar_[k] - z_[k];
    std::size_t nr_free = 0;
    for (std::size_t k = 0; k < active_; ++k)
      if (free_part(k) != 0) ++nr_free;
    if (nr_free * n_ > 2 * active_ * (n_ - active_)) {
      for (std::size_t k = active_; k < n_; ++k) {
        const float* row = rows_.row(index_[k], active_);
        double fk = f_[k];
        for (std::size_t q = 0; q < active_; ++q) {
          const double phi = free_part(q);
          if (phi != 0) fk += phi * row[q];
        }
        f_[k] = fk;
      }
    } else {
      for (std::size_t q = 0; q < active_; ++q) {
        const double phi = free_part(q);
        if (phi != 0) loops_.add_row(f_.data(), rows_.row(index_[q], n_), phi, active_, n_);
      }
    }
  }

  double violation() const {
    const auto [up, low] = extremes(n_);
    return up == -DBL_MAX || low == -DBL_MAX ? 0.0 : std::max(0.0, up + low);
  }

  // LIBSVM's calculate_rho over both variables of every active sample.
  double calculate_rho() const {
    std::size_t nr_free = 0;
    double ub = DBL_MAX, lb = -DBL_MAX, sum_free = 0;
    for (std::size_t k = 0; k < active_; ++k) {
      const double yg_plus = f_[k] + epsilon_, yg_minus = f_[k] - epsilon_;
      if (a_[k] >= c_) {
        lb = std::max(lb, yg_plus);
      } else if (a_[k] <= 0) {
        ub = std::min(ub, yg_plus);
      } else {
        ++nr_free;
        sum_free += yg_plus;
      }
      if (b_[k] >= c_) {
        ub = std::min(ub, yg_minus);
      } else if (b_[k] <= 0) {
        lb = std::max(lb, yg_minus);
      } else {
        ++nr_free;
        sum_free += yg_minus;
      }
    }
    return nr_free > 0 ? sum_free / static_cast<double>(nr_free) : (ub + lb) / 2;
  }
};

}  // namespace

SolverSummary solve_pairs(KernelCache& q, std::span<const double> target, double c, double epsilon,
                          const SolverOptions& options, DualSolution& out,
                          const DualSolution* warm) {
  PairSmo smo(q, target, c, epsilon, options);
  if (warm != nullptr) smo.warm_start(*warm, warm->kernel == q.kernel());
  const SolverSummary summary = smo.run();
  smo.export_solution(out);
  q.kept_order() = smo.release_order();
  return summary;
}

}  // namespace fogdrift::svr::detail
