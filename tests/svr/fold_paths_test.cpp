// The engine every search runs on (fold_paths.hpp): a path task is the fits fit_c_path makes,
// scored as path_squared_errors scores them; a one-C task warm-started from a solution is that
// warm-started fit; a fit stopped at its iteration cap says so and finishes from where it
// stopped; predictions add up to the errors; chains run a task only when the rule said so
// after the one before; and neither the order of the tasks nor the thread count changes a number.
#include "fogdrift/svr/fold_paths.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "fogdrift/base/thread_pool.hpp"

namespace fogdrift::svr {
namespace {

Data wavy_data(std::size_t n) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.05);
  Data d;
  d.rows = n;
  d.cols = 2;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::sin(0.07 * i), b = std::cos(0.023 * i);
    d.x.insert(d.x.end(), {a, b});
    d.y.push_back(a * b + std::sin(3 * a) + noise(rng));
  }
  return d;
}

struct EvenOddFolds {
  Data all;
  std::vector<std::unique_ptr<TrainingSet>> sets;
  std::vector<std::vector<std::size_t>> held;
  std::vector<ScoringFold> scoring;
};

/// Two folds: even rows train, odd rows are held out, and the other way round.
EvenOddFolds even_odd_folds(std::size_t n) {
  EvenOddFolds f{wavy_data(n), {}, {}, {}};
  for (std::size_t k = 0; k < 2; ++k) {
    std::vector<std::size_t> train, held;
    for (std::size_t i = 0; i < n; ++i) (i % 2 == k ? train : held).push_back(i);
    f.sets.push_back(std::make_unique<TrainingSet>(f.all.subset(train)));
    f.held.push_back(held);
  }
  for (std::size_t k = 0; k < 2; ++k)
    f.scoring.push_back({f.sets[k].get(), &f.all, f.held[k], f.held[k]});
  return f;
}

Params rbf_params(double gamma) {
  Params p;
  p.kernel = Kernel::rbf_gamma(gamma);
  p.epsilon = 0.05;
  p.tolerance = 1e-5;
  return p;
}

TEST(FoldPaths, ATaskIsItsPathScoredAndAWarmStartIsKept) {
  const EvenOddFolds f = even_odd_folds(200);
  const std::vector<double> cs = {0.3, 3.0, 30.0};
  std::vector<PathTask> tasks(2);
  tasks[0].fold = 1;
  tasks[0].params = rbf_params(1.5);
  tasks[0].c_values = cs;
  tasks[0].keep_duals = true;
  WorkspacePool spaces;
  const std::vector<PathScores> first = run_paths(f.scoring, {tasks.data(), 1}, nullptr, spaces);
  const std::vector<FitResult> path = fit_c_path(*f.sets[1], rbf_params(1.5), cs);
  EXPECT_EQ(first[0].sse, path_squared_errors(*f.sets[1], path, f.all, f.held[1]));
  ASSERT_EQ(first[0].duals.size(), cs.size());
  EXPECT_EQ(first[0].seconds.size(), cs.size());

  // One C from the path's last solution is fit() from it.
  tasks[1].fold = 1;
  tasks[1].params = rbf_params(1.5);
  tasks[1].params.c = 60.0;
  tasks[1].c_values = {60.0};
  tasks[1].warm = first[0].duals.back().get();
  const std::vector<PathScores> second = run_paths(f.scoring, {&tasks[1], 1}, nullptr, spaces);
  const FitResult warm = fit(*f.sets[1], tasks[1].params, first[0].duals.back().get());
  EXPECT_EQ(second[0].sse, path_squared_errors(*f.sets[1], {&warm, 1}, f.all, f.held[1]));
  EXPECT_TRUE(second[0].duals.empty());  // not asked for
}

