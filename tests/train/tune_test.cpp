// The SVR loss against LIBSVM, and the tuner: determinism across thread counts, the memo,
// racing, and a search that does at least as well as a fine grid.
#include "fogdrift/train/tune.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "svr/libsvm_oracle.hpp"
#include "synthetic_dataset.hpp"
#include "train/svr_objective.hpp"

namespace fogdrift::tune {
namespace {

using test::synthetic;

// The cross-validation loss, recomputed fold by fold with LIBSVM as the regressor.
TEST(SvrLoss, AgreesWithLibsvmFoldByFold) {
  const Dataset d = synthetic();
  TuneOptions o;
  o.cv = {CvScheme::repetition};
  for (double c : {0.1, 10.0}) {
    for (double sigma : {0.5, 2.0}) {
      svr::Params p;
      p.c = c;
      p.kernel = svr::Kernel::rbf_sigma(sigma);
      p.epsilon = 0.1;
      double sse = 0;
      std::size_t n = 0;
      for (const Fold& f : grouped_folds(d, o.cv)) {
        const ScaledSplit s = scale_split(d, f.train_rows, f.test_rows);
        svr::testing::OracleFit ref;
        svr::testing::libsvm_train(s.train, p, ref);
        for (std::size_t r = 0; r < s.test.rows; ++r)
          sse += std::pow(ref.predict(s.test.row(r), 3) - s.test.y[r], 2);
        n += s.test.rows;
      }
      const double expected = std::sqrt(sse / n);
      EXPECT_NEAR(svr_loss(d, p, o), expected, 1e-3 * expected) << "C=" << c << " σ=" << sigma;
    }
  }
  // The training loss of a flexible model is below its cross-validation loss.
  svr::Params p;
  p.c = 100;
  p.kernel = svr::Kernel::rbf_sigma(0.3);
  TuneOptions train = o;
  train.fitness = Fitness::train;
  EXPECT_LT(svr_loss(d, p, train), svr_loss(d, p, o));
}

TuneOptions small_search(opt::Algorithm algorithm, ThreadPool* pool) {
  TuneOptions o;
  o.optimizer.algorithm = algorithm;
  o.optimizer.run.population = 10;
  o.optimizer.run.iterations = 12;
  o.optimizer.run.seed = 5;
  o.space.c_max = 10;  // large C costs many SMO iterations and adds nothing to these checks
  o.pool = pool;
  return o;
}

TEST(TuneSvr, SameSeedSameResultWhateverTheThreadCount) {
  const Dataset d = synthetic();
  ThreadPool one(1), two(2);
  for (auto a : {opt::Algorithm::ssa, opt::Algorithm::pso, opt::Algorithm::gwo}) {
    const TuneSummary s1 = tune_svr(d, small_search(a, &one));
    const TuneSummary s2 = tune_svr(d, small_search(a, &two));
    EXPECT_EQ(s1.best_fitness, s2.best_fitness) << opt::to_string(a);
    EXPECT_EQ(s1.best.c, s2.best.c);
    EXPECT_EQ(s1.best.kernel, s2.best.kernel);
    EXPECT_EQ(s1.optimizer.log.size(), s2.optimizer.log.size());
    for (std::size_t t = 0; t < s1.optimizer.log.size(); ++t)
      ASSERT_EQ(s1.optimizer.log[t].mean_fitness, s2.optimizer.log[t].mean_fitness);
    // Bookkeeping: every distinct candidate is fitted once per fold, but for the folds racing
    // spared (at least one, at most two of three a stopped candidate).
    EXPECT_EQ(s1.fits, s2.fits);
    EXPECT_EQ(s1.raced, s2.raced);
    EXPECT_EQ(s1.warm_fits, s2.warm_fits);
    EXPECT_LE(s1.fits, s1.candidates * 3 - s1.raced);
    EXPECT_GE(s1.fits, s1.candidates * 3 - 2 * s1.raced);
    EXPECT_EQ(s1.candidates + s1.repeats, s1.optimizer.evaluations);
    EXPECT_EQ(s1.folds.size(), 3u);
    ASSERT_EQ(s1.history.size(), s1.candidates);
    double lowest = INFINITY;
    std::size_t stopped = 0;
    for (const Candidate& c : s1.history) {
      lowest = std::min(lowest, c.loss);
      stopped += c.complete ? 0 : 1;
    }
    EXPECT_EQ(lowest, s1.best_fitness);
    EXPECT_EQ(stopped, s1.raced);
    // The reported fitness is the loss of the reported parameters, up to the solver's
    // tolerance: the search warm-starts fits (some from a near σ), svr_loss fits cold, and two
    // solutions within the tolerance differ in loss by up to about 2e-3 here.
    EXPECT_NEAR(svr_loss(d, s1.best, small_search(a, nullptr)), s1.best_fitness,
                3e-3 * s1.best_fitness);
  }
}

// Racing stops only candidates that cannot win: a stopped candidate's full cross-validation loss
// and the estimate the optimizer saw both lie above the best, so full evaluation of the
// candidates the search visited would choose the same one. Without racing every fold of every
// candidate is fitted.
TEST(TuneSvr, RacingStopsOnlyCandidatesThatCannotWin) {
  const Dataset d = synthetic();
  ThreadPool pool(2);
  TuneOptions o = small_search(opt::Algorithm::ssa, &pool);
  const TuneSummary raced = tune_svr(d, o);
  ASSERT_GT(raced.raced, 0u);
  TuneOptions full_options = o;
  full_options.racing = false;
  TuneOptions one_candidate = o;
  one_candidate.pool = nullptr;
  std::size_t checked = 0;
  for (const Candidate& c : raced.history) {
    const double full = svr_loss(d, c.params, one_candidate);
    // The search warm-starts some fits, svr_loss none: the same optimum to the solver's
    // tolerance (as above).
    if (c.complete) {
      EXPECT_NEAR(full, c.loss, 3e-3 * c.loss);
      continue;
    }
    EXPECT_GT(c.loss, raced.best_fitness) << "C=" << c.params.c;
    EXPECT_GT(full, raced.best_fitness * (1 - 3e-3)) << "C=" << c.params.c;  // cold vs warm fits
    ++checked;
  }
  EXPECT_EQ(checked, raced.raced);

  const TuneSummary full = tune_svr(d, full_options);
  EXPECT_EQ(full.raced, 0u);
  EXPECT_EQ(full.fits, full.candidates * 3);
  for (const Candidate& c : full.history) EXPECT_TRUE(c.complete);
  // Fewer fits for a search of the same length, ending as low (the optimizer saw estimates for
  // the losers, so it may have visited other candidates).
  EXPECT_LT(raced.fits, full.fits);
  EXPECT_LE(raced.best_fitness, full.best_fitness * 1.01);
}

// The search `o` again on `pool`: the same answer, loss and fits as `s` (checked); returned for
// further checks.
TuneSummary same_search_on(ThreadPool& pool, const Dataset& d, TuneOptions o,
                           const TuneSummary& s) {
  o.pool = &pool;
  TuneSummary again = tune_svr(d, o);
  EXPECT_EQ(again.best_fitness, s.best_fitness);
  EXPECT_EQ(again.best.c, s.best.c);
  EXPECT_EQ(again.fits, s.fits);
  return again;
}

// A cap on the search's fits (docs/tuning.md, "A cap on the search's fits"): capped candidates
// steer the search, but the answer's loss is that of fits run to the end. Every capped candidate
// that looked better than the answer was finished and is worse than it; racing stopped only
// candidates whose finished loss is above the answer; and the thread count changes nothing.
TEST(TuneSvr, ACappedSearchNeverAnswersWithAnUnfinishedFit) {
  const Dataset d = synthetic();
  ThreadPool one(1), two(2);
  TuneOptions o = small_search(opt::Algorithm::ssa, &two);
  o.space.c_max = 1000;  // the slow corner the cap is for
  o.smo_iterations_per_row = 2;
  const TuneSummary s = tune_svr(d, o);
  ASSERT_GT(s.capped_fits, 0u);
  ASSERT_FALSE(s.finished.empty());  // at this cap some capped candidate looked best

  TuneOptions whole = o;
  whole.pool = nullptr;
  whole.smo_iterations_per_row = 0;
  // The answer's loss is its parameters' loss (warm starts vs cold fits, as above).
  EXPECT_NEAR(svr_loss(d, s.best, whole), s.best_fitness, 3e-3 * s.best_fitness);
  bool found = false;
  for (const Candidate& c : s.finished) {
    EXPECT_TRUE(c.capped);
    EXPECT_GE(c.loss, s.best_fitness);
    EXPECT_NEAR(svr_loss(d, c.params, whole), c.loss, 3e-3 * c.loss) << "C=" << c.params.c;
    found = found || (c.params.c == s.best.c && c.loss == s.best_fitness);
  }
  std::size_t capped = 0;
  for (const Candidate& c : s.history) {
    capped += c.capped ? 1 : 0;
    if (!c.complete) {
      EXPECT_GT(svr_loss(d, c.params, whole), s.best_fitness * (1 - 3e-3)) << "C=" << c.params.c;
      continue;
    }
    if (!c.capped) {
      EXPECT_GE(c.loss, s.best_fitness);
      found = found || (c.params.c == s.best.c && c.loss == s.best_fitness);
      continue;
    }
    if (c.loss >= s.best_fitness) continue;
    // A capped candidate that looked better than the answer was finished.
    bool was_finished = false;
    for (const Candidate& f : s.finished)
      was_finished =
          was_finished || (f.params.c == c.params.c && f.params.kernel == c.params.kernel);
    EXPECT_TRUE(was_finished) << "C=" << c.params.c;
  }
  EXPECT_TRUE(found);
  EXPECT_GT(capped, 0u);
  EXPECT_LE(capped, s.capped_fits);

  const TuneSummary s1 = same_search_on(one, d, o, s);
  EXPECT_EQ(s1.capped_fits, s.capped_fits);
  EXPECT_EQ(s1.finished.size(), s.finished.size());

  // Without the cap no fit is stopped and nothing is finished.
  TuneOptions uncapped = o;
  uncapped.smo_iterations_per_row = 0;
  const TuneSummary u = tune_svr(d, uncapped);
  EXPECT_EQ(u.capped_fits, 0u);
  EXPECT_TRUE(u.finished.empty());
  for (const Candidate& c : u.history) EXPECT_FALSE(c.capped);
}

// A search that treats candidates within 0.01 decade as one: no two candidates it fitted are
// that close, evaluations were answered by a neighbour, the answer is a fitted complete
// candidate with its own loss, and the thread count changes nothing.
TEST(TuneSvr, CandidatesWithinTheResolutionAreOneAndTheAnswerWasFitted) {
  const Dataset d = synthetic();
  ThreadPool one(1), two(2);
  TuneOptions o = small_search(opt::Algorithm::ssa, &two);
  o.optimizer.run.iterations = 20;
  o.candidate_resolution = kMaxCandidateResolution;
  const TuneSummary s = tune_svr(d, o);
  ASSERT_GT(s.near_repeats, 0u);
  auto at = [](const svr::Params& p) {
    return std::array<double, 2>{std::log10(p.c), std::log10(p.kernel.sigma())};
  };
  bool answer_fitted = false;
  for (std::size_t i = 0; i < s.history.size(); ++i) {
    const auto a = at(s.history[i].params);
    for (std::size_t j = 0; j < i; ++j) {
      const auto b = at(s.history[j].params);
      EXPECT_GT(std::max(std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1])),
                o.candidate_resolution * (1 - 1e-12))
          << "candidates " << j << " and " << i;
    }
    const Candidate& c = s.history[i];
    if (c.complete) {
      EXPECT_GE(c.loss, s.best_fitness);
    }
    answer_fitted = answer_fitted || (c.complete && c.params.c == s.best.c &&
                                      c.params.kernel == s.best.kernel && c.loss == s.best_fitness);
  }
  EXPECT_TRUE(answer_fitted);
  TuneOptions whole = o;
  whole.pool = nullptr;
  EXPECT_NEAR(svr_loss(d, s.best, whole), s.best_fitness, 3e-3 * s.best_fitness);

