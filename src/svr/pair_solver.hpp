// The pair solver: ε-SVR's dual solved per sample rather than per variable. Internal header; the
// public entry point is solve_epsilon_svr (fogdrift/svr/smo_solver.hpp), which documents it.
#pragma once

#include <span>

#include "fogdrift/svr/smo_solver.hpp"

namespace fogdrift::svr::detail {

/// Solves the dual from α = 0 or from `warm` (same data, already checked) into `out`. Fills every
/// summary field but warm_started and seconds; kernel_rows counts only the rows it computed in
/// its own order (SolverOptions::rows_in_order), not those of the KernelCache.
SolverSummary solve_pairs(KernelCache& q, std::span<const double> target, double c, double epsilon,
                          const SolverOptions& options, DualSolution& out,
                          const DualSolution* warm);

}  // namespace fogdrift::svr::detail
