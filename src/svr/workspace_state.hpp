// What a Workspace (fogdrift/svr/workspace.hpp) holds between fits. Internal header: not
// installed.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "fogdrift/svr/kernel.hpp"
#include "fogdrift/svr/workspace.hpp"
#include "svr/rows.hpp"

namespace fogdrift::svr::detail {

struct WorkspaceState {
  /// Row blocks of the last fit, for the next one's KernelCache and OrderedRows.
  KeptBlocks blocks;
  /// The pair solver's per-sample arrays, grown to the largest fit so far.
  std::vector<double> values;
  std::vector<std::uint8_t> flags;
  /// The sample order and rows the last pair-solver fit on `order_cache` left for the next fit
  /// on that cache; the cache drops them when it ends (its rows are theirs).
  const KernelCache* order_cache = nullptr;
  std::unique_ptr<SampleOrder> order;  // after `blocks`: its rows go back to them first

  /// Takes the order left on `cache`, or null when none is.
  std::unique_ptr<SampleOrder> take_order(const KernelCache& cache) {
    if (order_cache != &cache) return nullptr;
    order_cache = nullptr;
    return std::move(order);
  }
  /// Drops any order left on `cache` (before that cache ends).
  void forget(const KernelCache& cache) {
    if (order_cache != &cache) return;
    order.reset();
    order_cache = nullptr;
  }
};

}  // namespace fogdrift::svr::detail
