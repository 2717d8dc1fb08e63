// A grid search over folds by warm-started C paths (grid_search.hpp).
#include "fogdrift/svr/grid_search.hpp"

#include <algorithm>
#include <memory>
#include <numeric>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/fold_paths.hpp"

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
  // One path task per (fold, kernel), the whole C axis (fold_paths.hpp).
  std::vector<std::unique_ptr<TrainingSet>> sets(nf);
  std::vector<ScoringFold> scoring(nf);
  std::vector<PathTask> tasks;
  for (std::size_t f = 0; f < nf; ++f) {
    sets[f] = std::make_unique<TrainingSet>(data.subset(folds[f].train));
    scoring[f] = {sets[f].get(), &data, folds[f].test, folds[f].predict};
    for (std::size_t k = 0; k < kernels; ++k) {
      PathTask& t = tasks.emplace_back();
      t.fold = f;
      t.params = params_of(sets[f]->data(), k);
      t.c_values = ascending;
      t.predict = predict;
    }
  }
  const std::vector<PathScores> scores = run_paths(scoring, tasks, &pool, workspaces);
  for (std::size_t f = 0; f < nf; ++f) {
    for (std::size_t k = 0; k < kernels; ++k) {
      const PathScores& path = scores[f * kernels + k];
      if (predict) {
        const std::size_t n = folds[f].predict.size();
        for (std::size_t r = 0; r < n; ++r)
          for (std::size_t c = 0; c < nc; ++c)
            out.predictions[f][(k * nc + by_c[c]) * n + r] = path.predictions[r * nc + c];
      } else {
        for (std::size_t c = 0; c < nc; ++c) out.sse[(k * nc + by_c[c]) * nf + f] = path.sse[c];
      }
    }
  }
  return out;
}

}  // namespace fogdrift::svr
