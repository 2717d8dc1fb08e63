#include "fogdrift/train/gp_search.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"

namespace fogdrift {
namespace {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

double gp_squared_distance(const double* a, const double* b, std::size_t d) {
  double acc = 0;
  for (std::size_t k = 0; k < d; ++k) acc += (a[k] - b[k]) * (a[k] - b[k]);
  return acc;
}

// One fold, computed once for every candidate: the squared distances among the training rows
// kept and from the held-out rows kept to them.
struct FoldDistances {
  Matrix train;  // n × n
  Matrix cross;  // m × n
  Eigen::VectorXd y_train, y_test;

  FoldDistances(const Data& tr, const Data& te, std::size_t max_points) {
    const Data a = tr.subset(gp_rows(tr.rows, max_points));
    const Data b = te.subset(gp_rows(te.rows, max_points));
    const auto n = static_cast<Eigen::Index>(a.rows), m = static_cast<Eigen::Index>(b.rows);
    train.resize(n, n);
    cross.resize(m, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j <= i; ++j)
        train(i, j) = train(j, i) = gp_squared_distance(a.row(static_cast<std::size_t>(i)),
                                                        a.row(static_cast<std::size_t>(j)), a.cols);
    for (Eigen::Index i = 0; i < m; ++i)
      for (Eigen::Index j = 0; j < n; ++j)
        cross(i, j) = gp_squared_distance(b.row(static_cast<std::size_t>(i)),
                                          a.row(static_cast<std::size_t>(j)), a.cols);
    y_train = Eigen::Map<const Eigen::VectorXd>(a.y.data(), n);
    y_test = Eigen::Map<const Eigen::VectorXd>(b.y.data(), m);
  }

  // The sum of squared held-out errors of the GP (ℓ, λ); NaN when E + λI cannot be factored.
  double sse(double length, double ratio) const {
    const double scale = -0.5 / (length * length);
    Matrix e = (train.array() * scale).exp().matrix();
    e.diagonal().array() += ratio;
    const Eigen::LLT<Matrix> llt(e);
    if (llt.info() != Eigen::Success) return std::numeric_limits<double>::quiet_NaN();
    const Eigen::VectorXd a = llt.solve(y_train);
    const Eigen::VectorXd predicted = (cross.array() * scale).exp().matrix() * a;
    return (predicted - y_test).squaredNorm();
  }
};

}  // namespace

GpSearch search_gp(std::span<const tune::ScaledSplit> splits, const Data& all,
                   const GpOptions& options, const opt::OptimizerOptions& optimizer,
                   ThreadPool* pool) {
  validate(options);
  if (splits.empty()) throw OptionError("cv", "the search needs at least one fold");
  std::vector<FoldDistances> folds;
  std::size_t held = 0;
  for (const auto& s : splits) {
    if (s.train.rows == 0 || s.test.rows == 0)
      throw OptionError("cv", "a fold has no training or no held-out rows");
    folds.emplace_back(s.train, s.test, options.max_points);
    held += static_cast<std::size_t>(folds.back().y_test.size());
  }
  const GpSearchBox& box = options.box;
  // Racing: a candidate whose squared errors on the folds fitted so far already exceed the best
  // complete candidate's over every fold cannot be chosen; it leaves after that fold, with the
  // RMSE of its errors so far, a lower bound of its own above the best's. The bound is the best
  // of the batches before, so a batch's fitness does not depend on the order its points run in.
  double bound_sse = std::numeric_limits<double>::infinity();
  std::size_t raced = 0, fold_fits = 0;
  opt::Problem problem;
  problem.lower = {std::log10(box.length_min), std::log10(box.ratio_min)};
  problem.upper = {std::log10(box.length_max), std::log10(box.ratio_max)};
  problem.evaluate = [&](std::span<const double> points, std::span<double> fitness) {
    std::vector<std::size_t> fitted(fitness.size(), 0);
    std::vector<bool> complete(fitness.size(), true);
    auto one = [&](std::size_t i) {
      const double length = std::pow(10.0, points[2 * i]),
                   ratio = std::pow(10.0, points[2 * i + 1]);
      double sse = 0;
      for (const auto& f : folds) {
        sse += f.sse(length, ratio);
        ++fitted[i];
        if (sse > bound_sse && fitted[i] < folds.size()) {
          complete[i] = false;
          break;
        }
      }
      fitness[i] = std::sqrt(sse / static_cast<double>(held));
    };
    if (pool)
      pool->parallel_for(fitness.size(), one);
    else
      for (std::size_t i = 0; i < fitness.size(); ++i) one(i);
    for (std::size_t i = 0; i < fitness.size(); ++i) {
      fold_fits += fitted[i];
      if (!complete[i]) ++raced;
      const double sse = fitness[i] * fitness[i] * static_cast<double>(held);
      if (complete[i] && sse < bound_sse) bound_sse = sse;  // NaN never lowers it
    }
  };
  GpSearch out;
  out.search = opt::minimize(problem, optimizer);
  const double length = std::pow(10.0, out.search.best_point[0]);
  const double ratio = std::pow(10.0, out.search.best_point[1]);
  // The scale by eq. 7 on the rows the model keeps, then the GP of (s², ℓ, λ s²).
  const std::vector<std::size_t> kept_rows = gp_rows(all.rows, options.max_points);
  const Data kept = all.subset(kept_rows);
  GpHyper unit{1.0, std::vector<double>(all.cols, length), ratio};
  const GpPosterior correlation = fit_gp(kept, unit);  // α' = (E + λI)⁻¹ y
  double y_alpha = 0;
  for (std::size_t i = 0; i < kept.rows; ++i) y_alpha += kept.y[i] * correlation.gp.alpha[i];
  const double s2 = y_alpha / static_cast<double>(kept.rows);
  if (!(s2 > 0) || !std::isfinite(s2))
    throw OptionError("gp",
                      fmt::format("the chosen GP has no positive scale (yᵀα' = {:.3g})", y_alpha));
  const GpHyper hyper{s2, std::vector<double>(all.cols, length), ratio * s2};
  out.fit.posterior = fit_gp(kept, hyper);
  out.fit.summary.points = kept.rows;
  out.fit.summary.log_likelihood = out.fit.posterior.log_likelihood(kept.y);
  out.fit.summary.iterations = out.search.iterations;
  out.fit.summary.evaluations = out.search.evaluations;
  out.fit.summary.converged = true;
  out.fit.summary.raced = raced;
  out.fit.summary.fold_fits = fold_fits;
  return out;
}

}  // namespace fogdrift