  const TuneSummary s1 = same_search_on(one, d, o, s);
  EXPECT_EQ(s1.near_repeats, s.near_repeats);

  // Resolution 0: only equal points are one candidate.
  TuneOptions exact = o;
  exact.candidate_resolution = 0;
  const TuneSummary e = tune_svr(d, exact);
  EXPECT_EQ(e.near_repeats, 0u);
  EXPECT_GT(e.candidates, s.candidates);
}

// Within a batch and across batches: the nearer point within the resolution (in decades, in
// every coordinate) answers for a new one, and measured() names the candidate fitted.
TEST(SvrObjective, APointWithinTheResolutionTakesTheLossOfTheOneFitted) {
  const Dataset d = synthetic();
  TuneOptions o;
  o.candidate_resolution = 0.01;
  SvrObjective f(d, o, [&o](std::span<const double> x) { return params_at(x, o); });
  std::vector<double> points = {0.0, 0.0, 0.004, -0.003, 1.0, 0.3}, fitness(3);
  f.evaluate(points, fitness, 2);
  EXPECT_EQ(fitness[1], fitness[0]);
  EXPECT_NE(fitness[2], fitness[0]);
  EXPECT_EQ(f.candidates_, 2u);
  EXPECT_EQ(f.near_repeats_, 1u);
  EXPECT_EQ(f.measured(std::vector<double>{0.004, -0.003}), (std::vector<double>{0.0, 0.0}));

  points = {1.006, 0.295, 0.011, 0.0};
  std::vector<double> later(2);
  f.evaluate(points, later, 2);
  EXPECT_EQ(later[0], fitness[2]);  // within 0.01 of (1.0, 0.3), fitted in the first batch
  EXPECT_EQ(f.candidates_, 3u);     // (0.011, 0) is 0.011 from (0, 0): a candidate of its own
  EXPECT_EQ(f.near_repeats_, 2u);
  EXPECT_EQ(f.measured(std::vector<double>{1.006, 0.295}), (std::vector<double>{1.0, 0.3}));
  EXPECT_EQ(f.measured(std::vector<double>{0.011, 0.0}), (std::vector<double>{0.011, 0.0}));
  ASSERT_EQ(f.history_.size(), 3u);
}

