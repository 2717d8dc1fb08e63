// fogdrift plan: what a calibration protocol costs in the chamber, before it is run
// (docs/field.md, "Chamber hours").
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/report/protocol_figure.hpp"
#include "fogdrift/sim/chamber.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/plan_option_table.hpp"
#include "fogdrift/sim/protocol_front.hpp"
#include "fogdrift/sim/scenario_option_table.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {
namespace {

struct PlanArgs {
  std::string instrument_file;
  bool json = false;
  bool schedule = false;
  std::string figures;  ///< with --hours: the front as PNG and JSON here; empty: none
  bool force = false;
};

/// `fogdrift simulate calibration` with the flags that make `p`: those not at their default.
std::string simulate_command(const sim::CalibrationOptions& p) {
  const auto& table = sim::calibration_option_table();
  const std::vector<std::string> defaults = defaults_of(table, sim::CalibrationOptions{});
  std::string cmd = "fogdrift simulate calibration";
  for (std::size_t i = 0; i < table.size(); ++i) {
    const std::string text = table[i].text_of(p);
    if (text != defaults[i]) cmd += " " + table[i].spec.flag + "=" + text;
  }
  return cmd;
}

nlohmann::ordered_json shares_json(const std::array<sim::PopulationShare, 4>& shares) {
  nlohmann::ordered_json j;
  for (std::size_t c = 0; c < shares.size(); ++c)
    j[std::string(sim::to_string(sim::kServiceConditions[c]))] = {
        {"median_pct", shares[c].median_pct},
        {"p10_pct", shares[c].p10_pct},
        {"worst_pct", shares[c].worst_pct}};
  return j;
}

/// The study repeated with other search seeds: what the worst figures of the protocol also cover.
nlohmann::ordered_json reruns_json(const sim::StudiedProtocol& s) {
  nlohmann::ordered_json j = nlohmann::ordered_json::array();
  for (const sim::SeedRerun& r : s.reruns)
    j.push_back({{"search_seed_offset", r.search_seed_offset},
                 {"batch", shares_json(r.batch)},
                 {"causal", shares_json(r.causal)},
                 {"worse_than_raw", r.worse_than_raw}});
  return j;
}

nlohmann::ordered_json priced_json(const sim::PricedProtocol& p) {
  return {{"name", p.studied->name},
          {"service_hours", p.service_hours},
          {"hours", p.schedule.hours},
          {"simulate", simulate_command(p.studied->protocol)},
          {"worst_median_pct", p.worst_median_pct},
          {"worst_p10_pct", p.worst_p10_pct},
          {"worst_pct", p.worst_worst_pct},
          // The claim's count: the most cells worse than raw of any set of search seeds (the
          // first study's own is "worse_than_raw" below, each rerun's in "reruns").
          {"most_worse_than_raw", p.worse_than_raw},
          {"on_front", p.on_front},
          {"meets_goal", p.meets_goal},
          {"batch", shares_json(p.studied->batch)},
          {"causal", shares_json(p.studied->causal)},
          {"instruments", p.studied->instruments},
          {"worse_than_raw", p.studied->worse_than_raw},
          {"train_median_s", p.studied->train_median_s},
          {"reruns", reruns_json(*p.studied)}};
}

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
  if (!p.start_up_temps_degc.empty())
    std::cout << fmt::format("soaked, warm and ramping sweeps at {} set points: {} °C\n\n",
                             p.start_up_temps_degc.size(),
                             option_numbers_text(p.start_up_temps_degc));
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

std::string share_cells(const std::array<sim::PopulationShare, 4>& shares) {
  std::string row;
  for (const sim::PopulationShare& x : shares)
    row += fmt::format(" {:g} / {:g} / {:g} |", x.median_pct, x.p10_pct, x.worst_pct);
  return row;
}

/// What --hours prints: the chosen protocol, what it removed on the population, and the others.
void print_choice(const sim::PricedProtocol& chosen, const std::vector<sim::PricedProtocol>& all,
                  double budget, const std::string& service) {
  const sim::StudiedProtocol& s = *chosen.studied;
  // Where the study was repeated with other search seeds, each set's rows, and the worst figures
  // below cover them all.
  std::string rerun_rows, first_seeds, seeds;
  for (const sim::SeedRerun& r : s.reruns) {
    rerun_rows +=
        fmt::format("| batch, search seeds k + {0} |{1}\n| causal, search seeds k + {0} |{2}\n",
                    r.search_seed_offset, share_cells(r.batch), share_cells(r.causal));
    seeds += fmt::format(", k + {}", r.search_seed_offset);
  }
  if (!s.reruns.empty()) {
    first_seeds = ", search seeds k";
    seeds = fmt::format(" and {} sets of search seeds (train --seed k{} for instrument k)",
                        s.reruns.size() + 1, seeds);
  }
  std::cout << fmt::format(
      "{:g} chamber hours for a unit that will meet {} start-ups buy: {}, {:.1f} h ({:.1f} days) "
      "in this chamber, the test sweep left out\n"
      "run it (the last sweep is the test a unit calibrated for service does without):\n"
      "  {}\n\n"
      "what it removed on the population (docs/field.md, \"Protocols worth their hours\"), "
      "% of the removable north-finding error, median / 10th percentile / worst, guard on:\n"
      "| path | calibration | soaked | warm | ramping |\n|---|---|---|---|---|\n"
      "| batch{} |{}\n| causal{} |{}\n{}"
      "worst over {}, batch and causal{}: median {:g} %, 10th percentile {:g} %; of {} "
      "instruments × 4 conditions × 2 paths, {} worse than raw\n\n",
      budget, service, s.name, chosen.service_hours, chosen.service_hours / 24,
      simulate_command(s.protocol), first_seeds, share_cells(s.batch), first_seeds,
      share_cells(s.causal), rerun_rows, service, seeds, chosen.worst_median_pct,
      chosen.worst_p10_pct, s.instruments, chosen.worse_than_raw);
  if (!chosen.meets_goal) {
    const auto goal = sim::cheapest_meeting_goal(all);
    std::cout << fmt::format(
        "note: this protocol misses the goal on the population (every median ≥ {:g} %, every "
        "10th percentile ≥ {:g} %, none worse than raw); {}\n\n",
        sim::kGoalMedianPct, sim::kGoalP10Pct,
        goal ? fmt::format("the cheapest that meets it, {}, needs {:.1f} h here",
                           goal->studied->name, goal->service_hours)
             : std::string("none studied meets it under these conditions"));
  }
  std::cout << "every studied protocol in this chamber, cheapest first (* on the front: no "
               "cheaper one has as high a worst 10th percentile):\n"
               "| protocol | service hours | worst median / 10th percentile / worst, % | |\n"
               "|---|---|---|---|\n";
  for (const sim::PricedProtocol& p : all)
    std::cout << fmt::format("| {} | {:.1f} | {:g} / {:g} / {:g} | {}{} |\n", p.studied->name,
                             p.service_hours, p.worst_median_pct, p.worst_p10_pct,
                             p.worst_worst_pct, p.on_front ? "*" : "",
                             p.studied == chosen.studied ? " chosen" : "");
  std::cout << "\n";
}

/// --hours: the protocol the budget buys, its figures first (a folder that cannot be written
/// fails the command before anything is printed), then the choice as text or JSON.
void choose(const PlanArgs& a, const sim::Instrument& instrument, const sim::PlanOptions& o) {
  if (!a.figures.empty()) check_output_not_input(a.figures, "--figures");
  const auto priced = sim::price_protocols(instrument, o.chamber, o.service);
  const auto chosen = sim::choose_protocol(priced, *o.hours);
  if (!chosen)
    throw OptionError(
        "--hours", fmt::format("{:g} h buys no studied protocol: the cheapest, {}, "
                               "needs {:.1f} h in this chamber; give --hours {:.0f} "
                               "or more",
                               *o.hours, priced.front().studied->name, priced.front().service_hours,
                               std::ceil(priced.front().service_hours)));
  if (!a.figures.empty()) {
    std::vector<std::string> problems;
    fill_directory_atomically(a.figures, a.force, [&](const std::filesystem::path& folder) {
      problems = report::write_figures({report::protocol_front_figure(priced, *o.hours)}, folder);
    });
    std::cerr << "Wrote protocol_front (PNG and JSON) to " << a.figures << "/\n";
    for (const std::string& p : problems) std::cerr << "fogdrift plan: no PNG: " << p << "\n";
  }
  if (!a.json) {
    print_choice(*chosen, priced, *o.hours, sim::approaches_to_string(o.service));
    print(chosen->studied->protocol, chosen->schedule, a.schedule);
    return;
  }
  nlohmann::ordered_json j;
  j["budget_hours"] = *o.hours;
  j["service"] = sim::approaches_to_string(o.service);
  j["chosen"] = priced_json(*chosen);
  const auto goal = sim::cheapest_meeting_goal(priced);
  j["goal_needs_hours"] =
      goal ? nlohmann::ordered_json(goal->service_hours) : nlohmann::ordered_json(nullptr);
  j["protocol"] = to_json(chosen->studied->protocol, chosen->schedule, a.schedule);
  j["studied"] = nlohmann::ordered_json::array();
  for (const auto& p : priced) j["studied"].push_back(priced_json(p));
  std::cout << j.dump(2) << "\n";
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
      "Examples: the protocol docs/field.md recommends for a unit of unknown physics, and the "
      "one 60 chamber hours buy (\"Protocols worth their hours\"):\n"
      "  fogdrift plan --repetitions 7 "
      "--approach calibration,soaked,warm,ramping,warm,warm,calibration\n"
      "  fogdrift plan --hours 60 --schedule");
  const auto protocol = std::make_shared<OptionFlags>(
      cmd, specs_of(sim::calibration_option_table()),
      defaults_of(sim::calibration_option_table(), sim::CalibrationOptions{}),
      "The protocol (as simulate calibration)");
  const auto plan = std::make_shared<OptionFlags>(cmd, specs_of(sim::plan_option_table()),
                                                  defaults_of(sim::plan_option_table()),
                                                  "The chamber, and the choice of a protocol");
  cmd->add_option("--instrument", args->instrument_file,
                  "Instrument parameters (JSON, as simulate --instrument); default: the built-in "
                  "instrument");
  cmd->add_flag("--schedule", args->schedule,
                "Also list every step of the chamber in order (set point, action, air, minutes)");
  cmd->add_flag("--json", args->json, "Print JSON (with --schedule, every step) instead of text");
  cmd->add_option("--figures", args->figures,
                  "With --hours: write the studied protocols against their hours "
                  "(protocol_front.png for people, .json for machines) into this new folder");
  cmd->add_flag("--force", args->force, "Replace the --figures folder if it exists");
  cmd->callback([args, protocol, plan] {
    sim::PlanOptions o;
    plan->apply(sim::plan_option_table(), o);
    const auto given = plan->given();
    const bool service_given =
        std::any_of(given.begin(), given.end(), [](const auto& g) { return g.first == "service"; });
    if (service_given && !o.hours)
      throw OptionError("--service", "names the conditions --hours chooses for; give --hours H");
    if (!args->figures.empty() && !o.hours)
      throw OptionError("--figures", "draws the protocols --hours chooses among; give --hours H");
    if (args->force && args->figures.empty())
      throw OptionError("--force", "replaces the folder of --figures; give --figures DIR with it");
    const sim::Instrument instrument =
        args->instrument_file.empty()
            ? sim::Instrument{}
            : sim::instrument_from_json(read_text_file(args->instrument_file),
                                        args->instrument_file);
    if (o.hours) {
      if (!protocol->given().empty())
        throw OptionError("--hours", protocol->words("chooses the protocol, and {" +
                                                     protocol->given().front().first +
                                                     "} gives one: drop one of them"));
      try {
        choose(*args, instrument, o);
      } catch (const OptionError& e) {
        throw e.option().rfind("--", 0) == 0 ? e : plan->named(e);
      }
      return;
    }
    sim::CalibrationOptions p;
    protocol->apply(sim::calibration_option_table(), p);
    sim::ChamberSchedule s;
    try {
      s = sim::chamber_schedule(instrument, p, o.chamber);
    } catch (const OptionError& e) {
      throw e.option().rfind("calibration.", 0) == 0 ? protocol->named(e) : plan->named(e);
    }
    if (args->json)
      std::cout << to_json(p, s, args->schedule).dump(2) << "\n";
    else
      print(p, s, args->schedule);
  });
}

}  // namespace fogdrift::app
