// Sparrow search algorithm (SSA): Xue J., Shen B., "A novel swarm intelligence optimization
// approach: sparrow search algorithm", Systems Science & Control Engineering 8(1):22–34, 2020.
// The 2024 compensation paper restates it as its eq. (8)–(10) (docs/method.md §2 step 4); equation
// numbers below are Xue & Shen's: producers eq. (3), scroungers eq. (4), scouts eq. (5).
//
// Each iteration, with the population sorted by the fitness of each sparrow's remembered (best)
// position, rank i = 1 … n:
//   R2 ~ U[0,1) once per iteration (the alarm value, as in Xue & Shen's Algorithm 1).
//   Producers, the first PD·n ranks (eq. 3):
//     R2 <  ST:  x ← x·exp(−i / (α·iter_max)),  α ~ U(0,1] per producer
//     R2 ≥ ST:  x ← x + Q·L,                    Q ~ N(0,1) per producer, L a row of ones
//   The producers' new positions are evaluated; x_P is the best of them.
//   Scroungers, the other ranks (eq. 4), with x_worst the worst remembered position:
//     i > n/2:   x ← Q·exp((x_worst − x) / i²)  (element-wise)
//     otherwise: x ← x_P + |x − x_P|·A⁺·L, A a row of random ±1, A⁺ = Aᵀ(AAᵀ)⁻¹ = Aᵀ/d,
//                so every coordinate moves by the same (Σ_j A_j·|x_j − x_P,j|)/d
//   The scroungers' new positions are evaluated; the global best x_g, f_g is updated.
//   Scouts, SD·n sparrows drawn at random without replacement from the whole flock, moved from
//   their new positions with their new fitness f_i (eq. 5):
//     f_i > f_g:  x ← x_g + β·|x − x_g|,                 β ~ N(0,1) per coordinate
//     f_i = f_g:  x ← x + K·|x − x_worst| / ((f_i − f_w) + ε),  K ~ U[−1,1], ε = 1e-50
//   (f_w the worst new fitness). The scouts are evaluated; every sparrow keeps its new position
//   as its remembered one only if it is better ("if the new location is better than before,
//   update it", Algorithm 1).
// Every move is clipped to the bounds. Choices Xue & Shen leave open are the ones stated above;
// docs/tuning.md lists them and where widely used public implementations differ.
//
// Note: eq. (3)'s first branch contracts a producer towards the coordinate origin, so SSA is not
// shift-invariant. In fogdrift's tuning coordinates (log10 C, log10 σ) the origin is C = σ = 1.
#pragma once

#include "fogdrift/opt/problem.hpp"
#include "fogdrift/opt/summary.hpp"

namespace fogdrift::opt {

struct SsaOptions {
  double producer_fraction = 0.2;  ///< PD: share of producers, (0, 1); at least one producer
  double scout_fraction = 0.1;     ///< SD: share of scouts, (0, 1]; at least one scout
  double safety_threshold = 0.8;   ///< ST ∈ [0.5, 1]: producers search widely while R2 < ST
};

/// Throws OptionError naming the field for a value outside its range.
void validate(const SsaOptions& options);

/// Minimises the problem with SSA. Evaluations: n initial, then n + scouts per iteration.
Summary ssa(const Problem& problem, const RunOptions& run, const SsaOptions& options = {});

}  // namespace fogdrift::opt