// A fit stopped at params.max_iterations says so (the tuner's cap, docs/tuning.md), and a fit
// warm-started from its unfinished solution runs to the end: the finished loss of that C.
TEST(FoldPaths, ACappedFitSaysSoAndFinishesFromWhereItStopped) {
  const EvenOddFolds f = even_odd_folds(200);
  PathTask capped;
  capped.fold = 0;
  capped.params = rbf_params(1.5);
  capped.params.c = 300;
  capped.params.max_iterations = 20;
  capped.c_values = {300};
  capped.keep_duals = true;
  PathTask whole = capped;
  whole.params.max_iterations = 0;
  WorkspacePool spaces;
  const std::vector<PathTask> both = {capped, whole};
  const std::vector<PathScores> s = run_paths(f.scoring, both, nullptr, spaces);
  ASSERT_EQ(s[0].status.size(), 1u);
  EXPECT_EQ(s[0].status[0], SolverStatus::iteration_limit);
  EXPECT_EQ(s[1].status[0], SolverStatus::optimal);
  // Twenty iterations are far from the optimum here: the unfinished fit errs otherwise.
  EXPECT_GT(std::fabs(s[0].sse[0] - s[1].sse[0]), 1e-3 * s[1].sse[0]);

  PathTask finish = whole;
  finish.warm = s[0].duals[0].get();
  const std::vector<PathScores> finished = run_paths(f.scoring, {&finish, 1}, nullptr, spaces);
  EXPECT_EQ(finished[0].status[0], SolverStatus::optimal);
  // The same optimum to the solver's tolerance (1e-5), from another starting point.
  EXPECT_NEAR(finished[0].sse[0], s[1].sse[0], 1e-3 * s[1].sse[0]);
}

TEST(FoldPaths, PredictionsAddUpAndNothingDependsOnOrderOrThreads) {
  const EvenOddFolds f = even_odd_folds(180);
  std::vector<PathTask> tasks;
  for (std::size_t fold = 0; fold < 2; ++fold)
    for (const double gamma : {0.5, 2.0, 8.0}) {
      PathTask& t = tasks.emplace_back();
      t.fold = fold;
      t.params = rbf_params(gamma);
      t.c_values = {0.1, 1.0, 10.0};
      t.guess_seconds = gamma;  // handed out in another order than given
    }
  WorkspacePool spaces;
  const std::vector<PathScores> serial = run_paths(f.scoring, tasks, nullptr, spaces);
  ThreadPool pool(3);
  const std::vector<PathScores> parallel = run_paths(f.scoring, tasks, &pool, spaces);
  std::vector<PathTask> predicting = tasks;
  for (PathTask& t : predicting) t.predict = true;
  const std::vector<PathScores> predicted = run_paths(f.scoring, predicting, &pool, spaces);
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    EXPECT_EQ(serial[k].sse, parallel[k].sse) << k;
    const std::vector<std::size_t>& rows = f.held[tasks[k].fold];
    ASSERT_EQ(predicted[k].predictions.size(), rows.size() * 3);
    for (std::size_t c = 0; c < 3; ++c) {
      double sse = 0;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const double e = predicted[k].predictions[r * 3 + c] - f.all.y[rows[r]];
        sse += e * e;
      }
      EXPECT_NEAR(sse, serial[k].sse[c], 1e-9 * serial[k].sse[c]) << k << " " << c;
    }
  }
}

