// Lumped thermal network of the NFS in a thermal chamber (docs/simulator.md §1).
//
// Six nodes — housing, electronics, outer and inner fiber-coil layers, accelerometer 1 and 2 —
// exchange heat through conductances; the chamber air drives the housing; power-on switches the
// heat sources on. For node k:
//
//   C_k dT_k/dt = Σ_j G_kj (T_j − T_k) + G_k,air (T_air − T_k) + P_k(powered, T_housing)
//
// The inner/outer coil split gives the radial gradient across the coil whose rate drives the
// Shupe term of the FOG error model (docs/method.md eq. 2–3).
#pragma once

#include <array>

#include "fogdrift/sim/instrument.hpp"

namespace fogdrift::sim {

using NodeTemps = std::array<double, kNodeCount>;  ///< °C, in Node order

class ThermalNetwork {
 public:
  explicit ThermalNetwork(const ThermalParams& params);

  /// dT/dt of every node, K/s, for node temperatures `temps_degc` and chamber air `air_degc`.
  NodeTemps derivative(const NodeTemps& temps_degc, double air_degc, bool powered) const;

  /// Advances `temps_degc` by `dt_s` with classical Runge–Kutta (4th order); the air temperature
  /// varies linearly from `air_start_degc` to `air_end_degc` over the step.
  void step(NodeTemps& temps_degc, double dt_s, double air_start_degc, double air_end_degc,
            bool powered) const;
  /// Same, with the caller's derivative(temps_degc, air_start_degc, powered) as the first stage.
  void step(NodeTemps& temps_degc, double dt_s, double air_start_degc, double air_end_degc,
            bool powered, const NodeTemps& first_stage) const;

  /// Steady state for constant air temperature: all nodes equal to the air with power off; with
  /// power on, the solution of the linear heat balance (iterated for the cooler's |ΔT| term).
  NodeTemps steady_state(double air_degc, bool powered) const;

  /// Total heat dissipated while powered at housing temperature `housing_degc`, W.
  double total_power_w(double housing_degc) const;

  /// The shortest time constant of the network, s (bounds a stable explicit step).
  double shortest_time_constant_s() const;

 private:
  NodeTemps powers_w(double housing_degc, bool powered) const;

  ThermalParams p_;
  // Symmetric conductance matrix between nodes, W/K, and to air.
  std::array<std::array<double, kNodeCount>, kNodeCount> g_{};
  NodeTemps g_air_{};
};

}  // namespace fogdrift::sim