// The search ends at least as low as the best point of a 9 × 9 grid over the same box (up to
// the solver tolerance), and well below LIBSVM's default parameters.
TEST(TuneSvr, MatchesAFineGrid) {
  const Dataset d = synthetic();
  ThreadPool pool(2);
  TuneOptions o = small_search(opt::Algorithm::ssa, &pool);
  o.optimizer.run.population = 15;
  o.optimizer.run.iterations = 25;
  const TuneSummary s = tune_svr(d, o);
  double grid_best = INFINITY;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      svr::Params p;
      p.c = std::pow(10.0, -2 + 3.0 * i / 8);
      p.kernel = svr::Kernel::rbf_sigma(std::pow(10.0, std::log10(0.05) + std::log10(400) * j / 8));
      grid_best = std::min(grid_best, svr_loss(d, p, o));
    }
  EXPECT_LE(s.best_fitness, grid_best * 1.002);
  svr::Params untuned;
  untuned.kernel = svr::Kernel::rbf_gamma(1.0 / 3);
  EXPECT_LT(s.best_fitness, 0.9 * svr_loss(d, untuned, o));
  EXPECT_GE(s.best.c, o.space.c_min);
  EXPECT_LE(s.best.kernel.sigma(), o.space.sigma_max * (1 + 1e-12));
}

