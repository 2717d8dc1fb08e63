// The one engine that fits SVRs on folds and scores them (docs/svr.md, "Searches on folds").
// Every search of fogdrift is a list of path tasks: on one fold, one kernel, C values in
// ascending order, each fit warm-started from the one before (the first from a solution the
// caller gives), scored by the sum of squared errors on the fold's held-out rows or kept as
// predictions there. The tuner's candidates (tune.hpp) are paths of one C warm-started from the
// nearest solved candidate; the grid search's (grid_search.hpp) are the whole C axis of a
// kernel. Tasks run on the caller's pool, longest first as guessed, each with a workspace from
// the caller's WorkspacePool; the order never changes a result, and neither does the thread
// count.
#pragma once

#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "fogdrift/svr/svr.hpp"
#include "fogdrift/svr/workspace.hpp"

namespace fogdrift {
class ThreadPool;
}

namespace fogdrift::svr {

/// A fold the tasks fit and score on: its training rows, and the rows of `held` it is scored on
/// and predicted at.
struct ScoringFold {
  const TrainingSet* train = nullptr;
  const Data* held = nullptr;
  std::span<const std::size_t> score_rows;    ///< Σ (f(x) − y)² over these rows of `held`
  std::span<const std::size_t> predict_rows;  ///< f(x) at these rows, for tasks that ask
};

struct PathTask {
  std::size_t fold = 0;
  Params params;                 ///< the kernel, ε, tolerance, cache…; C is each of c_values
  std::vector<double> c_values;  ///< in the order fitted, ascending for warm starts to help
  const DualSolution* warm = nullptr;  ///< the first fit's warm start
  bool predict = false;                ///< predictions at predict_rows instead of squared errors
  bool keep_duals = false;          ///< keep each fit's solution (the caller's later warm starts)
  double guess_seconds = INFINITY;  ///< how long it is expected to take: longest first
};

struct PathScores {
  std::vector<double> sse;                                 ///< per C, unless predict
  std::vector<double> predictions;                         ///< [row][C] at predict_rows, if predict
  std::vector<std::shared_ptr<const DualSolution>> duals;  ///< per C, if keep_duals
  std::vector<double> seconds;                             ///< per C, each fit's
};

/// Runs every task; results in the order of `tasks`. Without a pool, on this thread.
std::vector<PathScores> run_paths(std::span<const ScoringFold> folds,
                                  std::span<const PathTask> tasks, ThreadPool* pool,
                                  WorkspacePool& workspaces);

}  // namespace fogdrift::svr
