// The one engine that fits SVRs on folds and scores them (docs/svr.md, "Searches on folds").
// Every search of fogdrift is a list of path tasks: on one fold, one kernel, C values in
// ascending order, each fit warm-started from the one before (the first from a solution the
// caller gives), scored by the sum of squared errors on the fold's held-out rows or kept as
// predictions there. The tuner's candidates (tune.hpp) are paths of one C warm-started from the
// nearest solved candidate; the grid search's (grid_search.hpp) are the whole C axis of a
// kernel. Tasks run on the caller's pool, longest first as guessed, each with a workspace from
// the caller's WorkspacePool; the order never changes a result, and neither does the thread
// count. Tasks may also come in chains whose next task runs only if the caller's rule says so
// after the one before (the tuner's racing: a candidate's folds, one after another, for as long
// as it can still win); chains run side by side, without waiting for one another.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
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
  /// per C: iteration_limit for a fit stopped at params.max_iterations, unfinished
  std::vector<SolverStatus> status;
};

/// Runs every task; results in the order of `tasks`. Without a pool, on this thread.
std::vector<PathScores> run_paths(std::span<const ScoringFold> folds,
                                  std::span<const PathTask> tasks, ThreadPool* pool,
                                  WorkspacePool& workspaces);

/// Whether the chain of task `k` goes on to task k + 1, from task k's scores.
using ChainRule = std::function<bool(std::size_t k, const PathScores& scores)>;

/// Runs `tasks` as chains of `chain_length` consecutive tasks (the last chain may be shorter):
/// the first task of every chain, and task k + 1 of a chain once task k has run and
/// `go_on(k, scores of k)` is true. A task whose chain stopped before it is not run and keeps
/// empty scores. Chains run in parallel, each as soon as a thread is free: no chain waits for
/// another's step, so a thread idles only when no ready task is left. Among ready tasks the one
/// whose chain has the most guessed time left (its guess × tasks left in its chain) goes first.
/// `go_on` is called one at a time. Since a chain's decisions read only its own scores, which
/// tasks run, and so every result, do not depend on the order or the thread count.
std::vector<PathScores> run_path_chains(std::span<const ScoringFold> folds,
                                        std::span<const PathTask> tasks, std::size_t chain_length,
                                        ThreadPool* pool, WorkspacePool& workspaces,
                                        const ChainRule& go_on);

}  // namespace fogdrift::svr
