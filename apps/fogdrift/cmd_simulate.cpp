// fogdrift simulate: the built-in north-finding-system simulator and the paper's protocols.
#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/option_table.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/population.hpp"
#include "fogdrift/sim/population_option_table.hpp"
#include "fogdrift/sim/scenario_option_table.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {
namespace {

struct SimulateArgs {
  std::string out;
  std::uint64_t seed = 1;
  std::string instrument_file;
  bool force = false;
};

sim::Instrument load_instrument(const std::string& file) {
  if (file.empty()) return sim::Instrument{};
  return sim::instrument_from_json(read_text_file(file), file);
}

/// What every protocol's front end decides itself: where, which seed, which instrument.
void add_common(CLI::App* cmd, SimulateArgs& a) {
  cmd->add_option("--out,-o", a.out, "Campaign folder to create (must not exist or be empty)")
      ->required();
  cmd->add_option("--seed", a.seed, "Random seed; the same seed gives the same files")
      ->capture_default_str();
  cmd->add_option("--instrument", a.instrument_file,
                  "Instrument parameters (JSON); omitted ones keep their defaults. "
                  "'fogdrift simulate --print-instrument' prints them all");
  cmd->add_flag("--force", a.force, "Replace --out if it exists (only after success)");
}

/// The protocol's options as flags (scenario_option_table.hpp), shown with `defaults`.
template <class O>
std::shared_ptr<OptionFlags> add_protocol(CLI::App* cmd, const OptionTable<O>& table,
                                          const O& defaults) {
  return std::make_shared<OptionFlags>(cmd, specs_of(table), defaults_of(table, defaults));
}

/// Simulates `scenario` with the options given over `options` and writes the campaign.
template <class O, class Simulate>
void run_protocol(const SimulateArgs& a, const OptionFlags& flags, const OptionTable<O>& table,
                  O options, const std::string& scenario, Simulate simulate) {
  const auto start = std::chrono::steady_clock::now();
  flags.apply(table, options);
  options.seed = a.seed;
  sim::SimulatedCampaign campaign;
  const sim::Instrument instrument = load_instrument(a.instrument_file);
  check_output_not_input(a.out, "--out");
  try {
    campaign = simulate(instrument, options);
  } catch (const OptionError& e) {
    throw flags.named(e);
  }
  sim::write_campaign(a.out, campaign, a.force);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << fmt::format("wrote {} {} recordings and campaign.json to {} (seed {}, {:.1f} s)\n",
                           campaign.recordings.size(), scenario, a.out, a.seed, elapsed);
}

constexpr const char* kApproachHelp =
    "  calibration  the paper's chamber protocol: the calibration's cycles (ramp 10 °C in\n"
    "               10 min, soak 20 min) up to the temperature; the instrument powers on\n"
    "               short of the chamber's temperature (5 °C on the default instrument)\n"
    "  soaked       soaked to equilibrium (an instrument stored overnight at ambient)\n"
    "  warm         soaked, powered 30 min, off --warm-off-s, on again (a power cut)\n"
    "  ramping      from equilibrium 10 °C below, the air ramps up at --ramp-degc-per-min\n"
    "               from power-on (a chamber still ramping, an enclosure warming in the sun)\n";

}  // namespace