// A search on every k-th training row fits with C × k. With every row of the campaign present
// twice in a row, every second training row is the campaign itself, and C × 2 on it is the same
// quadratic program as C on both copies (each copy's dual variable holds half): the losses the
// strided search saw equal the losses on all rows, to the solver's tolerance. The rescored
// candidates are the search's best, scored on all rows, and the winner is the lowest of them.
TEST(TuneSvr, AStrideScalesCSoThatDuplicatedRowsLoseNothing) {
  const Dataset once = synthetic();
  Dataset twice = once;
  twice.x.clear(), twice.y.clear(), twice.time_s.clear(), twice.group.clear();
  const std::size_t cols = once.feature_names.size();
  for (std::size_t r = 0; r < once.rows; ++r)
    for (int copy = 0; copy < 2; ++copy) {
      twice.x.insert(twice.x.end(), once.x.begin() + static_cast<long>(r * cols),
                     once.x.begin() + static_cast<long>((r + 1) * cols));
      twice.y.push_back(once.y[r]);
      twice.time_s.push_back(once.time_s[r]);
      twice.group.push_back(once.group[r]);
    }
  twice.rows = 2 * once.rows;
  ThreadPool pool(2);
  TuneOptions o = small_search(opt::Algorithm::ssa, &pool);
  // Three folds of the four temperatures, dealt in turn: the most training rows of a fold are
  // three temperatures' 360 rows (720 twice).
  o.cv.scheme = CvScheme::temperature;
  o.search_rows = 360;
  EXPECT_EQ(search_stride(once, o), 1u);
  // A fold smaller than thin_from_rows keeps every row; at or above it, search_rows decides.
  struct Case {
    std::size_t search_rows, thin_from_rows, stride;
  };
  for (const Case c : {Case{360, 0, 2}, Case{361, 0, 1}, Case{240, 0, 3}, Case{1000, 0, 1},
                       Case{0, 0, 1}, Case{240, 721, 1}, Case{240, 720, 3}, Case{0, 720, 1}}) {
    o.search_rows = c.search_rows;
    o.thin_from_rows = c.thin_from_rows;
    EXPECT_EQ(search_stride(twice, o), c.stride)
        << "search_rows " << c.search_rows << ", thin_from_rows " << c.thin_from_rows;
  }
  o.thin_from_rows = 0;
  o.search_rows = 360;
  const TuneSummary s = tune_svr(twice, o);
  ASSERT_EQ(s.stride, 2u);
  TuneOptions all_rows = o;
  all_rows.search_rows = 0;
  all_rows.pool = nullptr;
  std::size_t checked = 0;
  for (const Candidate& c : s.history) {
    if (!c.complete || checked == 6) continue;
    EXPECT_NEAR(svr_loss(twice, c.params, all_rows), c.loss, 3e-3 * c.loss) << "C=" << c.params.c;
    ++checked;
  }
  EXPECT_EQ(checked, 6u);
  ASSERT_EQ(s.rescored.size(), kRescored);
  // The first rescored candidate is the search's best.
  EXPECT_EQ(s.rescored[0].params.c, std::pow(10.0, s.optimizer.best_point[0]));
  EXPECT_EQ(s.rescored[0].params.kernel, params_at(s.optimizer.best_point, o).kernel);
  double lowest_rescored = INFINITY;
  for (const Candidate& c : s.rescored) {
    EXPECT_NEAR(svr_loss(twice, c.params, all_rows), c.loss, 1e-12 * c.loss);
    lowest_rescored = std::min(lowest_rescored, c.loss);
  }
  EXPECT_EQ(s.best_fitness, lowest_rescored);
  // The same search without a stride sees the same landscape (the same losses to the solver's
  // tolerance), so it ends as low.
  const TuneSummary plain = tune_svr(twice, all_rows);
  EXPECT_EQ(plain.stride, 1u);
  EXPECT_TRUE(plain.rescored.empty());
  EXPECT_NEAR(s.best_fitness, plain.best_fitness, 1e-2 * plain.best_fitness);
}

