// Path tasks on folds (fold_paths.hpp).
#include "fogdrift/svr/fold_paths.hpp"

#include <algorithm>
#include <numeric>

#include "fogdrift/base/thread_pool.hpp"

namespace fogdrift::svr {

std::vector<PathScores> run_paths(std::span<const ScoringFold> folds,
                                  std::span<const PathTask> tasks, ThreadPool* pool,
                                  WorkspacePool& workspaces) {
  std::vector<PathScores> out(tasks.size());
  std::vector<std::size_t> order(tasks.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return tasks[a].guess_seconds > tasks[b].guess_seconds;
  });
  auto one = [&](std::size_t k) {
    const PathTask& task = tasks[order[k]];
    const ScoringFold& fold = folds[task.fold];
    PathScores& scores = out[order[k]];
    const WorkspacePool::Lease workspace = workspaces.borrow();
    std::vector<FitResult> path =
        fit_c_path(*fold.train, task.params, task.c_values, workspace.get(), task.warm);
    // Scored with one vectorised kernel row per held-out row, in float as the solver's rows
    // (path_squared_errors): a scalar prediction per support vector was 40 % of a search.
    if (task.predict)
      scores.predictions = path_predictions(*fold.train, path, *fold.held, fold.predict_rows);
    else
      scores.sse = path_squared_errors(*fold.train, path, *fold.held, fold.score_rows);
    for (FitResult& fit : path) {
      scores.seconds.push_back(fit.summary.seconds);
      if (task.keep_duals)
        scores.duals.push_back(std::make_shared<const DualSolution>(std::move(fit.dual)));
    }
  };
  if (pool)
    pool->parallel_for(order.size(), one);
  else
    for (std::size_t k = 0; k < order.size(); ++k) one(k);
  return out;
}

}  // namespace fogdrift::svr
