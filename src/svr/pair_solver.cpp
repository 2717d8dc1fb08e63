// The pair solver: the SMO skeleton (smo.hpp) run on the pair layout of the dual
// (pair_layout.hpp); see solve_epsilon_svr in smo_solver.hpp for what it computes and why.
#include "svr/pair_solver.hpp"

#include "svr/pair_layout.hpp"
#include "svr/smo.hpp"

namespace fogdrift::svr::detail {

SolverSummary solve_pairs(KernelCache& q, std::span<const double> target, double c, double epsilon,
                          const SolverOptions& options, DualSolution& out,
                          const DualSolution* warm) {
  PairLayout layout(q, target, c, epsilon, options);
  if (warm != nullptr)
    layout.warm_start(*warm, q.training_set().data(), warm->kernel == q.kernel());
  SolverSummary summary = Smo<PairLayout>(layout, options, q.size()).run();
  layout.export_solution(out);
  layout.keep_order(q);
  summary.kernel_rows = layout.rows_computed();
  summary.gradient_reused = layout.gradient_reused();
  summary.conjugate_steps = layout.conjugate_steps();
  summary.newton_steps = layout.newton_steps();
  return summary;
}

}  // namespace fogdrift::svr::detail
