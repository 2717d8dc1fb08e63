// The LIBSVM path: ε-SVR's dual over LIBSVM's 2l variables, step for step as svm-train. Internal
// header; the public entry point is solve_epsilon_svr (fogdrift/svr/smo_solver.hpp), which
// documents it.
#pragma once

#include <span>

#include "fogdrift/svr/smo_solver.hpp"

namespace fogdrift::svr::detail {

/// Solves the dual from α = 0 or from `warm` (same data, already checked) into `out`. Fills every
/// summary field but warm_started, kernel_rows and seconds.
SolverSummary solve_libsvm_path(KernelCache& q, std::span<const double> target, double c,
                                double epsilon, const SolverOptions& options, DualSolution& out,
                                const DualSolution* warm);

}  // namespace fogdrift::svr::detail
