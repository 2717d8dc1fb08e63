// The ε-SVR's trainer (trainer.hpp; docs/method.md §2, §3): C and σ tuned by a search over the
// grouped folds (tune.hpp) and the SVR refitted on every training row, or, with no search,
// LIBSVM's defaults on standardised data (C = 1, γ = 1/features, ε = 0.1) or the parameters a
// study gives (its Options::params).
#pragma once

#include <array>
#include <optional>

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

}  // namespace fogdrift
