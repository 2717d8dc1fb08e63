// A grid search over folds by warm-started C paths (grid_search.hpp).
#include "fogdrift/svr/grid_search.hpp"

#include <algorithm>
#include <memory>
#include <numeric>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"

namespace fogdrift::svr {

GridSearchResult grid_search(
    const Data& data, std::span<const GridFold> folds, std::size_t kernels,
    const std::function<Params(const Data& training_rows, std::size_t kernel)>& params_of,
    std::span<const double> c_values, bool predict, ThreadPool& pool, WorkspacePool& workspaces) {
  validate_c_values(c_values);
  if (kernels == 0 || folds.empty())
    throw OptionError("folds", "a grid search needs a kernel and a fold");
  for (const GridFold& f : folds)
    for (const auto* rows : {&f.train, &f.test, &f.predict})
      for (const std::size_t r : *rows)
        if (r >= data.rows) throw OptionError("folds", "a fold's row index is out of range");
  const std::size_t nf = folds.size(), nc = c_values.size();
  // C in ascending order along each path: warm starts go from small C to large.
  std::vector<std::size_t> by_c(nc);
  std::iota(by_c.begin(), by_c.end(), std::size_t{0});
  std::stable_sort(by_c.begin(), by_c.end(),
                   [&](std::size_t a, std::size_t b) { return c_values[a] < c_values[b]; });
  std::vector<double> ascending(nc);
  for (std::size_t k = 0; k < nc; ++k) ascending[k] = c_values[by_c[k]];

  GridSearchResult out;
  out.kernels = kernels;
  out.c_values = nc;
  out.folds = nf;
  if (predict) {
    out.predictions.resize(nf);
    for (std::size_t f = 0; f < nf; ++f)
      out.predictions[f].resize(kernels * nc * folds[f].predict.size());
  } else {
    out.sse.assign(kernels * nc * nf, 0.0);
  }
  std::vector<std::unique_ptr<TrainingSet>> sets(nf);
  std::vector<std::vector<Params>> params(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    sets[f] = std::make_unique<TrainingSet>(data.subset(folds[f].train));
    for (std::size_t k = 0; k < kernels; ++k) params[f].push_back(params_of(sets[f]->data(), k));
  }
  pool.parallel_for(nf * kernels, [&](std::size_t task) {
    const std::size_t f = task / kernels, k = task % kernels;
    const WorkspacePool::Lease workspace = workspaces.borrow();
    const std::vector<FitResult> path =
        fit_c_path(*sets[f], params[f][k], ascending, workspace.get());
    if (predict) {
      const std::vector<double> p = path_predictions(*sets[f], path, data, folds[f].predict);
      const std::size_t n = folds[f].predict.size();
      for (std::size_t r = 0; r < n; ++r)
        for (std::size_t c = 0; c < nc; ++c)
          out.predictions[f][(k * nc + by_c[c]) * n + r] = p[r * nc + c];
      return;
    }
    const std::vector<double> errors = path_squared_errors(*sets[f], path, data, folds[f].test);
    for (std::size_t c = 0; c < nc; ++c) out.sse[(k * nc + by_c[c]) * nf + f] = errors[c];
  });
  return out;
}

}  // namespace fogdrift::svr
