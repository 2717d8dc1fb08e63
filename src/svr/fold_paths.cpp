// Path tasks on folds (fold_paths.hpp).
#include "fogdrift/svr/fold_paths.hpp"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>

#include "fogdrift/base/interrupt.hpp"
#include "fogdrift/base/thread_pool.hpp"

namespace fogdrift::svr {
namespace {

// One task: its fits in order, then their scores (or predictions) on the fold's held-out rows.
PathScores run_one(const ScoringFold& fold, const PathTask& task, WorkspacePool& workspaces) {
  PathScores scores;
  const WorkspacePool::Lease workspace = workspaces.borrow();
  std::vector<FitResult> path =
      fit_c_path(*fold.train, task.params, task.c_values, workspace.get(), task.warm);
  // Scored with one vectorised kernel row per held-out row, in the fits' own arithmetic
  // (path_squared_errors): a scalar prediction per support vector was 40 % of a search.
  const KernelArithmetic arithmetic = task.params.kernel_arithmetic;
  if (task.predict)
    scores.predictions =
        path_predictions(*fold.train, path, *fold.held, fold.predict_rows, arithmetic);
  else
    scores.sse = path_squared_errors(*fold.train, path, *fold.held, fold.score_rows, arithmetic);
  for (FitResult& fit : path) {
    scores.seconds.push_back(fit.summary.seconds);
    scores.status.push_back(fit.summary.solver.status);
    if (task.keep_duals)
      scores.duals.push_back(std::make_shared<const DualSolution>(std::move(fit.dual)));
  }
  return scores;
}

}  // namespace

std::vector<PathScores> run_paths(std::span<const ScoringFold> folds,
                                  std::span<const PathTask> tasks, ThreadPool* pool,
                                  WorkspacePool& workspaces) {
  return run_path_chains(folds, tasks, 1, pool, workspaces,
                         [](std::size_t, const PathScores&) { return false; });
}

std::vector<PathScores> run_path_chains(std::span<const ScoringFold> folds,
                                        std::span<const PathTask> tasks, std::size_t chain_length,
                                        ThreadPool* pool, WorkspacePool& workspaces,
                                        const ChainRule& go_on) {
  std::vector<PathScores> out(tasks.size());
  if (tasks.empty()) return out;
  chain_length = std::max<std::size_t>(chain_length, 1);
  const auto chain_end = [&](std::size_t k) {
    return std::min(tasks.size(), (k / chain_length + 1) * chain_length);
  };
  // The guessed time left in task k's chain, k included: what longest-first orders by.
  const auto time_left = [&](std::size_t k) {
    return tasks[k].guess_seconds * static_cast<double>(chain_end(k) - k);
  };

  std::mutex mutex;
  std::condition_variable changed;
  std::vector<std::size_t> ready;  // tasks whose chain has reached them
  for (std::size_t k = 0; k < tasks.size(); k += chain_length) ready.push_back(k);
  std::size_t running = 0;
  std::exception_ptr error;

  // Each thread takes ready tasks until none is ready and none is running (a running task may
  // make its chain's next one ready).
  auto work = [&](std::size_t) {
    std::unique_lock lock(mutex);
    for (;;) {
      changed.wait(lock, [&] { return !ready.empty() || running == 0; });
      if (ready.empty()) return;
      // The most time left first; ties to the lowest index.
      auto pick = ready.begin();
      for (auto it = ready.begin(); it != ready.end(); ++it)
        if (time_left(*it) > time_left(*pick) ||
            (time_left(*it) == time_left(*pick) && *it < *pick))
          pick = it;
      const std::size_t k = *pick;
      ready.erase(pick);
      ++running;
      lock.unlock();
      PathScores scores;
      std::exception_ptr err;
      try {
        check_interrupt();  // base/interrupt.hpp: no new task once a stop was asked
        scores = run_one(folds[tasks[k].fold], tasks[k], workspaces);
      } catch (...) {
        err = std::current_exception();
      }
      lock.lock();
      --running;
      if (err) {
        if (!error) error = err;
        ready.clear();  // start nothing more; the running tasks finish
      } else {
        out[k] = std::move(scores);
        if (!error && k + 1 < chain_end(k) && go_on(k, out[k])) ready.push_back(k + 1);
      }
      changed.notify_all();
    }
  };
  if (pool != nullptr && pool->size() > 1)
    pool->parallel_for(pool->size(), work);
  else
    work(0);
  if (error) std::rethrow_exception(error);
  return out;
}

}  // namespace fogdrift::svr
