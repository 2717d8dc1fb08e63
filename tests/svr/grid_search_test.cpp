// The grid search over folds (grid_search.hpp): every (kernel, C, fold) as a fit of its own
// would score it, C in any order, predictions that add up to the errors, and the same numbers
// on any number of threads.
#include "fogdrift/svr/grid_search.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"

namespace fogdrift::svr {
namespace {

Data smooth(std::size_t n) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 0.05);
  Data d;
  d.rows = n;
  d.cols = 2;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = std::sin(0.05 * i), b = std::cos(0.031 * i);
    d.x.insert(d.x.end(), {a, b});
    d.y.push_back(std::sin(2 * a) + 0.5 * a * b + noise(rng));
  }
  return d;
}

std::vector<GridFold> two_folds(std::size_t n) {
  std::vector<GridFold> folds(2);
  for (std::size_t i = 0; i < n; ++i) {
    folds[i % 2].train.push_back(i);
    folds[1 - i % 2].test.push_back(i);
  }
  for (auto& f : folds) f.predict = f.test;
  return folds;
}

Params base(double gamma) {
  Params p;
  p.kernel = Kernel::rbf_gamma(gamma);
  p.epsilon = 0.05;
  p.tolerance = 1e-6;
  return p;
}

TEST(GridSearch, EachPointIsTheFitOfItsOwnAndCMayComeInAnyOrder) {
  const Data d = smooth(240);
  const auto folds = two_folds(d.rows);
  const std::vector<double> gammas = {0.5, 2.0}, cs = {10.0, 0.1, 1.0};  // not sorted
  ThreadPool pool(2);
  WorkspacePool spaces;
  const GridSearchResult r = grid_search(
      d, folds, gammas.size(), [&](const Data&, std::size_t k) { return base(gammas[k]); }, cs,
      false, pool, spaces);
  ASSERT_EQ(r.sse.size(), 2u * 3u * 2u);
  for (std::size_t k = 0; k < gammas.size(); ++k)
    for (std::size_t c = 0; c < cs.size(); ++c)
      for (std::size_t f = 0; f < folds.size(); ++f) {
        // A cold fit of this point alone, scored by the same sum.
        TrainingSet set(d.subset(folds[f].train));
        Params p = base(gammas[k]);
        p.c = cs[c];
        const std::vector<FitResult> one = {fit(set, p)};
        const double cold = path_squared_errors(set, one, d, folds[f].test)[0];
        // The warm path stops within the solver's tolerance of the same optimum.
        EXPECT_NEAR(r.sse_at(k, c, f), cold, 1e-4 * cold) << k << " " << c << " " << f;
      }
}

TEST(GridSearch, PredictionsAddUpToTheErrorsAndThreadsChangeNothing) {
  const Data d = smooth(200);
  const auto folds = two_folds(d.rows);
  const std::vector<double> cs = {0.3, 3.0};
  const auto params_of = [](const Data&, std::size_t) { return base(1.0); };
  WorkspacePool spaces;
  ThreadPool one(1), three(3);
  const GridSearchResult a = grid_search(d, folds, 1, params_of, cs, false, one, spaces);
  const GridSearchResult b = grid_search(d, folds, 1, params_of, cs, false, three, spaces);
  EXPECT_EQ(a.sse, b.sse);
  const GridSearchResult p = grid_search(d, folds, 1, params_of, cs, true, three, spaces);
  ASSERT_TRUE(p.sse.empty());
  for (std::size_t f = 0; f < folds.size(); ++f)
    for (std::size_t c = 0; c < cs.size(); ++c) {
      double sse = 0;
      const std::size_t n = folds[f].predict.size();
      for (std::size_t i = 0; i < n; ++i) {
        const double e = p.predictions[f][c * n + i] - d.y[folds[f].predict[i]];
        sse += e * e;
      }
      EXPECT_NEAR(sse, a.sse_at(0, c, f), 1e-9 * sse);
    }
}

TEST(GridSearch, BadGridsAreErrorsBeforeAnyFit) {
  const Data d = smooth(50);
  const auto folds = two_folds(d.rows);
  ThreadPool pool(1);
  WorkspacePool spaces;
  const auto params_of = [](const Data&, std::size_t) { return base(1.0); };
  const auto option_of = [&](std::vector<double> cs, std::vector<GridFold> fs) {
    try {
      grid_search(d, fs, 1, params_of, cs, false, pool, spaces);
    } catch (const OptionError& e) {
      return e.option();
    }
    return std::string();
  };
  EXPECT_EQ(option_of({}, folds), "C");
  EXPECT_EQ(option_of({1.0, -2.0}, folds), "C");
  EXPECT_EQ(option_of({1.0, NAN}, folds), "C");
  EXPECT_EQ(option_of({1.0}, {}), "folds");
  auto far = folds;
  far[0].test.push_back(d.rows);
  EXPECT_EQ(option_of({1.0}, far), "folds");
  EXPECT_EQ(spaces.size(), 0u);  // no fit started
}

}  // namespace
}  // namespace fogdrift::svr
