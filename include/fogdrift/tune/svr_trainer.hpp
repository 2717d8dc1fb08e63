// The ε-SVR's trainer (trainer.hpp; docs/method.md §2, §3): C and σ tuned by a search over the
// grouped folds (tune.hpp) and the SVR refitted on every training row, or, with no search,
// LIBSVM's defaults on standardised data (C = 1, γ = 1/features, ε = 0.1) or the parameters a
// study gives (TrainOptions::svr_params).
#pragma once

#include <array>

#include "fogdrift/tune/trainer.hpp"

namespace fogdrift {

struct SvrTrainer {
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
