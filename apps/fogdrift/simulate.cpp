// fogdrift simulate: the built-in north-finding-system simulator and the paper's protocols.
#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <memory>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/population.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace fogdrift::app {
namespace {

// The simulator's fields and the flags that set them (the three subcommands share their names).
const FlagTable kSimulateFlags = [] {
  FlagTable t = {{"output_rate_hz", "--rate-hz"},
                 {"calibration.repetitions", "--repetitions"},
                 {"calibration.test_repetitions", "--test-repetitions"},
                 {"calibration.approaches", "--approach"}};
  for (const char* scenario : {"calibration", "northfind", "stable"}) {
    const std::string s = scenario;
    t[s + ".temps_degc"] = "--temps";
    t[s + ".output_rate_hz"] = "--rate-hz";
    t[s + ".latitude_deg"] = "--latitude";
    t[s + ".warm_off_s"] = "--warm-off-s";
    t[s + ".ramp_degc_per_min"] = "--ramp-degc-per-min";
    t[s + ".findings"] = "--findings";
    t[s + ".position_s"] = "--position-s";
    t[s + ".warmup_s"] = "--warmup-s";
    t[s + ".soak_s"] = "--soak-s";
  }
  return t;
}();

struct SimulateArgs {
  std::string out;
  std::uint64_t seed = 1;
  std::string instrument_file;
  double rate_hz = 1.0;
  double latitude_deg = 30.0;
  std::string temps;
  bool force = false;
  int repetitions = 4;
  int test_repetitions = 1;
  int findings = 0;
  double position_s = 90.0;
  double warmup_s = 7200.0;
  std::string approach = "calibration";
  double soak_s = 1200.0;
  double ramp_degc_per_min = 1.0;
  double warm_off_s = 600.0;
  int count = 20;
};

/// What northfind and stable share: temperatures, findings, timing, seed and site.
void set_findings(sim::NorthfindOptions& o, const SimulateArgs& a) {
  if (!a.temps.empty()) o.temps_degc = parse_number_list(a.temps, "--temps");
  if (a.findings != 0) o.findings = a.findings;
  o.position_s = a.position_s;
  o.seed = a.seed;
  o.output_rate_hz = a.rate_hz;
  o.latitude_deg = a.latitude_deg;
}

sim::Instrument load_instrument(const std::string& file) {
  if (file.empty()) return sim::Instrument{};
  return sim::instrument_from_json(read_text_file(file), file);
}

void add_common(CLI::App* cmd, SimulateArgs& a) {
  cmd->add_option("--out,-o", a.out, "Campaign folder to create (must not exist or be empty)")
      ->required();
  cmd->add_option("--seed", a.seed, "Random seed; the same seed gives the same files")
      ->capture_default_str();
  cmd->add_option("--instrument", a.instrument_file,
                  "Instrument parameters (JSON); omitted ones keep their defaults. "
                  "'fogdrift simulate --print-instrument' prints them all");
  cmd->add_option("--rate-hz", a.rate_hz, "Logger output rate, Hz")->capture_default_str();
  cmd->add_option("--latitude", a.latitude_deg, "Site latitude, degrees")->capture_default_str();
  cmd->add_flag("--force", a.force, "Replace --out if it exists (only after success)");
}

// The options of the start-up approaches other than the paper's own.
void add_start_up(CLI::App* cmd, SimulateArgs& a) {
  cmd->add_option("--warm-off-s", a.warm_off_s,
                  "Power-off before a warm restart (--approach warm), s")
      ->capture_default_str();
  cmd->add_option("--ramp-degc-per-min", a.ramp_degc_per_min,
                  "Chamber ramp for --approach ramping (from 10 °C below, starting at power-on) "
                  "and sweep (between temperatures), °C/min")
      ->capture_default_str();
}

constexpr const char* kApproachHelp =
    "  calibration  the paper's chamber protocol: ramp 10 °C in 10 min, soak 20 min; the\n"
    "               instrument powers on some 5 °C short of the chamber's temperature\n"
    "  soaked       soaked to equilibrium (an instrument stored overnight at ambient)\n"
    "  warm         soaked, powered 30 min, off --warm-off-s, on again (a power cut)\n"
    "  ramping      from equilibrium 10 °C below, the air ramps up at --ramp-degc-per-min\n"
    "               from power-on (a chamber still ramping, an enclosure warming in the sun)\n";

void finish(const SimulateArgs& a, const sim::SimulatedCampaign& campaign,
            std::chrono::steady_clock::time_point start, std::string_view scenario) {
  sim::write_campaign(a.out, campaign, a.force);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << fmt::format("wrote {} {} recordings and campaign.json to {} (seed {}, {:.1f} s)\n",
                           campaign.recordings.size(), scenario, a.out, a.seed, elapsed);
}

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
                  "the r-th, cycling; docs/simulator.md gives the chamber hours of each):\n") +
          kApproachHelp +
          "Example: a protocol that covers the field (docs/compensation.md):\n"
          "  fogdrift simulate calibration --out cal --repetitions 4 "
          "--approach calibration,soaked,warm,ramping");
  add_common(cal, *args);
  add_start_up(cal, *args);
  cal->add_option("--approach", args->approach,
                  "Start-up approach of each repetition, comma-separated, cycling")
      ->capture_default_str();
  cal->add_option("--temps", args->temps, "Chamber temperatures, °C, comma-separated")
      ->default_str("-40,-30,...,60");
  cal->add_option("--repetitions", args->repetitions, "Temperature sweeps")->capture_default_str();
  cal->add_option("--test-repetitions", args->test_repetitions, "The last N sweeps get role 'test'")
      ->capture_default_str();
  cal->callback([args] {
    with_flags(kSimulateFlags, [&] {
      const auto start = std::chrono::steady_clock::now();
      sim::CalibrationOptions o;
      if (!args->temps.empty()) o.temps_degc = parse_number_list(args->temps, "--temps");
      o.repetitions = args->repetitions;
      o.test_repetitions = args->test_repetitions;
      o.seed = args->seed;
      o.output_rate_hz = args->rate_hz;
      o.latitude_deg = args->latitude_deg;
      o.approaches = sim::approaches_from_string(args->approach, "--approach");
      o.warm_off_s = args->warm_off_s;
      o.ramp_degc_per_min = args->ramp_degc_per_min;
      finish(*args, sim::simulate_calibration(load_instrument(args->instrument_file), o), start,
             "calibration");
    });
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
  add_start_up(nf, *args);
  nf->add_option("--temps", args->temps, "Initial temperatures, °C, comma-separated")
      ->default_str("-32,-16,-5,17,28,43,54");
  nf->add_option("--findings", args->findings, "Findings per recording")->default_str("5");
  nf->add_option("--position-s", args->position_s, "Seconds per position, rotation included")
      ->capture_default_str();
  nf->add_option("--approach", args->approach, "calibration, soaked, warm, ramping or sweep")
      ->capture_default_str();
  nf->add_option("--soak-s", args->soak_s, "Unpowered soak before power-on, s")
      ->capture_default_str();
  nf->callback([args] {
    with_flags(kSimulateFlags, [&] {
      const auto start = std::chrono::steady_clock::now();
      sim::NorthfindOptions o;
      set_findings(o, *args);
      o.approach = sim::approach_from_string(args->approach, "--approach");
      o.soak_s = args->soak_s;
      o.ramp_degc_per_min = args->ramp_degc_per_min;
      o.warm_off_s = args->warm_off_s;
      finish(*args, sim::simulate_northfind(load_instrument(args->instrument_file), o), start,
             "northfind");
    });
  });

  auto* st = cmd->add_subcommand(
      "stable",
      "The stable-stage reference: four-position findings after a long powered warm-up at room "
      "temperature.");
  add_common(st, *args);
  st->add_option("--temps", args->temps, "Temperatures, °C, comma-separated")->default_str("25");
  st->add_option("--findings", args->findings, "Findings per recording")->default_str("20");
  st->add_option("--warmup-s", args->warmup_s, "Powered warm-up before recording, s")
      ->capture_default_str();
  st->add_option("--position-s", args->position_s, "Seconds per position, rotation included")
      ->capture_default_str();
  st->callback([args] {
    with_flags(kSimulateFlags, [&] {
      const auto start = std::chrono::steady_clock::now();
      sim::NorthfindOptions o = sim::stable_defaults();
      set_findings(o, *args);
      o.warmup_s = args->warmup_s;
      finish(*args, sim::simulate_stable(load_instrument(args->instrument_file), o), start,
             "stable");
    });
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
  pop->add_option("--count", args->count, "Instruments to draw, 1..999")->capture_default_str();
  pop->add_option("--seed", args->seed, "Seed of the population")->capture_default_str();
  pop->add_flag("--force", args->force, "Replace --out if it exists (only after success)");
  pop->callback([args] {
    if (args->count < 1 || args->count > 999)
      throw OptionError("--count", fmt::format("{} is outside 1..999", args->count));
    fill_directory_atomically(args->out, args->force, [&](const std::filesystem::path& dir) {
      for (int k = 1; k <= args->count; ++k)
        write_text_atomically(
            dir / fmt::format("unit_{:02}.json", k),
            sim::to_json(sim::draw_instrument(args->seed, static_cast<std::uint64_t>(k))));
    });
    std::cout << fmt::format(
        "wrote {} instruments unit_01.json … unit_{:02}.json to {} (seed {})\n", args->count,
        args->count, args->out, args->seed);
  });
}

}  // namespace fogdrift::app
