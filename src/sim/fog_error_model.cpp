#include "fogdrift/sim/fog_error_model.hpp"

#include <cmath>

namespace fogdrift::sim {

DriftTerms thermal_drift(const FogParams& f, double coil_mean_degc, double coil_mean_rate,
                         double gradient_rate, const HiddenState& hidden) {
  const double dt = coil_mean_degc - f.reference_temp_degc;
  DriftTerms d;
  d.static_dph =
      dt * (f.static_d1_dph_per_k + dt * (f.static_d2_dph_per_k2 + dt * f.static_d3_dph_per_k3));
  d.rate_dph = f.rate_r0_dph_per_kps * (1.0 + f.rate_r1_per_k * dt) * coil_mean_rate;
  d.shupe_dph = f.shupe_s0_dph_per_kps * (1.0 + dt * (f.shupe_s1_per_k + dt * f.shupe_s2_per_k2)) *
                gradient_rate;
  if (f.filtered_rate_dph_per_kps != 0.0)
    d.filtered_dph = f.filtered_rate_dph_per_kps * hidden.filtered_rate_k_per_s;
  if (f.electronics_dph_per_k != 0.0)
    d.electronics_dph = f.electronics_dph_per_k * (hidden.electronics_degc - f.reference_temp_degc);
  return d;
}

FogNoise::FogNoise(const FogParams& fog, std::uint64_t seed) : fog_(fog), rng_(seed) {
  gm_dph_ = fog_.bias_gm_sigma_dph * rng_.normal();  // start in the stationary distribution
}

double FogNoise::angle_increment_arcsec(double dt) {
  // ARW N (°/√h): the angle after t hours has σ = N·√t degrees = 60·N·√t_s arcseconds.
  const double arw = 60.0 * fog_.arw_deg_per_rth * std::sqrt(dt) * rng_.normal();
  const double phi = std::exp(-dt / fog_.bias_gm_tau_s);
  gm_dph_ = phi * gm_dph_ + fog_.bias_gm_sigma_dph * std::sqrt(1.0 - phi * phi) * rng_.normal();
  // RRW K (°/h/√h): the rate after t hours has σ = K·√t.
  rrw_dph_ += fog_.rrw_deg_per_h_rth * std::sqrt(dt / 3600.0) * rng_.normal();
  return arw + (gm_dph_ + rrw_dph_) * dt;
}

double FogNoise::quantize_arcsec(double angle_arcsec) {
  const double q = fog_.quantization_arcsec;
  if (q <= 0.0) return angle_arcsec;
  const double total = residual_arcsec_ + angle_arcsec;
  const double pulses = std::floor(total / q);
  residual_arcsec_ = total - pulses * q;
  return pulses * q;
}

}  // namespace fogdrift::sim
