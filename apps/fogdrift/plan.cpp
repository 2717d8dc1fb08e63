// fogdrift plan: what a calibration protocol costs in the chamber, before it is run
// (docs/field.md, "Chamber hours").
#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/sim/chamber.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/scenario_option_table.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {
namespace {

struct PlanArgs {
  std::string instrument_file;
  bool json = false;
  bool schedule = false;
};

nlohmann::ordered_json to_json(const sim::CalibrationOptions& p, const sim::ChamberSchedule& s,
                               bool with_steps) {
  nlohmann::ordered_json j;
  j["hours"] = s.hours;
  j["days"] = s.hours / 24;
  j["test_hours"] = s.test_hours;
  j["move_hours"] = s.move_hours;
  j["settle_10degc_s"] = s.settle_10degc_s;
  j["chained_warm_start_ups"] = s.chained_warm_start_ups;
  j["repetitions"] = nlohmann::ordered_json::array();
  for (int r = 1; r <= p.repetitions; ++r)
    j["repetitions"].push_back({{"repetition", r},
                                {"approach", sim::to_string(sim::approach_of(p, r))},
                                {"role", to_string(sim::role_of(p, r))},
                                {"hours", s.repetition_hours[static_cast<std::size_t>(r - 1)]}});
  if (with_steps) {
    j["steps"] = nlohmann::ordered_json::array();
    for (const sim::ChamberStep& st : s.steps)
      j["steps"].push_back({{"repetition", st.repetition},
                            {"approach", sim::to_string(st.approach)},
                            {"set_point_degc", st.set_point_degc},
                            {"action", st.action},
                            {"air_from_degc", st.air_from_degc},
                            {"air_to_degc", st.air_to_degc},
                            {"seconds", st.seconds}});
  }
  return j;
}

void print(const sim::CalibrationOptions& p, const sim::ChamberSchedule& s, bool with_steps) {
  std::cout << fmt::format(
      "protocol: {} repetitions ({}) at {} set points, {:g} … {:g} °C\n"
      "equilibrium after a 10 °C step: {:.1f} h (this instrument's thermal network)\n\n",
      p.repetitions, sim::approaches_to_string(p.approaches), p.temps_degc.size(),
      p.temps_degc.front(), p.temps_degc.back(), s.settle_10degc_s / 3600);
  std::cout << "| repetition | approach | role | chamber hours |\n|---|---|---|---|\n";
  for (int r = 1; r <= p.repetitions; ++r)
    std::cout << fmt::format("| {} | {} | {} | {:.1f} |\n", r,
                             sim::to_string(sim::approach_of(p, r)), to_string(sim::role_of(p, r)),
                             s.repetition_hours[static_cast<std::size_t>(r - 1)]);
  std::cout << fmt::format("| moves between passes | | | {:.1f} |\n\n", s.move_hours);
  if (with_steps) {
    std::cout << "| repetition | approach | set point °C | action | air °C | minutes |\n"
                 "|---|---|---|---|---|---|\n";
    for (const sim::ChamberStep& st : s.steps)
      std::cout << fmt::format(
          "| {} | {} | {:g} | {} | {} | {:.1f} |\n",
          st.repetition == 0 ? std::string("move") : std::to_string(st.repetition),
          sim::to_string(st.approach), st.set_point_degc, st.action,
          st.air_from_degc == st.air_to_degc
              ? fmt::format("{:g}", st.air_from_degc)
              : fmt::format("{:g} → {:g}", st.air_from_degc, st.air_to_degc),
          st.seconds / 60);
    std::cout << "\n";
  }
  std::cout << fmt::format(
      "chamber hours: {:.1f} ({:.1f} days), of which {:.1f} h the test repetitions a unit "
      "calibrated for service does without; {} warm start-ups chained to soaked ones\n",
      s.hours, s.hours / 24, s.test_hours, s.chained_warm_start_ups);
}

}  // namespace

void add_plan(CLI::App& app) {
  auto args = std::make_shared<PlanArgs>();
  auto* cmd = app.add_subcommand(
      "plan",
      "What a calibration protocol costs in the thermal chamber before it is run: the chamber "
      "hours of each repetition and of the whole, from this instrument's thermal network "
      "(equilibrium where a start-up needs it) and the chamber's ramp rate. The protocol is "
      "given as to 'fogdrift simulate calibration', which runs it (docs/field.md, \"Chamber "
      "hours\").\n"
      "Example, the protocol docs/field.md recommends for a unit of unknown physics:\n"
      "  fogdrift plan --repetitions 7 "
      "--approach calibration,soaked,warm,ramping,warm,warm,calibration");
  const auto protocol = std::make_shared<OptionFlags>(
      cmd, specs_of(sim::calibration_option_table()),
      defaults_of(sim::calibration_option_table(), sim::CalibrationOptions{}),
      "The protocol (as simulate calibration)");
  const auto chamber = std::make_shared<OptionFlags>(
      cmd, specs_of(sim::chamber_option_table()),
      defaults_of(sim::chamber_option_table(), sim::ChamberOptions{}), "The chamber");
  cmd->add_option("--instrument", args->instrument_file,
                  "Instrument parameters (JSON, as simulate --instrument); default: the built-in "
                  "instrument");
  cmd->add_flag("--schedule", args->schedule,
                "Also list every step of the chamber in order (set point, action, air, minutes)");
  cmd->add_flag("--json", args->json, "Print JSON (with --schedule, every step) instead of text");
  cmd->callback([args, protocol, chamber] {
    sim::CalibrationOptions p;
    protocol->apply(sim::calibration_option_table(), p);
    sim::ChamberOptions c;
    chamber->apply(sim::chamber_option_table(), c);
    const sim::Instrument instrument =
        args->instrument_file.empty()
            ? sim::Instrument{}
            : sim::instrument_from_json(read_text_file(args->instrument_file),
                                        args->instrument_file);
    sim::ChamberSchedule s;
    try {
      s = sim::chamber_schedule(instrument, p, c);
    } catch (const OptionError& e) {
      throw e.option().rfind("calibration.", 0) == 0 ? protocol->named(e) : chamber->named(e);
    }
    if (args->json)
      std::cout << to_json(p, s, args->schedule).dump(2) << "\n";
    else
      print(p, s, args->schedule);
  });
}

}  // namespace fogdrift::app
