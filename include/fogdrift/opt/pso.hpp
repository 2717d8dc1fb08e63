// Particle swarm optimisation with inertia weight: Shi Y., Eberhart R., "A modified particle
// swarm optimizer", IEEE ICEC 1998, pp. 69–73 (global-best topology of Kennedy & Eberhart 1995).
//
//   v ← w·v + c1·r1·(p − x) + c2·r2·(g − x)     r1, r2 ~ U[0,1) per coordinate   (S&E eq. 1)
//   x ← x + v                                                                     (S&E eq. 2)
// p is the particle's best position, g the swarm's. The inertia w falls linearly from
// w_start at the first iteration to w_end at the last (the schedule Shi & Eberhart recommend,
// 0.9 → 0.4). Velocities are clamped to ±v_max = max_velocity_fraction·(upper − lower) per
// coordinate; a particle leaving the box is put on the bound and that velocity component zeroed.
// Initial velocities are uniform in ±v_max.
#pragma once

#include "fogdrift/opt/problem.hpp"
#include "fogdrift/opt/summary.hpp"

namespace fogdrift::opt {

struct PsoOptions {
  double inertia_start = 0.9;          ///< w at the first iteration, ≥ 0
  double inertia_end = 0.4;            ///< w at the last iteration, ≥ 0
  double cognitive = 2.0;              ///< c1 ≥ 0, pull towards the particle's best
  double social = 2.0;                 ///< c2 ≥ 0, pull towards the swarm's best
  double max_velocity_fraction = 0.2;  ///< v_max as a share of each coordinate's range, (0, 1]
};

void validate(const PsoOptions& options);

/// Minimises the problem with PSO. Evaluations: n per iteration, initial population included.
Summary pso(const Problem& problem, const RunOptions& run, const PsoOptions& options = {});

}  // namespace fogdrift::opt
