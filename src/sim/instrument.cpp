#include "fogdrift/sim/instrument.hpp"

#include <fmt/format.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"

namespace fogdrift::sim {
namespace {

constexpr const char* kInstrumentFormat = "fogdrift-instrument/1";

void add_thermometer(std::vector<InstrumentField>& f, const std::string& name, ThermometerParams& t,
                     const std::string& node) {
  f.push_back({name + ".lag_s", "s", 0, 3600, false, "first-order lag reading " + node, &t.lag_s});
  f.push_back(
      {name + ".noise_degc", "°C", 0, 10, false, "white noise σ per sample", &t.noise_degc});
  f.push_back({name + ".resolution_degc", "°C", 0, 10, false, "quantisation step (0: none)",
               &t.resolution_degc});
  f.push_back({name + ".offset_degc", "°C", -50, 50, false, "calibration offset", &t.offset_degc});
  f.push_back({name + ".housing_share", "1", 0, 1, false,
               "placement: share of the housing temperature in the reading", &t.housing_share});
}

void add_accel(std::vector<InstrumentField>& f, const std::string& name, AccelerometerParams& a) {
  f.push_back({name + ".bias_g", "g", -0.1, 0.1, false, "constant bias", &a.bias_g});
  f.push_back({name + ".temp_coeff_g_per_k", "g/K", -1e-3, 1e-3, false,
               "bias change per K of its node's temperature from 25 °C", &a.temp_coeff_g_per_k});
  f.push_back({name + ".noise_g", "g", 0, 0.1, false, "white noise σ per sample", &a.noise_g});
}

}  // namespace

std::vector<InstrumentField> instrument_fields(Instrument& in) {
  std::vector<InstrumentField> f;
  static const char* node_names[kNodeCount] = {"housing",    "electronics", "coil_outer",
                                               "coil_inner", "acc1",        "acc2"};
  for (int k = 0; k < kNodeCount; ++k) {
    f.push_back({fmt::format("thermal.capacity_j_per_k.{}", node_names[k]), "J/K", 0, 1e7, true,
                 fmt::format("heat capacity of the {} node", node_names[k]),
                 &in.thermal.capacity_j_per_k[k]});
  }
  ThermalParams& t = in.thermal;
  f.push_back({"thermal.housing_air_w_per_k", "W/K", 0, 1e4, true,
               "conductance housing ↔ chamber air", &t.housing_air_w_per_k});
  f.push_back({"thermal.electronics_housing_w_per_k", "W/K", 0, 1e4, false,
               "conductance electronics ↔ housing", &t.electronics_housing_w_per_k});
  f.push_back({"thermal.coil_outer_housing_w_per_k", "W/K", 0, 1e4, false,
               "conductance outer coil layers ↔ housing", &t.coil_outer_housing_w_per_k});
  f.push_back({"thermal.coil_inner_outer_w_per_k", "W/K", 0, 1e4, false,
               "conductance across the coil, inner ↔ outer layers", &t.coil_inner_outer_w_per_k});
  f.push_back({"thermal.coil_inner_electronics_w_per_k", "W/K", 0, 1e4, false,
               "conductance coil hub ↔ electronics", &t.coil_inner_electronics_w_per_k});
  f.push_back({"thermal.acc1_electronics_w_per_k", "W/K", 0, 1e4, false,
               "conductance accelerometer 1 ↔ electronics", &t.acc1_electronics_w_per_k});
  f.push_back({"thermal.acc1_housing_w_per_k", "W/K", 0, 1e4, false,
               "conductance accelerometer 1 ↔ housing", &t.acc1_housing_w_per_k});
  f.push_back({"thermal.acc2_housing_w_per_k", "W/K", 0, 1e4, false,
               "conductance accelerometer 2 ↔ housing", &t.acc2_housing_w_per_k});
  f.push_back({"thermal.electronics_power_w", "W", 0, 1e3, false,
               "electronics dissipation while powered", &t.electronics_power_w});
  f.push_back({"thermal.light_source_power_w", "W", 0, 1e3, false,
               "light source dissipation (on the electronics board) while powered",
               &t.light_source_power_w});
  f.push_back({"thermal.tec_w_per_k", "W/K", 0, 10, false,
               "cooler power per K of |T_housing − set point|", &t.tec_w_per_k});
  f.push_back({"thermal.tec_setpoint_degc", "°C", -60, 100, false, "cooler set point",
               &t.tec_setpoint_degc});
  f.push_back(
      {"thermal.acc1_power_w", "W", 0, 100, false, "accelerometer 1 dissipation", &t.acc1_power_w});
  f.push_back(
      {"thermal.acc2_power_w", "W", 0, 100, false, "accelerometer 2 dissipation", &t.acc2_power_w});
  add_thermometer(f, "thermometer_fog", in.thermometer_fog, "the outer coil node");
  add_thermometer(f, "thermometer_acc1", in.thermometer_acc1, "the accelerometer 1 node");
  add_thermometer(f, "thermometer_acc2", in.thermometer_acc2, "the accelerometer 2 node");
  FogParams& g = in.fog;
  f.push_back({"fog.bias_dph", "°/h", -100, 100, false, "constant turn-on bias", &g.bias_dph});
  f.push_back({"fog.bias_run_to_run_dph", "°/h", 0, 100, false,
               "σ of the random turn-on bias, drawn once per recording", &g.bias_run_to_run_dph});
  f.push_back({"fog.reference_temp_degc", "°C", -60, 100, false, "T_ref of the drift coefficients",
               &g.reference_temp_degc});
  f.push_back({"fog.static_d1_dph_per_k", "°/h/K", -1, 1, false, "static drift, linear term d1",
               &g.static_d1_dph_per_k});
  f.push_back({"fog.static_d2_dph_per_k2", "°/h/K²", -1, 1, false,
               "static drift, quadratic term d2", &g.static_d2_dph_per_k2});
  f.push_back({"fog.static_d3_dph_per_k3", "°/h/K³", -1, 1, false, "static drift, cubic term d3",
               &g.static_d3_dph_per_k3});
  f.push_back({"fog.rate_r0_dph_per_kps", "(°/h)/(K/s)", -1e4, 1e4, false,
               "temperature-rate coefficient D_Ṫ at T_ref", &g.rate_r0_dph_per_kps});
  f.push_back(
      {"fog.rate_r1_per_k", "1/K", -1, 1, false, "relative change of D_Ṫ per K", &g.rate_r1_per_k});
  f.push_back({"fog.shupe_s0_dph_per_kps", "(°/h)/(K/s)", -1e4, 1e4, false,
               "Shupe coefficient D_∇ (coil gradient rate) at T_ref", &g.shupe_s0_dph_per_kps});
  f.push_back({"fog.shupe_s1_per_k", "1/K", -1, 1, false, "relative change of D_∇ per K",
               &g.shupe_s1_per_k});
  f.push_back({"fog.shupe_s2_per_k2", "1/K²", -1, 1, false, "relative change of D_∇ per K²",
               &g.shupe_s2_per_k2});
  f.push_back({"fog.filtered_rate_dph_per_kps", "(°/h)/(K/s)", -1e4, 1e4, false,
               "filtered-rate coefficient F: drift F·ds/dt, s the coil mean low-passed with τ_F",
               &g.filtered_rate_dph_per_kps});
  f.push_back({"fog.filtered_rate_tau_s", "s", 0, 1e6, true, "τ_F of the filtered-rate term",
               &g.filtered_rate_tau_s});
  f.push_back({"fog.electronics_dph_per_k", "°/h/K", -1, 1, false,
               "drift per K of the electronics node from T_ref (no thermometer reads it)",
               &g.electronics_dph_per_k});
  f.push_back(
      {"fog.arw_deg_per_rth", "°/√h", 0, 10, false, "angle random walk N", &g.arw_deg_per_rth});
  f.push_back({"fog.bias_gm_sigma_dph", "°/h", 0, 100, false, "bias instability: Gauss–Markov σ",
               &g.bias_gm_sigma_dph});
  f.push_back({"fog.bias_gm_tau_s", "s", 0, 1e6, true, "bias instability: correlation time",
               &g.bias_gm_tau_s});
  f.push_back({"fog.rrw_deg_per_h_rth", "°/h/√h", 0, 10, false, "rate random walk K",
               &g.rrw_deg_per_h_rth});
  f.push_back({"fog.quantization_arcsec", "″", 0, 100, false,
               "angle quantum of the output (0: none)", &g.quantization_arcsec});
  f.push_back({"fog.fine_step_s", "s", 0, 1, true,
               "integration step; must divide the output interval, or exceed it (a logger above "
               "10 Hz is then integrated at its interval)",
               &g.fine_step_s});
  add_accel(f, "accel_x", in.accel_x);
  add_accel(f, "accel_y", in.accel_y);
  TurntableParams& tt = in.turntable;
  f.push_back(
      {"turntable.rate_deg_per_s", "°/s", 0, 1000, true, "rotation rate", &tt.rate_deg_per_s});
  f.push_back({"turntable.indexing_error_arcsec", "″", 0, 3600, false,
               "σ of the angle reached at each position", &tt.indexing_error_arcsec});
  f.push_back({"turntable.tilt_east_deg", "°", -10, 10, false, "platform tilt, rotation about east",
               &tt.tilt_east_deg});
  f.push_back({"turntable.tilt_north_deg", "°", -10, 10, false,
               "platform tilt, rotation about north", &tt.tilt_north_deg});
  return f;
}

void validate(const Instrument& instrument) {
  Instrument copy = instrument;
  for (const auto& field : instrument_fields(copy)) {
    const double v = *field.value;
    const bool low = field.min_open ? !(v > field.min) : !(v >= field.min);
    if (!std::isfinite(v) || low || v > field.max) {
      throw OptionError("instrument." + field.path,
                        fmt::format("{} is outside {}{}, {}] {}", v, field.min_open ? "(" : "[",
                                    field.min, field.max, field.unit));
    }
  }
}

std::string to_json(const Instrument& instrument) {
  Instrument copy = instrument;
  nlohmann::ordered_json doc;
  doc["format"] = kInstrumentFormat;
  for (const auto& field : instrument_fields(copy)) {
    std::string pointer = "/";
    pointer += field.path;
    for (char& c : pointer)
      if (c == '.') c = '/';
    doc[nlohmann::ordered_json::json_pointer(pointer)] = *field.value;
  }
  return doc.dump(2) + "\n";
}

Instrument instrument_from_json(const std::string& text, const std::string& file) {
  check_json_nesting(file, text);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw_json_syntax_error(file, text, e.byte, e.what());
  } catch (const nlohmann::json::out_of_range& e) {
    throw_json_number_error(file, text, e.what());
  }
  if (!doc.is_object()) throw InputError(file, 0, 0, "(top level): must be a JSON object");
  if (doc.contains("format") &&
      (!doc["format"].is_string() || doc["format"].get<std::string>() != kInstrumentFormat)) {
    throw InputError(
        file, 0, 0,
        fmt::format("format: is {}, expected \"{}\"", doc["format"].dump(), kInstrumentFormat));
  }
  Instrument in;
  const auto fields = instrument_fields(in);
  // Every leaf in the document must be a known field.
  const nlohmann::json flat = doc.flatten();
  for (const auto& [pointer, value] : flat.items()) {
    if (pointer == "/format" || pointer.empty()) continue;  // "": the empty document, {}
    std::string path = pointer.substr(1);
    for (char& c : path)
      if (c == '/') c = '.';
    const InstrumentField* match = nullptr;
    for (const auto& field : fields)
      if (field.path == path) match = &field;
    if (!match) {
      throw InputError(file, 0, 0,
                       fmt::format("{}: unknown parameter ('fogdrift simulate --print-instrument' "
                                   "lists them all)",
                                   path));
    }
    if (!value.is_number()) {
      throw InputError(file, 0, 0,
                       fmt::format("{}: must be a number, found {}", path, value.dump()));
    }
    *match->value = value.get<double>();
  }
  try {
    validate(in);
  } catch (const OptionError& e) {
    throw InputError(file, 0, 0, e.what());
  }
  return in;
}

std::string parameter_table_markdown() {
  Instrument in;
  std::string out =
      "| parameter | default | unit | valid range | meaning |\n|---|---|---|---|---|\n";
  for (const auto& field : instrument_fields(in)) {
    out += fmt::format("| `{}` | {} | {} | {}{}, {}] | {} |\n", field.path, *field.value,
                       field.unit, field.min_open ? "(" : "[", field.min, field.max, field.meaning);
  }
  return out;
}

}  // namespace fogdrift::sim
