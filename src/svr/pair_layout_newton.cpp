// The pair layout's Newton steps on the free samples between shrinking rounds (pair_layout.hpp;
// the step itself is free_set_step.hpp's): called once a round, not in the SMO's inner loop.
#include <algorithm>
#include <cstdint>

#include "svr/free_set_step.hpp"
#include "svr/pair_layout.hpp"

namespace fogdrift::svr::detail {

void PairLayout::between_rounds(std::size_t active, std::int64_t iterations) {
  if (!newton_) return;
  smo_work_ += static_cast<double>(iterations) * static_cast<double>(active);
  total_iterations_ += iterations;
  if (!warm_ && total_iterations_ < static_cast<std::int64_t>(n_)) return;
  free_.clear();
  for (std::size_t k = 0; k < active; ++k) {
    const bool a_free = a_[k] > 0 && a_[k] < cap_[k];
    const bool b_free = b_[k] > 0 && b_[k] < cap_[k];
    if ((a_free && b_[k] == 0) || (b_free && a_[k] == 0)) free_.push_back(k);
  }
  const std::size_t m = free_.size();
  const double rows_work = static_cast<double>(m) * static_cast<double>(active);
  if (m < 2 || m > kMaxNewtonFree ||
      kNewtonWorkWeight * (newton_work_ + free_set_step_work(m, 0)) + rows_work > smo_work_)
    return;
  Eigen::MatrixXd kff(m, m);
  Eigen::VectorXd r(m), lo(m), hi(m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t k = free_[i];
    const float* row = rows_.row(index_[k], active);
    for (std::size_t j = 0; j < m; ++j) kff(i, j) = row[free_[j]];
    kff(i, i) = qd_[k];
    // In β = α⁺ − α⁻: a free α⁺ has gradient f + ε and may change by [−α⁺, C − α⁺]; a free α⁻
    // has gradient f − ε and β may change by [α⁻ − C, α⁻].
    const bool plus = a_[k] > 0;
    r[i] = plus ? f_[k] + epsilon_ : f_[k] - epsilon_;
    lo[i] = plus ? -a_[k] : b_[k] - cap_[k];
    hi[i] = plus ? cap_[k] - a_[k] : b_[k];
  }
  kff = (0.5 * (kff + kff.transpose())).eval();  // rows are computed one by one, in floats
  const FreeSetStep step = free_set_step(kff, r, lo, hi, m);
  newton_work_ += free_set_step_work(m, step.removals);
  smo_work_ -= rows_work;
  if (!step.moved) return;
  for (std::size_t i = 0; i < m; ++i) {
    const std::size_t k = free_[i];
    const double beta = a_[k] - b_[k];
    const bool plus = a_[k] > 0;
    double& alpha = plus ? a_[k] : b_[k];
    const double y = plus ? 1.0 : -1.0;
    switch (step.ends[i]) {  // lower: β at lo, which is α⁺ = 0 or α⁻ = C
      case FreeSetEnd::lower:
        place(alpha, plus ? 0.0 : cap_[k], y, k);
        break;
      case FreeSetEnd::upper:
        place(alpha, plus ? cap_[k] : 0.0, y, k);
        break;
      case FreeSetEnd::free:
        place(alpha, std::clamp(alpha + y * step.delta[static_cast<Eigen::Index>(i)], 0.0, cap_[k]),
              y, k);
        break;
    }
    refresh(k);
    const double moved = (a_[k] - b_[k]) - beta;
    if (moved != 0) loops_.add_row(f_.data(), rows_.row(index_[k], active), moved, 0, active);
  }
  forget_direction();
  up_current_ = false;
  ++newton_steps_;
}

}  // namespace fogdrift::svr::detail
