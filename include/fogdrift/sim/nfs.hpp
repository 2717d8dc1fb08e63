// The north-finding system in its chamber, advanced in time: thermal network, thermometers, FOG,
// accelerometers and turntable together (docs/simulator.md). Scenarios (scenarios.hpp) drive it.
#pragma once

#include <cstdint>
#include <functional>

#include "fogdrift/io/recording.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/thermal_network.hpp"
#include "fogdrift/sim/turntable.hpp"

namespace fogdrift::sim {

/// Chamber air temperature, °C, as a function of the simulator's absolute time, s.
using AirProfile = std::function<double(double time_s)>;

/// What one powered recording looks like.
struct RecordSetup {
  double duration_s = 1800.0;   ///< powered time recorded, s (a whole number of samples)
  double output_rate_hz = 1.0;  ///< logger rate, Hz; 1/rate must be a multiple of fine_step_s
  double latitude_deg = 30.0;   ///< site latitude, °
  Platform platform{0.0, 0.0, 0.0};
  TurntableSchedule table;       ///< times relative to the start of the recording
  std::uint64_t seed = 1;        ///< noise of this recording (FOG, thermometers, accelerometers)
  bool write_true_drift = true;  ///< add the simulator's ground truth column drift_true_dph
};

class NfsSimulator {
 public:
  /// Starts at absolute time `time_s` with every node at `initial_degc`.
  NfsSimulator(const Instrument& instrument, const NodeTemps& initial_degc, double time_s = 0.0);

  /// Advances the thermal state only (nothing is logged), powered or not, at the fine step.
  void advance(double duration_s, const AirProfile& air, bool powered);

  /// Records `setup.duration_s` of powered operation from now. Time stamps in the recording are
  /// seconds since `power_on_time_s` (absolute); each sample is the mean rate over the interval
  /// that ends at its stamp, and the thermometers and accelerometers are read at the stamp.
  Recording record(const RecordSetup& setup, const AirProfile& air, double power_on_time_s);

  double time_s() const { return time_s_; }
  /// Sets the absolute clock to `time_s` and keeps every state: the nodes, the thermometers'
  /// lags and the filtered coil mean. A start-up's history is simulated on its own clock, then
  /// recorded with the clock at 0 at power-on, from the state that history left.
  void restart_clock(double time_s) { time_s_ = time_s; }
  const NodeTemps& temps_degc() const { return temps_; }

 private:
  /// One fine step; `rate` is the network's derivative at the current state when the caller
  /// already has it (it is the first Runge–Kutta stage), or null.
  void step(double dt_s, const AirProfile& air, bool powered, const NodeTemps* rate = nullptr);
  /// What thermometer 0 (fog), 1 (acc1) or 2 (acc2) senses before its lag: its node, mixed
  /// with the housing by its placement (ThermometerParams::housing_share).
  double read_node(int thermometer) const;

  Instrument instrument_;
  ThermalNetwork network_;
  NodeTemps temps_;
  std::array<double, 3> thermometer_state_degc_;  // fog, acc1, acc2 after their lags
  double filtered_coil_degc_;  // the coil mean low-passed with fog.filtered_rate_tau_s
  // 1 − exp(−dt/τ) of the three thermometers' lags and of the filter, for the step lag_dt_s_.
  std::array<double, 4> lag_gain_{};
  double lag_dt_s_ = -1.0;
  double time_s_;
};

}  // namespace fogdrift::sim