TEST(TuneSvr, SearchesEpsilonWhenAsked) {
  const Dataset d = synthetic();
  TuneOptions o = small_search(opt::Algorithm::pso, nullptr);
  o.space.search_epsilon = true;
  const TuneSummary s = tune_svr(d, o);
  EXPECT_EQ(s.optimizer.best_point.size(), 3u);
  EXPECT_GE(s.best.epsilon, o.space.epsilon_min);
  EXPECT_LE(s.best.epsilon, o.space.epsilon_max * (1 + 1e-12));
}

TEST(TuneSvr, RejectsImpossibleOptions) {
  const Dataset d = synthetic();
  auto expect_option = [&](TuneOptions o, const std::string& option) {
    try {
      tune_svr(d, o);
      ADD_FAILURE() << "no error for " << option;
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), option) << e.what();
    }
  };
  TuneOptions o;
  o.space.c_min = 0;
  expect_option(o, "c_min");
  o = {};
  o.space.sigma_max = o.space.sigma_min;
  expect_option(o, "sigma_max");
  o = {};
  o.space.epsilon = -1;
  expect_option(o, "epsilon");
  o = {};
  o.tolerance = 0;
  expect_option(o, "tolerance");
  o = {};
  o.optimizer.run.population = 3;
  expect_option(o, "population");
  o = {};
  o.smo_iterations_per_row = kMaxSmoIterationsPerRow + 1;
  expect_option(o, "smo_iterations_per_row");
  for (const double r : {-1e-3, kMaxCandidateResolution * 1.5, static_cast<double>(NAN)}) {
    o = {};
    o.candidate_resolution = r;
    expect_option(o, "candidate_resolution");
  }
  EXPECT_THROW(parse_fitness("loo"), OptionError);
  EXPECT_EQ(parse_cv_scheme("recording"), CvScheme::recording);
  EXPECT_EQ(parse_cv_scheme("temperature"), CvScheme::temperature);
  EXPECT_THROW(parse_cv_scheme("temperatures"), OptionError);
}

}  // namespace
}  // namespace fogdrift::tune
