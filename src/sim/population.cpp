#include "fogdrift/sim/population.hpp"

#include <fmt/format.h>

#include <cmath>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"

namespace fogdrift::sim {
namespace {

// Scales: a factor of two either side of the default (log-uniform over [default/2, 2·default]).
PopulationRange twice(std::string path, double value, std::string why) {
  return {std::move(path), value / 2, value * 2, true, std::move(why)};
}
// Signed coefficients: ±twice the default's magnitude, either sign, uniform.
PopulationRange either_sign(std::string path, double value, std::string why) {
  const double magnitude = 2 * std::abs(value);
  return {std::move(path), -magnitude, magnitude, false, std::move(why)};
}

std::vector<PopulationRange> make_ranges() {
  const Instrument d;
  const ThermalParams& t = d.thermal;
  const FogParams& f = d.fog;
  std::vector<PopulationRange> r;
  static const char* nodes[kNodeCount] = {"housing",    "electronics", "coil_outer",
                                          "coil_inner", "acc1",        "acc2"};
  for (int k = 0; k < kNodeCount; ++k)
    r.push_back(twice(fmt::format("thermal.capacity_j_per_k.{}", nodes[k]), t.capacity_j_per_k[k],
                      "mass and materials of the build"));
  const std::string links = "mounting, potting and air flow";
  r.push_back(twice("thermal.housing_air_w_per_k", t.housing_air_w_per_k, "chamber air flow"));
  r.push_back(twice("thermal.electronics_housing_w_per_k", t.electronics_housing_w_per_k, links));
  r.push_back(twice("thermal.coil_outer_housing_w_per_k", t.coil_outer_housing_w_per_k, links));
  r.push_back(twice("thermal.coil_inner_outer_w_per_k", t.coil_inner_outer_w_per_k,
                    "fiber winding and potting"));
  r.push_back({"thermal.coil_inner_electronics_w_per_k", t.coil_inner_electronics_w_per_k / 3,
               t.coil_inner_electronics_w_per_k * 3, true,
               "the hub's path to the board: how asymmetrically the coil heats"});
  r.push_back(twice("thermal.acc1_electronics_w_per_k", t.acc1_electronics_w_per_k, links));
  r.push_back(twice("thermal.acc1_housing_w_per_k", t.acc1_housing_w_per_k, links));
  r.push_back(twice("thermal.acc2_housing_w_per_k", t.acc2_housing_w_per_k, links));
  r.push_back(twice("thermal.electronics_power_w", t.electronics_power_w, "electronics design"));
  r.push_back(twice("thermal.light_source_power_w", t.light_source_power_w, "light source"));
  r.push_back(twice("thermal.tec_w_per_k", t.tec_w_per_k, "cooler efficiency"));
  r.push_back({"thermal.tec_setpoint_degc", 15, 35, false, "cooler set point"});
  r.push_back(twice("thermal.acc1_power_w", t.acc1_power_w, "accelerometer servo"));
  r.push_back(twice("thermal.acc2_power_w", t.acc2_power_w, "accelerometer servo"));
  for (const char* name : {"thermometer_fog", "thermometer_acc1", "thermometer_acc2"}) {
    const std::string n = name;
    r.push_back({n + ".lag_s", 2, 30, true, "sensor type and its thermal contact"});
    r.push_back({n + ".noise_degc", 0.005, 0.03, true, "sensor and converter noise"});
    r.push_back({n + ".offset_degc", -0.5, 0.5, false, "uncalibrated offset"});
    r.push_back({n + ".housing_share", 0, 0.5, false, "placement: how near the wall it sits"});
  }
  r.push_back(either_sign("fog.bias_dph", f.bias_dph, "turn-on bias"));
  r.push_back(twice("fog.bias_run_to_run_dph", f.bias_run_to_run_dph, "bias repeatability"));
  const std::string law = "the drift law's coefficient, either sign";
  r.push_back(either_sign("fog.static_d1_dph_per_k", f.static_d1_dph_per_k, law));
  r.push_back(either_sign("fog.static_d2_dph_per_k2", f.static_d2_dph_per_k2, law));
  r.push_back(either_sign("fog.static_d3_dph_per_k3", f.static_d3_dph_per_k3, law));
  r.push_back(either_sign("fog.rate_r0_dph_per_kps", f.rate_r0_dph_per_kps, law));
  r.push_back(either_sign("fog.rate_r1_per_k", f.rate_r1_per_k, law));
  r.push_back(either_sign("fog.shupe_s0_dph_per_kps", f.shupe_s0_dph_per_kps, law));
  r.push_back(either_sign("fog.shupe_s1_per_k", f.shupe_s1_per_k, law));
  r.push_back(either_sign("fog.shupe_s2_per_k2", f.shupe_s2_per_k2, law));
  r.push_back(either_sign("fog.filtered_rate_dph_per_kps", f.rate_r0_dph_per_kps,
                          "a term in a filtered rate, as large as the rate term"));
  r.push_back({"fog.filtered_rate_tau_s", 120, 1800, true, "its time constant"});
  r.push_back(either_sign("fog.electronics_dph_per_k", f.static_d1_dph_per_k / 2,
                          "a term no thermometer reads, up to the static term's slope"));
  r.push_back(twice("fog.arw_deg_per_rth", f.arw_deg_per_rth, "noise grade"));
  r.push_back(twice("fog.bias_gm_sigma_dph", f.bias_gm_sigma_dph, "noise grade"));
  r.push_back({"fog.bias_gm_tau_s", 100, 900, true, "noise grade"});
  r.push_back(twice("fog.rrw_deg_per_h_rth", f.rrw_deg_per_h_rth, "noise grade"));
  return r;
}

double* field_value(std::vector<InstrumentField>& fields, const std::string& path) {
  for (InstrumentField& f : fields)
    if (f.path == path) return f.value;
  throw OptionError("population", fmt::format("no instrument field '{}'", path));
}

}  // namespace

const std::vector<PopulationRange>& population_ranges() {
  static const std::vector<PopulationRange> ranges = make_ranges();
  return ranges;
}

Instrument draw_instrument(std::uint64_t seed, std::uint64_t index) {
  Instrument in;
  auto fields = instrument_fields(in);
  Rng rng(derive_seed(seed, index));
  for (const PopulationRange& r : population_ranges()) {
    const double u = rng.uniform();
    *field_value(fields, r.path) =
        r.log_uniform ? std::exp(std::log(r.low) + u * (std::log(r.high) - std::log(r.low)))
                      : r.low + u * (r.high - r.low);
  }
  validate(in);
  return in;
}

std::vector<double> default_positions() {
  Instrument in;
  auto fields = instrument_fields(in);
  std::vector<double> out;
  for (const PopulationRange& r : population_ranges()) {
    const double v = *field_value(fields, r.path);
    out.push_back(r.log_uniform
                      ? (std::log(v) - std::log(r.low)) / (std::log(r.high) - std::log(r.low))
                      : (v - r.low) / (r.high - r.low));
  }
  return out;
}

std::string population_table_markdown() {
  Instrument in;
  auto fields = instrument_fields(in);
  std::string out =
      "| parameter | default | low | high | draw | stands for |\n|---|---|---|---|---|---|\n";
  for (const PopulationRange& r : population_ranges())
    out += fmt::format("| `{}` | {:g} | {:g} | {:g} | {} | {} |\n", r.path,
                       *field_value(fields, r.path), r.low, r.high,
                       r.log_uniform ? "log-uniform" : "uniform", r.why);
  return out;
}

}  // namespace fogdrift::sim
