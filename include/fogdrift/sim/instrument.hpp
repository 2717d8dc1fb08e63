// Parameters of a simulated north-finding system (NFS): thermal network, thermometers, FOG error
// model, accelerometers and turntable. Equations and a parameter table are in docs/simulator.md.
//
// Every parameter is listed once in instrument_fields(), with its JSON path, unit, valid range and
// meaning; JSON reading and writing, validation and the documentation table all come from there.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace fogdrift::sim {

/// Nodes of the lumped thermal network, in state-vector order.
enum class Node : int { housing = 0, electronics, coil_outer, coil_inner, acc1, acc2 };
inline constexpr int kNodeCount = 6;
/// A node's index into arrays of kNodeCount values.
constexpr int node_index(Node n) {
  return static_cast<int>(n);
}

struct ThermalParams {
  /// Heat capacity of each node, J/K, in Node order.
  std::array<double, kNodeCount> capacity_j_per_k{2000.0, 400.0, 250.0, 250.0, 60.0, 60.0};
  // Thermal conductances, W/K.
  double housing_air_w_per_k = 1.2;              ///< housing ↔ chamber air (convection)
  double electronics_housing_w_per_k = 0.8;      ///< electronics board ↔ housing
  double coil_outer_housing_w_per_k = 1.5;       ///< outer fiber layers ↔ coil mount/housing
  double coil_inner_outer_w_per_k = 1.0;         ///< inner ↔ outer fiber layers (across the coil)
  double coil_inner_electronics_w_per_k = 0.15;  ///< coil hub ↔ electronics (asymmetric path)
  double acc1_electronics_w_per_k = 0.3;  ///< accelerometer 1 ↔ electronics (near the board)
  double acc1_housing_w_per_k = 0.3;      ///< accelerometer 1 ↔ housing
  double acc2_housing_w_per_k = 0.6;      ///< accelerometer 2 ↔ housing (far from the board)
  // Heat sources while powered, W.
  double electronics_power_w = 5.0;   ///< processor, FOG and accelerometer electronics
  double light_source_power_w = 1.0;  ///< light source and driver, on the electronics board
  double tec_w_per_k = 0.02;          ///< light-source cooler: extra W per K of |T_housing − set|
  double tec_setpoint_degc = 25.0;    ///< cooler set point, °C
  double acc1_power_w = 0.3;          ///< accelerometer 1 servo
  double acc2_power_w = 0.3;          ///< accelerometer 2 servo
};

/// A built-in thermometer: reads its node through a first-order lag, with noise and quantisation.
struct ThermometerParams {
  double lag_s = 5.0;             ///< first-order time constant, s
  double noise_degc = 0.01;       ///< white noise standard deviation per sample, °C
  double resolution_degc = 0.01;  ///< quantisation step, °C (0 = none)
  double offset_degc = 0.0;       ///< calibration offset, °C
  /// Placement: the share of the housing temperature in what it reads (0: its node alone; a
  /// sensor mounted near the wall reads partly the housing).
  double housing_share = 0.0;
};

