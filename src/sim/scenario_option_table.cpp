// The simulator's protocol options (scenario_option_table.hpp). Defaults are read from the
// options structs, never written here; ranges are checked by validate() (scenarios.hpp), whose
// errors name "calibration.FIELD", "northfind.FIELD" or "stable.FIELD": each option lists those
// names as its fields, so a front end names the error by its own word for the option.
#include "fogdrift/sim/scenario_option_table.hpp"

#include <string>
#include <vector>

namespace fogdrift::sim {
namespace {

/// The library's names of `field` in the scenarios that have it.
std::vector<std::string> in(std::initializer_list<const char*> scenarios,
                            const std::string& field) {
  std::vector<std::string> out;
  for (const char* s : scenarios) out.push_back(std::string(s) + "." + field);
  return out;
}

const std::initializer_list<const char*> kCalibration = {"calibration"};
const std::initializer_list<const char*> kFindings = {"northfind", "stable"};

/// The temperatures of a protocol, each a recording.
template <class O>
Option<O> temps_option(const char* doc, std::initializer_list<const char*> scenarios) {
  return numbers_option<O>(
      {"temps_degc", "--temps", {}, "°C", between(-70, 100), doc, in(scenarios, "temps_degc")},
      [](auto& o) -> auto& { return o.temps_degc; });
}

/// The options calibration and north-finding share: the site, the logger, the start-ups.
template <class O>
void add_site_and_start_up(OptionTable<O>& t, std::initializer_list<const char*> scenarios) {
  t.push_back(number_option<O>(
      {"latitude_deg",
       "--latitude",
       {},
       "°",
       between(-85, 85),
       "Site latitude",
       in(scenarios, "latitude_deg")},
      [](auto& o) -> auto& { return o.latitude_deg; }));
  t.push_back(number_option<O>(
      {"output_rate_hz",
       "--rate-hz",
       {},
       "Hz",
       above(0).at_most(2000),
       "Logger output rate (an interval shorter than the instrument's fine step, 0.1 s by "
       "default, is integrated at the interval)",
       in(scenarios, "output_rate_hz")},
      [](auto& o) -> auto& { return o.output_rate_hz; }));
  t.push_back(number_option<O>(
      {"warm_off_s",
       "--warm-off-s",
       {},
       "s",
       between(0, 1e6),
       "Power-off before a warm restart (approach warm)",
       in(scenarios, "warm_off_s")},
      [](auto& o) -> auto& { return o.warm_off_s; }));
  t.push_back(number_option<O>(
      {"ramp_degc_per_min",
       "--ramp-degc-per-min",
       {},
       "°C/min",
       above(0).at_most(100),
       "Chamber ramp for approach ramping (from 10 °C below, starting at power-on) and sweep "
       "(between temperatures)",
       in(scenarios, "ramp_degc_per_min")},
      [](auto& o) -> auto& { return o.ramp_degc_per_min; }));
}

OptionTable<CalibrationOptions> make_calibration() {
  using O = CalibrationOptions;
  OptionTable<O> t;
  t.push_back(temps_option<O>("Chamber temperatures of the cycles, in order", kCalibration));
  {
    const OptionSpec spec{"start_up_temps_degc",
                          "--start-up-temps",
                          OptionType::numbers,
                          "°C",
                          between(-70, 100).with("empty: --temps"),
                          "Set points of the soaked, warm and ramping repetitions, in order "
                          "(default: --temps; a calibration repetition always sweeps --temps). "
                          "Fewer of them save most of a protocol's chamber hours (docs/field.md, "
                          "\"Protocols worth their hours\")",
                          in(kCalibration, "start_up_temps_degc")};
    t.push_back({spec, [](const O& o) { return option_numbers_text(o.start_up_temps_degc); },
                 [spec](O& o, const std::string& text) {
                   o.start_up_temps_degc =
                       text.empty() ? std::vector<double>{} : parse_numbers_option(spec, text);
                 }});
  }
  t.push_back(whole_option<O>(
      {"repetitions",
       "--repetitions",
       {},
       "",
       between(1, 100),
       "Whole temperature sweeps",
       in(kCalibration, "repetitions")},
      [](auto& o) -> auto& { return o.repetitions; }));
  t.push_back(whole_option<O>(
      {"test_repetitions",
       "--test-repetitions",
       {},
       "",
       at_least(0).with("at most {repetitions}"),
       "The last this many sweeps get role 'test'",
       in(kCalibration, "test_repetitions")},
      [](auto& o) -> auto& { return o.test_repetitions; }));
  t.push_back({{"approaches", "--approach", OptionType::names, "", approach_names(false),
                "How each repetition's start-ups begin: repetition r takes the r-th, cycling "
                "(docs/simulator.md)",
                in(kCalibration, "approaches")},
               [](const O& o) { return approaches_to_string(o.approaches); },
               [](O& o, const std::string& text) {
                 o.approaches = approaches_from_string(text, "approaches");
               }});
  t.push_back(number_option<O>(
      {"soak_s",
       "--soak-s",
       {},
       "s",
       at_least(0),
       "Unpowered soak at each cycle's temperature before power-on",
       in(kCalibration, "soak_s")},
      [](auto& o) -> auto& { return o.soak_s; }));
  t.push_back(number_option<O>(
      {"powered_s",
       "--powered-s",
       {},
       "s",
       above(0),
       "Powered and recorded time of each cycle",
       {}},
      [](auto& o) -> auto& { return o.powered_s; }));
  t.push_back(number_option<O>(
      {"ramp_s",
       "--ramp-s",
       {},
       "s",
       at_least(0),
       "Unpowered ramp to the next cycle's temperature",
       {}},
      [](auto& o) -> auto& { return o.ramp_s; }));
  t.push_back(number_option<O>(
      {"chamber_setpoint_sd_degc",
       "--chamber-setpoint-sd-degc",
       {},
       "°C",
       between(0, 10),
       "σ of the set point the chamber reaches each cycle",
       in(kCalibration, "chamber_setpoint_sd_degc")},
      [](auto& o) -> auto& { return o.chamber_setpoint_sd_degc; }));
  t.push_back(number_option<O>(
      {"azimuth_deg",
       "--azimuth-deg",
       {},
       "°",
       "",
       "Heading of the gyro's axis in the chamber, from north",
       {}},
      [](auto& o) -> auto& { return o.azimuth_deg; }));
  add_site_and_start_up(t, kCalibration);
  return t;
}

OptionTable<NorthfindOptions> make_northfind() {
  using O = NorthfindOptions;
  OptionTable<O> t;
  t.push_back(temps_option<O>("Initial (chamber) temperatures, one recording each", kFindings));
  t.push_back(whole_option<O>(
      {"findings",
       "--findings",
       {},
       "",
       between(1, 1000),
       "Four-position findings per recording, back to back",
       in(kFindings, "findings")},
      [](auto& o) -> auto& { return o.findings; }));
  t.push_back(number_option<O>(
      {"position_s",
       "--position-s",
       {},
       "s",
       between(20, 36000),
       "Time per position, the rotation into it included",
       in(kFindings, "position_s")},
      [](auto& o) -> auto& { return o.position_s; }));
  t.push_back(number_option<O>(
      {"warmup_s",
       "--warmup-s",
       {},
       "s",
       at_least(0),
       "Powered time before recording starts (0: record the start-up)",
       in(kFindings, "warmup_s")},
      [](auto& o) -> auto& { return o.warmup_s; }));
  t.push_back(
      {{"approach", "--approach", OptionType::choice, "", approach_names(true),
        "How the instrument reaches each initial temperature before power-on; sweep: "
        "the temperatures in the given order as one chamber sweep (docs/simulator.md)",
        in(kFindings, "approach")},
       [](const O& o) { return std::string(to_string(o.approach)); },
       [](O& o, const std::string& text) { o.approach = approach_from_string(text, "approach"); }});
  t.push_back(number_option<O>(
      {"soak_s",
       "--soak-s",
       {},
       "s",
       between(0, 1e6),
       "Unpowered soak at each temperature before power-on",
       in(kFindings, "soak_s")},
      [](auto& o) -> auto& { return o.soak_s; }));
  add_site_and_start_up(t, kFindings);
  return t;
}

OptionTable<ChamberOptions> make_chamber() {
  using O = ChamberOptions;
  OptionTable<O> t;
  t.push_back(number_option<O>(
      {"start_degc",
       "--start-degc",
       {},
       "°C",
       between(-70, 100),
       "The unit's temperature, at equilibrium, when the chamber starts",
       {}},
      [](auto& o) -> auto& { return o.start_degc; }));
  t.push_back(number_option<O>(
      {"chamber_ramp_degc_per_min",
       "--chamber-ramp-degc-per-min",
       {},
       "°C/min",
       above(0).at_most(100),
       "How fast the chamber moves between set points (a ramping start-up's own ramp is "
       "--ramp-degc-per-min)",
       {}},
      [](auto& o) -> auto& { return o.chamber_ramp_degc_per_min; }));
  t.push_back(number_option<O>(
      {"settled_within_degc",
       "--settled-within-degc",
       {},
       "°C",
       between(0.001, 10),
       "Equilibrium, which soaked, warm and ramping start-ups begin from: every node of the "
       "instrument this close to the air",
       {}},
      [](auto& o) -> auto& { return o.settled_within_degc; }));
  t.push_back(on_off_option<O>(
      {"chain_warm",
       "--chain-warm",
       {},
       "",
       "",
       "Run each warm repetition's start-up right after a soaked repetition's at the same set "
       "point (off, then on again): the history the simulator gives it, without a soak of its "
       "own",
       {}},
      [](auto& o) -> auto& { return o.chain_warm; }));
  return t;
}

}  // namespace

const OptionTable<ChamberOptions>& chamber_option_table() {
  static const OptionTable<ChamberOptions> table = make_chamber();
  return table;
}

const OptionTable<CalibrationOptions>& calibration_option_table() {
  static const OptionTable<CalibrationOptions> table = make_calibration();
  return table;
}

const OptionTable<NorthfindOptions>& northfind_option_table() {
  static const OptionTable<NorthfindOptions> table = make_northfind();
  return table;
}

}  // namespace fogdrift::sim
