// The ε-SVR's trainer (trainer.hpp; docs/method.md §2, §3): C and σ tuned by a search over the
// grouped folds (tune.hpp) and the SVR refitted on every training row, or, with no search,
// LIBSVM's defaults on standardised data (C = 1, γ = 1/features, ε = 0.1) or the parameters a
// study gives (its Options::params).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/svr/svr.hpp"
#include "fogdrift/train/trainer.hpp"

namespace fogdrift {

struct SvrTrainer {
  using Regressor = svr::Model;  ///< what it fits
  /// Its search's box and budget are train's (TrainOptions::tune), which fogdrift paper shares.
  struct Options {
    /// Without a search, fit with these instead of LIBSVM's defaults (a study refitting a tuned
    /// SVR on other rows); the tolerance and cache are still tune's.
    std::optional<svr::Params> params;
  };
  /// Its part of the summary (trainer_record.hpp), for a searched SVR; none without a search.
  struct Record {
    tune::TuneSummary tuning;  ///< the last search (the widest box, with auto-box)
    std::size_t population = 0;
    /// The boxes searched, in order (more than one with auto-box), and the edges the last
    /// search's best lies on.
    std::vector<tune::SearchSpace> boxes;
    std::vector<tune::BoxEdge> box_edges;
  };
  /// None: a study's parameters are set in code.
  static OptionTable<Options> option_table() { return {}; }
  static constexpr std::string_view kName = "svr";
  static constexpr std::array<MethodName, 4> kMethods = {{
      {"ssa-svr", Search::ssa, "an ε-SVR with C and σ tuned by sparrow search (the paper's)"},
      {"pso-svr", Search::pso, "an ε-SVR with C and σ tuned by particle swarm"},
      {"gwo-svr", Search::gwo, "an ε-SVR with C and σ tuned by grey wolf"},
      {"svr", Search::own,
       "an ε-SVR with LIBSVM's defaults (C = 1, γ = 1/features, ε = 0.1), or tuned by the "
       "search {search} names (svr with {search} ssa is ssa-svr)"},
  }};
  /// own and none: no search; ssa, pso, gwo: that one.
  static Search search(Search requested, const TrainOptions& options);
  /// A searched SVR's box, budget and folds (tune::validate).
  static void validate(const TrainOptions& options);
  static Trained train(const TrainContext& context);
};

/// {"search": {optimizer, population, iterations, status, …}, "box_edges": […],
/// "boxes_searched": […], "fits": N}.
nlohmann::ordered_json to_json(const SvrTrainer::Record& record);

/// One warning for each best value of a searched SVR on the edge of its box (its record's
/// box_edges; none for another method): the box, not the data, may have stopped the search.
/// The advice names what the user sets, in their own words: `name_of` turns a field (c_min,
/// c_max, sigma_min, sigma_max, search_epsilon, auto_box) into a flag (--c-max) or a keyword
/// (c_max); `auto_box` says whether the box was widened already.
std::vector<std::string> box_edge_warnings(
    const TrainSummary& summary, bool auto_box,
    const std::function<std::string(const std::string&)>& name_of);

}  // namespace fogdrift
