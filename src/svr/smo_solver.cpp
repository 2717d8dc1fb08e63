#include "fogdrift/svr/smo_solver.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "svr/libsvm_solver.hpp"
#include "svr/pair_solver.hpp"

namespace fogdrift::svr {

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
  const DualSolution* from = warm_started ? warm : nullptr;
  if (options.libsvm_path)
    summary = detail::solve_libsvm_path(q, y, c, epsilon, options, out, from);
  else
    summary = detail::solve_pairs(q, y, c, epsilon, options, out, from);
  out.c = c;
  out.epsilon = epsilon;
  out.kernel = q.kernel();
  summary.warm_started = warm_started;
  summary.kernel_rows += q.rows_computed() - rows_before;  // plus any the solver computed itself
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace fogdrift::svr