/// FOG output = Earth-rate projection + turn-on bias + thermal drift (IEEE Std 952) + noise.
struct FogParams {
  double bias_dph = 0.02;              ///< constant turn-on bias, °/h
  double bias_run_to_run_dph = 0.002;  ///< σ of the random part of the turn-on bias, °/h
  double reference_temp_degc = 25.0;   ///< T_ref of the drift coefficients, °C
  // Static term B(T̄) = d1·ΔT + d2·ΔT² + d3·ΔT³, ΔT = T̄ − T_ref, T̄ = mean coil temperature.
  double static_d1_dph_per_k = 0.003;
  double static_d2_dph_per_k2 = 6.0e-5;
  double static_d3_dph_per_k3 = 9.0e-7;
  // Rate term D_Ṫ(T̄)·dT̄/dt, D_Ṫ = r0·(1 + r1·ΔT), in (°/h)/(°C/s).
  double rate_r0_dph_per_kps = -18.0;
  double rate_r1_per_k = 0.006;
  // Shupe term D_∇(T̄)·d(T_inner − T_outer)/dt, D_∇ = s0·(1 + s1·ΔT + s2·ΔT²), in (°/h)/(°C/s).
  double shupe_s0_dph_per_kps = -70.0;
  double shupe_s1_per_k = -0.008;
  double shupe_s2_per_k2 = 1.0e-4;
  // Terms outside the paper's form, 0 in the default instrument (docs/simulator.md §2, "Other
  // instruments"). A filtered-rate term F·ṡ, s the coil mean temperature low-passed with time
  // constant τ_F (a slow stress relaxation of the coil's potting), in (°/h)/(°C/s):
  double filtered_rate_dph_per_kps = 0.0;
  double filtered_rate_tau_s = 600.0;
  /// An electronics term e1·(T_electronics − T_ref): the light source's wavelength and the
  /// modulation electronics drift with a temperature no thermometer reads, °/h/K.
  double electronics_dph_per_k = 0.0;
  // Noise (IEEE Std 952 Allan terms).
  double arw_deg_per_rth = 0.0005;    ///< angle random walk N, °/√h
  double bias_gm_sigma_dph = 0.0015;  ///< bias instability as a Gauss–Markov process: σ, °/h
  double bias_gm_tau_s = 300.0;       ///< its correlation time, s
  double rrw_deg_per_h_rth = 0.0005;  ///< rate random walk K, °/h/√h
  double quantization_arcsec = 0.05;  ///< angle quantum of the output pulses, ″
  double fine_step_s = 0.1;           ///< internal integration step, s
};

struct AccelerometerParams {
  double bias_g = 2.0e-4;              ///< constant bias, g
  double temp_coeff_g_per_k = 2.0e-6;  ///< bias change per K of its own thermometer node
  double noise_g = 1.0e-5;             ///< white noise per sample, g
};

struct TurntableParams {
  double rate_deg_per_s = 10.0;        ///< rotation rate between positions, °/s
  double indexing_error_arcsec = 2.0;  ///< σ of the angle actually reached at a position, ″
  double tilt_east_deg = 0.05;         ///< platform tilt: rotation about the east axis, °
  double tilt_north_deg = -0.03;       ///< platform tilt: rotation about the north axis, °
};

struct Instrument {
  ThermalParams thermal;
  ThermometerParams thermometer_fog;                          ///< reads the outer coil layer
  ThermometerParams thermometer_acc1{10.0, 0.01, 0.01, 0.0};  ///< reads accelerometer 1
  ThermometerParams thermometer_acc2{10.0, 0.01, 0.01, 0.0};  ///< reads accelerometer 2
  FogParams fog;
  AccelerometerParams accel_x;                            ///< accelerometer 1, along the FOG axis
  AccelerometerParams accel_y{-1.5e-4, -1.5e-6, 1.0e-5};  ///< accelerometer 2, 90° clockwise
  TurntableParams turntable;
};

/// One documented parameter: JSON path (dots), unit, valid range, meaning, and where it lives.
struct InstrumentField {
  std::string path;
  std::string unit;
  double min;
  double max;
  bool min_open;  ///< true: value must be > min (else >= min)
  std::string meaning;
  double* value = nullptr;
};

/// Every parameter of `instrument`, each pointing into it.
std::vector<InstrumentField> instrument_fields(Instrument& instrument);

/// Throws OptionError naming "instrument.PATH", the value and the valid range.
void validate(const Instrument& instrument);

/// Full JSON text {"format": "fogdrift-instrument/1", ...}, every parameter present.
std::string to_json(const Instrument& instrument);

/// Reads JSON text: parameters not given keep their defaults; an unknown key, a non-number or an
/// out-of-range value is an InputError naming `file` and the JSON path.
Instrument instrument_from_json(const std::string& text, const std::string& file);

/// Markdown table of all parameters with defaults (used to write docs/simulator.md).
std::string parameter_table_markdown();

}  // namespace fogdrift::sim