TEST(FoldPaths, AChainGoesOnOnlyWhereItsRuleSaysAndNothingElseMoves) {
  const EvenOddFolds f = even_odd_folds(180);
  // Chains of two: fold 0, then fold 1, for five kernels; then a chain of one (7 % 2).
  std::vector<PathTask> tasks;
  const std::vector<double> gammas = {0.05, 0.5, 2.0, 8.0, 30.0, 1.0};
  for (std::size_t g = 0; g < gammas.size(); ++g)
    for (std::size_t fold = 0; fold < 2; ++fold) {
      if (g + 1 == gammas.size() && fold == 1) break;
      PathTask& t = tasks.emplace_back();
      t.fold = fold;
      t.params = rbf_params(gammas[g]);
      t.c_values = {3.0};
      t.guess_seconds = static_cast<double>((g * 7 + fold) % 5);  // another order than given
    }
  WorkspacePool spaces;
  const std::vector<PathScores> every = run_paths(f.scoring, tasks, nullptr, spaces);
  // Go on where the first fold's error is below the median of the five: some chains stop.
  std::vector<double> first;
  for (std::size_t k = 0; k + 1 < tasks.size(); k += 2) first.push_back(every[k].sse[0]);
  std::sort(first.begin(), first.end());
  const double median = first[2];
  for (unsigned threads : {1u, 2u, 3u}) {
    ThreadPool pool(threads);
    std::vector<int> asked(tasks.size(), 0);
    const std::vector<PathScores> chained = run_path_chains(
        f.scoring, tasks, 2, &pool, spaces, [&](std::size_t k, const PathScores& s) {
          ++asked[k];
          return s.sse[0] < median;
        });
    ASSERT_EQ(chained.size(), tasks.size());
    std::size_t stopped = 0;
    for (std::size_t k = 0; k < tasks.size(); ++k) {
      const bool chain_start = k % 2 == 0;
      // The rule is asked once after every task that has a next one in its chain, never after
      // the last of a chain.
      const bool has_next = chain_start && k + 1 < tasks.size();
      EXPECT_EQ(asked[k], has_next && !chained[k].sse.empty() ? 1 : 0) << threads << " " << k;
      const bool runs = chain_start || every[k - 1].sse[0] < median;
      if (runs) {
        EXPECT_EQ(chained[k].sse, every[k].sse) << threads << " " << k;  // to the bit
      } else {
        EXPECT_TRUE(chained[k].sse.empty()) << threads << " " << k;
        ++stopped;
      }
    }
    EXPECT_EQ(stopped, 3u) << threads;  // the three kernels at or above the median
  }
}

TEST(FoldPaths, AStoppedChainRunsNothingMore) {
  // One chain of three on two threads: the rule stops it after its first task, and nothing of
  // the other two is run or returned.
  const EvenOddFolds f = even_odd_folds(240);
  std::vector<PathTask> tasks(3);
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    tasks[k].fold = k % 2;
    tasks[k].params = rbf_params(0.5 + static_cast<double>(k));
    tasks[k].c_values = {10.0};
  }
  WorkspacePool spaces;
  ThreadPool pool(2);
  for (int repeat = 0; repeat < 5; ++repeat) {
    int asked = 0;
    const std::vector<PathScores> out =
        run_path_chains(f.scoring, tasks, 3, &pool, spaces, [&](std::size_t k, const PathScores&) {
          EXPECT_EQ(k, 0u);
          ++asked;
          return false;
        });
    EXPECT_EQ(asked, 1);
    EXPECT_EQ(out[0].sse.size(), 1u);
    EXPECT_TRUE(out[1].sse.empty() && out[1].seconds.empty());
    EXPECT_TRUE(out[2].sse.empty() && out[2].seconds.empty());
  }
}

TEST(FoldPaths, AFailingTaskStopsItsChainsAndIsRethrown) {
  const EvenOddFolds f = even_odd_folds(120);
  std::vector<PathTask> tasks(4);
  for (std::size_t k = 0; k < tasks.size(); ++k) {
    tasks[k].fold = k % 2;
    tasks[k].params = rbf_params(1.0);
    tasks[k].c_values = {1.0};
  }
  tasks[0].c_values = {-1.0};  // C must be positive: the fit throws
  WorkspacePool spaces;
  ThreadPool pool(2);
  EXPECT_THROW(run_path_chains(f.scoring, tasks, 2, &pool, spaces,
                               [](std::size_t, const PathScores&) { return true; }),
               std::invalid_argument);
}

}  // namespace
}  // namespace fogdrift::svr
