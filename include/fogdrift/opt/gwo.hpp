// Grey wolf optimizer: Mirjalili S., Mirjalili S. M., Lewis A., "Grey Wolf Optimizer",
// Advances in Engineering Software 69:46–61, 2014. Equation numbers are theirs.
//
// α, β, δ are the three best positions found so far. For every wolf and coordinate:
//   A = 2a·r1 − a,  C = 2·r2,  r1, r2 ~ U[0,1)                                 (eq. 3.3, 3.4)
//   D_k = |C_k·X_k − X|,  X_k' = X_k − A_k·D_k  for k = α, β, δ                (eq. 3.5, 3.6)
//   X ← (X_α' + X_β' + X_δ') / 3                                               (eq. 3.7)
// with a decreasing linearly from 2 to 0 over the iterations. Positions are clipped to the box.
#pragma once

#include "fogdrift/opt/problem.hpp"
#include "fogdrift/opt/summary.hpp"

namespace fogdrift::opt {

struct GwoOptions {
  double a_start = 2.0;  ///< a at the first iteration, > 0 (Mirjalili et al.: 2)
};

void validate(const GwoOptions& options);

/// Minimises the problem with GWO. Evaluations: n per iteration, initial population included.
Summary gwo(const Problem& problem, const RunOptions& run, const GwoOptions& options = {});

}  // namespace fogdrift::opt
