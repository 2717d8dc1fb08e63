#include "fogdrift/gp_search.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>

#include "fogdrift/error.hpp"

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

  FoldDistances(const svr::Data& tr, const svr::Data& te, std::size_t max_points) {
    const svr::Data a = tr.subset(gp_rows(tr.rows, max_points));
    const svr::Data b = te.subset(gp_rows(te.rows, max_points));
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

GpSearch search_gp(std::span<const tune::ScaledSplit> splits, const svr::Data& all,
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
  const opt::Problem problem = opt::Problem::from_function(
      {std::log10(box.length_min), std::log10(box.ratio_min)},
      {std::log10(box.length_max), std::log10(box.ratio_max)},
      [&](std::span<const double> p) {
        double sse = 0;
        for (const auto& f : folds) sse += f.sse(std::pow(10.0, p[0]), std::pow(10.0, p[1]));
        return std::sqrt(sse / static_cast<double>(held));
      },
      pool);
  GpSearch out;
  out.search = opt::minimize(problem, optimizer);
  const double length = std::pow(10.0, out.search.best_point[0]);
  const double ratio = std::pow(10.0, out.search.best_point[1]);
  // The scale by eq. 7 on the rows the model keeps, then the GP of (s², ℓ, λ s²).
  const std::vector<std::size_t> kept_rows = gp_rows(all.rows, options.max_points);
  const svr::Data kept = all.subset(kept_rows);
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
  out.fit.summary.log_likelihood = log_marginal_likelihood(kept, hyper, false).value;
  out.fit.summary.iterations = out.search.iterations;
  out.fit.summary.evaluations = out.search.evaluations;
  out.fit.summary.converged = true;
  return out;
}

}  // namespace fogdrift
