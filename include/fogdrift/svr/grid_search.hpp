// A grid search's fits over folds the caller gives (docs/svr.md, "Searches on folds"): for each
// fold and kernel, one warm-started path over C in ascending order on the fold's training rows,
// every model of it scored on the fold's test rows by its sum of squared errors, or its predictions
// at rows the caller names (for any other scorer). The (fold, kernel) paths are path tasks of
// the engine every search runs on (fold_paths.hpp), in parallel, each with a workspace from the
// caller's pool; results do not depend on the thread count.
// fogdrift.SVRGridSearchCV runs on it (python/src/svr_bindings.cpp).
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "fogdrift/svr/svr.hpp"
#include "fogdrift/svr/workspace.hpp"

namespace fogdrift {
class ThreadPool;
}

namespace fogdrift::svr {

/// One fold: indices into the data of its training and test rows, and the rows to predict at
/// (used only when the search asks for predictions).
struct GridFold {
  std::vector<std::size_t> train, test, predict;
};

struct GridSearchResult {
  std::size_t kernels = 0, c_values = 0, folds = 0;
  /// Σ (f(x) − y)² over each fold's test rows, [kernel][c][fold], C in the order given; empty
  /// when predictions were asked for.
  std::vector<double> sse;
  /// Per fold, f(x) at its predict rows, [kernel][c][row]; empty unless asked for.
  std::vector<std::vector<double>> predictions;

  double sse_at(std::size_t kernel, std::size_t c, std::size_t fold) const {
    return sse[(kernel * c_values + c) * folds + fold];
  }
};

/// Every (kernel, C, fold). `params_of(training rows, k)` gives kernel k's parameters for a
/// fold (a γ such as scikit-learn's 'scale' depends on the fold's rows); their C is replaced by
/// each of `c_values` (any order, each > 0). `predict`: return predictions, not SSE.
GridSearchResult grid_search(
    const Data& data, std::span<const GridFold> folds, std::size_t kernels,
    const std::function<Params(const Data& training_rows, std::size_t kernel)>& params_of,
    std::span<const double> c_values, bool predict, ThreadPool& pool, WorkspacePool& workspaces);

}  // namespace fogdrift::svr