void add_simulate(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "simulate",
      "Simulate a north-finding system in a thermal chamber and write a campaign folder.\n"
      "The model (thermal network, IEEE Std 952 drift, FOG noise, accelerometers, turntable) is\n"
      "described in docs/simulator.md. Examples:\n"
      "  fogdrift simulate calibration --out cal --seed 1     # paper §4.1: 11 temps x 4 reps\n"
      "  fogdrift simulate northfind --out nf --temps -32,17,54\n"
      "  fogdrift simulate stable --out st\n"
      "  fogdrift simulate --print-instrument > unit.json     # edit, then --instrument unit.json");
  auto args = std::make_shared<SimulateArgs>();
  auto print = std::make_shared<bool>(false);
  auto print_table = std::make_shared<bool>(false);
  auto print_population = std::make_shared<bool>(false);
  cmd->add_flag("--print-instrument", *print,
                "Print the default instrument parameters as JSON and exit");
  cmd->add_flag("--print-parameter-table", *print_table,
                "Print the parameters as a Markdown table (units, ranges, meaning) and exit");
  cmd->add_flag("--print-population-table", *print_population,
                "Print the ranges 'simulate population' draws instruments from (Markdown) and "
                "exit");
  cmd->require_subcommand(0, 1);
  cmd->callback([cmd, print, print_table, print_population] {
    if (*print_table) {
      std::cout << sim::parameter_table_markdown();
    } else if (*print_population) {
      std::cout << sim::population_table_markdown();
    } else if (*print) {
      std::cout << sim::to_json(sim::Instrument{});
    } else if (cmd->get_subcommands().empty()) {
      throw CLI::CallForHelp();
    }
  });

  auto* cal = cmd->add_subcommand(
      "calibration",
      std::string("Paper §4.1: chamber steps from -40 to 60 °C by 10 °C, one-hour cycles (20 min "
                  "soak, 30 min powered and recorded, 10 min ramp), repeated; the last repetition "
                  "is the test set.\n"
                  "How each repetition's start-ups begin (--approach A[,B,...]: repetition r takes "
                  "the r-th, cycling; 'fogdrift plan' gives the chamber hours of a protocol):\n") +
          kApproachHelp +
          "Example: the protocol that covers the field's start-ups on a unit of unknown physics "
          "(docs/field.md; the last repetition is the test):\n"
          "  fogdrift simulate calibration --out cal --repetitions 7 "
          "--approach calibration,soaked,warm,ramping,warm,warm,calibration");
  add_common(cal, *args);
  const auto cal_flags =
      add_protocol(cal, sim::calibration_option_table(), sim::CalibrationOptions{});
  cal->callback([args, cal_flags] {
    run_protocol(*args, *cal_flags, sim::calibration_option_table(), sim::CalibrationOptions{},
                 "calibration", sim::simulate_calibration);
  });

  auto* nf = cmd->add_subcommand(
      "northfind",
      std::string(
          "Paper §4.2: at each initial temperature, power on and make four-position "
          "north-findings back to back during the start-up; the true azimuth is in the "
          "manifest.\nHow the instrument reaches each initial temperature (--approach):\n") +
          kApproachHelp +
          "  sweep        the temperatures in the given order as one chamber sweep (ramp, soak)");
  add_common(nf, *args);
  const auto nf_flags = add_protocol(nf, sim::northfind_option_table(), sim::NorthfindOptions{});
  nf->callback([args, nf_flags] {
    run_protocol(*args, *nf_flags, sim::northfind_option_table(), sim::NorthfindOptions{},
                 "northfind", sim::simulate_northfind);
  });

  auto* st = cmd->add_subcommand(
      "stable",
      "The stable-stage reference: four-position findings after a long powered warm-up at room "
      "temperature.");
  add_common(st, *args);
  const auto st_flags = add_protocol(st, sim::northfind_option_table(), sim::stable_defaults());
  st->callback([args, st_flags] {
    run_protocol(*args, *st_flags, sim::northfind_option_table(), sim::stable_defaults(), "stable",
                 sim::simulate_stable);
  });

  auto* pop = cmd->add_subcommand(
      "population",
      "Draw instruments at random from documented ranges around the default one (thermal\n"
      "network, heat sources, thermometer lags and placement, every drift-law coefficient of\n"
      "either sign, a filtered-rate term and a term no thermometer reads, noise levels) and\n"
      "write each as an instrument file, unit_01.json, unit_02.json, ... The same seed gives the\n"
      "same instruments; unit k does not depend on --count. The ranges are in docs/simulator.md\n"
      "(fogdrift simulate --print-population-table). Example, a unit unlike the default:\n"
      "  fogdrift simulate population --out units --count 20 --seed 1\n"
      "  fogdrift simulate calibration --out cal --instrument units/unit_03.json");
  pop->add_option("--out,-o", args->out, "Folder to create (must not exist or be empty)")
      ->required();
  const auto pop_flags = std::make_shared<OptionFlags>(
      pop, specs_of(sim::population_option_table()), defaults_of(sim::population_option_table()));
  pop->add_option("--seed", args->seed, "Seed of the population")->capture_default_str();
  pop->add_flag("--force", args->force, "Replace --out if it exists (only after success)");
  pop->callback([args, pop_flags] {
    sim::PopulationOptions o;
    pop_flags->apply(sim::population_option_table(), o);
    fill_directory_atomically(args->out, args->force, [&](const std::filesystem::path& dir) {
      for (unsigned k = 1; k <= o.count; ++k)
        write_text_atomically(
            dir / fmt::format("unit_{:02}.json", k),
            sim::to_json(sim::draw_instrument(args->seed, static_cast<std::uint64_t>(k))));
    });
    std::cout << fmt::format(
        "wrote {} instruments unit_01.json … unit_{:02}.json to {} (seed {})\n", o.count, o.count,
        args->out, args->seed);
  });
}

}  // namespace fogdrift::app
