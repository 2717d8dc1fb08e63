// Overlapping Allan deviation of a rate signal and the three noise terms a gyro datasheet
// quotes (IEEE Std 952-1997 Annex C; IEEE Std 1554-2005).
//
// With the angle θ_k = Σ_{i<k} ω_i·Δt (θ_0 = 0), N rate samples and cluster time τ = m·Δt,
//   σ²(τ) = Σ_{k=0}^{N−2m} (θ_{k+2m} − 2θ_{k+m} + θ_k)² / (2τ²·(N − 2m + 1))
// the fully overlapping estimator (σ in the rate's unit, here °/h). Slopes on log-log axes:
//   angle random walk   σ = N/√τ             (slope −½; N read at τ = 1 h, °/√h)
//   bias instability    σ_min ≈ 0.664·B      (slope 0; B = σ_min/0.664, °/h)
//   rate random walk    σ = K·√(τ/3)         (slope +½; K read at τ = 3 h, °/h/√h)
// N and K are read by passing a line of exactly the term's slope through the points whose local
// log-log slope is within 0.05 of it (weighted towards short clusters, which are better
// determined; the point of closest slope if none is that close). B is the curve's minimum
// divided by 0.664. Each reading assumes the terms are well separated along τ; where they
// overlap, N and K come out high and B slightly high.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace fogdrift::eval {

struct AllanDeviation {
  std::vector<double> tau_s;
  std::vector<double> adev;    ///< same unit as the rate (°/h)
  std::vector<std::size_t> m;  ///< samples per cluster
};

/// σ(τ) at τ = m·Δt for m = 1, 2, 4, … up to N/2 (octave spacing) or, with
/// `points_per_decade` > 0, about that many log-spaced m per decade. Throws OptionError for
/// Δt ≤ 0 or fewer than 4 samples; the caller checks that the rate is finite.
AllanDeviation allan_deviation(std::span<const double> rate, double dt_s,
                               std::size_t points_per_decade = 0);

struct NoiseTerms {
  double arw_deg_per_rt_h = 0;                                      ///< angle random walk N
  double bias_instability_dph = 0;                                  ///< B
  double rrw_dph_per_rt_h = 0;                                      ///< rate random walk K
  double arw_tau_s = 0, bias_instability_tau_s = 0, rrw_tau_s = 0;  ///< where each was read
};

/// Reads N, B and K off the curve (rate in °/h).
NoiseTerms noise_terms(const AllanDeviation& curve);

}  // namespace fogdrift::eval
