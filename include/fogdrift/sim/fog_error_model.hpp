// FOG error model: thermal drift in the IEEE Std 952 form and the stochastic Allan terms
// (docs/simulator.md §2).
//
//   drift = B(T̄) + D_Ṫ(T̄)·dT̄/dt + D_∇(T̄)·d(T_in − T_out)/dt            (docs/method.md eq. 3)
//   B(T̄)  = d1·ΔT + d2·ΔT² + d3·ΔT³,  D_Ṫ = r0(1 + r1·ΔT),  D_∇ = s0(1 + s1·ΔT + s2·ΔT²)
//
// with T̄ the mean coil temperature and ΔT = T̄ − T_ref. The last term is the Shupe
// non-reciprocity (docs/method.md eq. 2) of a coil heated asymmetrically from its hub. Because
// every coefficient depends on T̄, the start-up shape differs at each initial temperature.
#pragma once

#include <cstdint>

#include "fogdrift/base/random.hpp"
#include "fogdrift/sim/instrument.hpp"

namespace fogdrift::sim {

struct DriftTerms {
  double static_dph = 0;  ///< B(T̄)
  double rate_dph = 0;    ///< D_Ṫ·dT̄/dt
  double shupe_dph = 0;   ///< D_∇·d(T_in − T_out)/dt
  /// Terms outside the paper's form (FogParams): F·ds/dt and e1·(T_electronics − T_ref).
  double filtered_dph = 0;
  double electronics_dph = 0;
  double total_dph() const {
    return static_dph + rate_dph + shupe_dph + filtered_dph + electronics_dph;
  }
};

/// The state the terms outside the paper's form read, beyond the coil: the filtered coil mean
/// s's rate, K/s, and the electronics node's temperature, °C.
struct HiddenState {
  double filtered_rate_k_per_s = 0;
  double electronics_degc = 0;
};

/// The thermal drift for coil mean temperature `coil_mean_degc`, its rate `coil_mean_rate_k_per_s`
/// and the rate of the inner-minus-outer coil gradient `gradient_rate_k_per_s`.
/// `hidden` feeds the terms outside the paper's form; they are 0 when their coefficients are.
DriftTerms thermal_drift(const FogParams& fog, double coil_mean_degc, double coil_mean_rate_k_per_s,
                         double gradient_rate_k_per_s, const HiddenState& hidden = {});

/// Stochastic part of the FOG output, integrated at the fine step: angle random walk (white rate
/// noise), bias instability (first-order Gauss–Markov), rate random walk, plus the quantiser of
/// the output angle. Angles are in arcseconds (1 °/h × 1 s = 1″).
class FogNoise {
 public:
  FogNoise(const FogParams& fog, std::uint64_t seed);

  /// Noise angle increment over one fine step `dt_s`, ″: ARW plus the (GM + RRW) rate times dt.
  double angle_increment_arcsec(double dt_s);

  /// Feeds the true angle increment of an output interval; returns the quantised increment, ″.
  /// The residual below one quantum is carried to the next interval, as a pulse counter does.
  double quantize_arcsec(double angle_arcsec);

 private:
  FogParams fog_;
  Rng rng_;
  double gm_dph_ = 0;   // Gauss–Markov bias state
  double rrw_dph_ = 0;  // random-walk bias state
  double residual_arcsec_ = 0;
};

}  // namespace fogdrift::sim
