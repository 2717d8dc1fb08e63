// The cross-validated choice of a GP's hyperparameters (gp_search.hpp): the scale it sets is the
// likelihood's maximum (a closed form), its fitness is the folds' RMSE as a direct computation
// gives it, and a seed gives the same model on one thread or several.
#include "fogdrift/train/gp_search.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "synthetic_dataset.hpp"

namespace fogdrift {
namespace {

std::vector<tune::ScaledSplit> splits_of(const Dataset& d) {
  std::vector<tune::ScaledSplit> out;
  for (const auto& f : tune::grouped_folds(d, {tune::CvScheme::recording, 3}))
    out.push_back(tune::scale_split(d, f.train_rows, f.test_rows));
  return out;
}

opt::OptimizerOptions budget(std::uint64_t seed) {
  opt::OptimizerOptions o;
  o.run.population = 8;
  o.run.iterations = 6;
  o.run.seed = seed;
  return o;
}

TEST(GpSearch, ScaleIsTheLikelihoodsMaximumAndFitnessTheFoldsRmse) {
  const Dataset d = test::synthetic();
  const auto splits = splits_of(d);
  const tune::ScaledSplit all = tune::scale_split(d, tune::grouped_folds(d).front().train_rows, {});
  GpOptions o;
  o.max_points = 120;
  const GpSearch s = search_gp(splits, all.train, o, budget(3));
  const GpHyper h = s.fit.posterior.gp.hyper;
  // eq. 7: at s² = yᵀ(E + λI)⁻¹y / n the likelihood's slope in log s², at fixed λ, is zero. With
  // σn² = λs² moving along, that slope is the sum of the gradient's s² and σn² components.
  const svr::Data kept = all.train.subset(gp_rows(all.train.rows, o.max_points));
  const GpLikelihood l = log_marginal_likelihood(kept, h, false);
  EXPECT_NEAR(l.gradient[0] + l.gradient[2], 0.0, 1e-8 * static_cast<double>(kept.rows));
  EXPECT_NEAR(s.fit.summary.log_likelihood, l.value, 1e-9 * std::abs(l.value));
  // The best fitness is the RMSE of that (ℓ, λ) over the folds, computed here directly.
  double sse = 0;
  std::size_t n = 0;
  for (const auto& sp : splits) {
    const svr::Data tr = sp.train.subset(gp_rows(sp.train.rows, o.max_points));
    const svr::Data te = sp.test.subset(gp_rows(sp.test.rows, o.max_points));
    const Gp gp = fit_gp(tr, {1.0, h.length_scale, h.noise_variance / h.signal_variance}).gp;
    for (std::size_t r = 0; r < te.rows; ++r) {
      const double e = gp.predict(te.row(r)) - te.y[r];
      sse += e * e;
    }
    n += te.rows;
  }
  EXPECT_NEAR(s.search.best_fitness, std::sqrt(sse / static_cast<double>(n)),
              1e-9 * s.search.best_fitness);
  EXPECT_EQ(s.fit.summary.points, kept.rows);
  // Inside the box, and better than a GP at the box's corner.
  EXPECT_GE(h.length_scale[0], o.box.length_min);
  EXPECT_LE(h.length_scale[0], o.box.length_max);
  EXPECT_LT(s.search.best_fitness, s.search.initial_best_fitness + 1e-12);
  // Racing: candidates that cannot win leave before their last fold.
  EXPECT_GT(s.fit.summary.raced, 0u);
  EXPECT_LT(s.fit.summary.fold_fits, splits.size() * s.search.evaluations);
  EXPECT_GE(s.fit.summary.fold_fits, s.search.evaluations);
}

TEST(GpSearch, OneSeedOneModelOnAnyThreadCount) {
  const Dataset d = test::synthetic(2);
  const auto splits = splits_of(d);
  const tune::ScaledSplit all = tune::scale_split(d, tune::grouped_folds(d).front().train_rows, {});
  GpOptions o;
  o.max_points = 100;
  const GpSearch serial = search_gp(splits, all.train, o, budget(4));
  ThreadPool pool(3);
  const GpSearch parallel = search_gp(splits, all.train, o, budget(4), &pool);
  EXPECT_EQ(to_json(serial.fit.posterior.gp), to_json(parallel.fit.posterior.gp));
  EXPECT_EQ(serial.search.best_fitness, parallel.search.best_fitness);
}

TEST(GpSearch, RefusesWhatItCannotSearch) {
  const Dataset d = test::synthetic();
  const auto splits = splits_of(d);
  GpOptions o;
  o.ard = true;  // one length scale per feature is the likelihood's
  EXPECT_THROW(search_gp(splits, splits.front().train, o, budget(1)), OptionError);
  o.ard = false;
  o.box.length_min = 30;  // above length_max
  EXPECT_THROW(search_gp(splits, splits.front().train, o, budget(1)), OptionError);
  EXPECT_THROW(search_gp({}, splits.front().train, GpOptions{}, budget(1)), OptionError);
  // A fold that holds nothing out.
  std::vector<tune::ScaledSplit> empty_fold = splits;
  empty_fold[1].test = {};
  EXPECT_THROW(search_gp(empty_fold, splits.front().train, GpOptions{}, budget(1)), OptionError);
  // A drift that is zero everywhere has no scale s² (eq. 7): an error, not a model of NaNs.
  svr::Data flat = splits.front().train;
  std::fill(flat.y.begin(), flat.y.end(), 0.0);
  std::vector<tune::ScaledSplit> flat_folds = splits;
  for (auto& f : flat_folds) std::fill(f.train.y.begin(), f.train.y.end(), 0.0);
  try {
    search_gp(flat_folds, flat, GpOptions{}, budget(1));
    ADD_FAILURE() << "a flat drift was accepted";
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("no positive scale"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fogdrift
