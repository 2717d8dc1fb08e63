// Any of fogdrift's optimizers by name, for callers (the tuner, the CLI) that let users choose.
#pragma once

#include "fogdrift/opt/gwo.hpp"
#include "fogdrift/opt/pso.hpp"
#include "fogdrift/opt/ssa.hpp"

namespace fogdrift::opt {

struct OptimizerOptions {
  Algorithm algorithm = Algorithm::ssa;
  RunOptions run;
  SsaOptions ssa;
  PsoOptions pso;
  GwoOptions gwo;
};

/// Validates the options and runs the chosen algorithm.
Summary minimize(const Problem& problem, const OptimizerOptions& options);

}  // namespace fogdrift::opt
