#include "fogdrift/opt/optimizer.hpp"

namespace fogdrift::opt {

Summary minimize(const Problem& problem, const OptimizerOptions& options) {
  switch (options.algorithm) {
    case Algorithm::pso:
      return pso(problem, options.run, options.pso);
    case Algorithm::gwo:
      return gwo(problem, options.run, options.gwo);
    case Algorithm::ssa:
      break;
  }
  return ssa(problem, options.run, options.ssa);
}

}  // namespace fogdrift::opt
