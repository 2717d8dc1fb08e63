#include "fogdrift/sim/scenarios.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "fogdrift/base/atomic_file.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/option_table.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/base/version.hpp"
#include "fogdrift/sim/nfs.hpp"

namespace fogdrift::sim {
namespace {

// Stream numbers below the run seed, so every recording has its own independent noise.
constexpr std::uint64_t kCalibrationStream = 0;
constexpr std::uint64_t kNorthfindStream = 1'000'000;
constexpr std::uint64_t kStableStream = 2'000'000;
constexpr std::uint64_t kChamberStream = 3'000'000;

// What made the campaign, for its manifest; a north-finding campaign also records how its
// start-ups began.
std::string generator_json(std::string_view scenario, std::uint64_t seed, double rate_hz,
                           const NorthfindOptions* findings = nullptr,
                           const CalibrationOptions* calibration = nullptr) {
  nlohmann::ordered_json g;
  g["tool"] = "fogdrift simulate";
  g["version"] = kVersion;
  g["scenario"] = scenario;
  g["seed"] = seed;
  g["output_rate_hz"] = rate_hz;
  if (findings) {
    g["approach"] = std::string(to_string(findings->approach));
    if (findings->approach != Approach::soaked) g["soak_s"] = findings->soak_s;
    if (findings->approach == Approach::sweep || findings->approach == Approach::ramping)
      g["ramp_degc_per_min"] = findings->ramp_degc_per_min;
    if (findings->approach == Approach::warm) g["warm_off_s"] = findings->warm_off_s;
    if (findings->warmup_s > 0) g["warmup_s"] = findings->warmup_s;
  }
  // The calibration's start-up approaches are written only when they are not the paper's.
  if (calibration && (calibration->approaches.size() != 1 ||
                      calibration->approaches[0] != Approach::calibration)) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (Approach a : calibration->approaches) list.push_back(std::string(to_string(a)));
    g["approaches"] = list;
    g["warm_off_s"] = calibration->warm_off_s;
    g["ramp_degc_per_min"] = calibration->ramp_degc_per_min;
    if (!calibration->start_up_temps_degc.empty())
      g["start_up_temps_degc"] = calibration->start_up_temps_degc;
  }
  return g.dump();
}

void check_temps(const std::vector<double>& temps, const std::string& option) {
  if (temps.empty()) throw OptionError(option, "needs at least one temperature");
  for (double t : temps) {
    if (!std::isfinite(t) || t < -70.0 || t > 100.0) {
      throw OptionError(option, fmt::format("{} °C is outside [-70, 100]", t));
    }
  }
}

void check_rate(double rate_hz, const std::string& field) {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0 || rate_hz > 2000.0) {
    throw OptionError(field, fmt::format("{} is outside (0, 2000] Hz: north-finders log at up to "
                                         "2 kHz",
                                         rate_hz));
  }
}

void check_latitude(double latitude_deg, const std::string& field) {
  // The four-position method needs a horizontal Earth-rate component.
  if (!std::isfinite(latitude_deg) || std::abs(latitude_deg) > 85.0) {
    throw OptionError(field, fmt::format("{}° is outside [-85, 85]", latitude_deg));
  }
}

void check_start_up(double warm_off_s, double ramp_degc_per_min, const std::string& struct_name) {
  if (!(warm_off_s >= 0.0) || warm_off_s > 1e6) {
    throw OptionError(struct_name + ".warm_off_s",
                      fmt::format("{} s is outside [0, 1e6]", warm_off_s));
  }
  if (!(ramp_degc_per_min > 0.0) || ramp_degc_per_min > 100.0) {
    throw OptionError(struct_name + ".ramp_degc_per_min",
                      fmt::format("{} is outside (0, 100] °C/min", ramp_degc_per_min));
  }
}

// The instrument at power-on for a start-up at chamber temperature t0 under an approach that
// does not depend on the previous recording (all but sweep), and the chamber air from then on.
// The simulator's clock reads 0 at power-on. The whole simulator is handed over, not only its
// node temperatures: the filtered coil mean and the thermometers' lags carry the history into
// the start-up as they do between a calibration campaign's cycles (docs/simulator.md).
struct StartUp {
  NfsSimulator simulator;
  AirProfile air;
};

NfsSimulator at_equilibrium(const Instrument& instrument, double degc) {
  NodeTemps temps;
  temps.fill(degc);
  return NfsSimulator(instrument, temps, 0.0);
}

StartUp start_up(const Instrument& instrument, Approach approach, double t0, double soak_s,
                 double warm_off_s, double ramp_degc_per_min) {
  StartUp out{at_equilibrium(instrument, t0), [t0](double) { return t0; }};
  switch (approach) {
    case Approach::soaked:
    case Approach::sweep:
      break;
    case Approach::calibration: {
      // The calibration's sweep shifted to end at t0: as many cycles (soak, powered, ramp 10 °C)
      // before it as the calibration runs before its temperature nearest t0, from equilibrium
      // at the first, then the soak at t0. A slow instrument carries a lag into its start-up
      // that only hours of cycles build up (docs/simulator.md).
      const CalibrationOptions paper;  // its set points and cycle lengths
      const long nearest = std::lround((t0 - paper.temps_degc.front()) / kStepDegc);
      const int cycles =
          static_cast<int>(std::clamp(nearest, 0L, static_cast<long>(paper.temps_degc.size()) - 1));
      const double powered_s = paper.powered_s, ramp_s = paper.ramp_s;
      NfsSimulator chamber = at_equilibrium(instrument, t0 - cycles * kStepDegc);
      for (int c = cycles; c >= 1; --c) {
        const double here = t0 - c * kStepDegc;
        chamber.advance(
            soak_s, [here](double) { return here; }, false);
        const double power_on = chamber.time_s();
        const AirProfile cycle = [here, power_on, powered_s, ramp_s](double t) {
          return here + std::clamp((t - power_on - powered_s) / ramp_s, 0.0, 1.0) * kStepDegc;
        };
        chamber.advance(powered_s, cycle, true);
        chamber.advance(ramp_s, cycle, false);
      }
      chamber.advance(soak_s, out.air, false);
      out.simulator = std::move(chamber);
      break;
    }
    case Approach::warm: {
      constexpr double kFirstRunS = 1800.0;
      out.simulator.advance(kFirstRunS, out.air, true);
      out.simulator.advance(warm_off_s, out.air, false);
      break;
    }
    case Approach::ramping: {
      out.simulator = at_equilibrium(instrument, t0 - kStepDegc);
      const double ramp_s = kStepDegc / ramp_degc_per_min * 60.0;
      out.air = [t0, ramp_s](double t) {
        return t0 - kStepDegc + std::clamp(t / ramp_s, 0.0, 1.0) * kStepDegc;
      };
      break;
    }
  }
  out.simulator.restart_clock(0.0);
  return out;
}

}  // namespace

std::string temperature_tag(double t) {
  std::string body = csv::format_number(std::abs(t));
  return (t < 0 ? "m" : "") + body + "C";
}

namespace {

// In the order of kApproaches, which messages list.
constexpr std::array<EnumName<Approach>, 5> kApproachNames = {
    {{Approach::calibration, "calibration"},
     {Approach::soaked, "soaked"},
     {Approach::warm, "warm"},
     {Approach::ramping, "ramping"},
     {Approach::sweep, "sweep"}}};

}  // namespace

std::string_view to_string(Approach approach) {
  return name_in(kApproachNames, approach);
}

Approach approach_from_string(std::string_view name, const std::string& option) {
  return parse_in(kApproachNames, name, option, "an approach");
}

std::vector<Approach> approaches_from_string(std::string_view list, const std::string& option) {
  std::vector<Approach> out;
  for (const std::string& name : option_items(list))
    out.push_back(approach_from_string(name, option));
  return out;
}

std::string approaches_to_string(const std::vector<Approach>& approaches) {
  std::string out;
  for (const Approach a : approaches) {
    if (!out.empty()) out += ',';
    out += to_string(a);
  }
  return out;
}

std::string approach_names(bool with_sweep) {
  std::string out;
  for (const Approach a : kApproaches)
    if (with_sweep || a != Approach::sweep)
      out += (out.empty() ? "" : ", ") + std::string(to_string(a));
  return out;
}

CalibrationOptions field_calibration() {
  CalibrationOptions o;
  o.approaches = {Approach::calibration, Approach::soaked, Approach::warm, Approach::ramping};
  o.repetitions = 5;
  return o;
}

NorthfindOptions stable_defaults() {
  NorthfindOptions o;
  o.temps_degc = {25.0};
  o.findings = 20;
  o.warmup_s = 7200.0;
  o.approach = Approach::soaked;
  return o;
}

void validate(const CalibrationOptions& o) {
  check_temps(o.temps_degc, "calibration.temps_degc");
  if (!o.start_up_temps_degc.empty())
    check_temps(o.start_up_temps_degc, "calibration.start_up_temps_degc");
  if (o.repetitions < 1 || o.repetitions > 100) {
    throw OptionError("calibration.repetitions",
                      fmt::format("{} is outside [1, 100]", o.repetitions));
  }
  if (o.test_repetitions < 0 || o.test_repetitions > o.repetitions) {
    throw OptionError(
        "calibration.test_repetitions",
        fmt::format("{} is outside [0, repetitions = {}]", o.test_repetitions, o.repetitions));
  }
  if (!(o.soak_s >= 0.0) || !(o.ramp_s >= 0.0) || !(o.powered_s > 0.0)) {
    throw OptionError("calibration.soak_s",
                      "soak and ramp must be >= 0 s and the powered time > 0 s");
  }
  if (!(o.chamber_setpoint_sd_degc >= 0.0) || o.chamber_setpoint_sd_degc > 10.0) {
    throw OptionError("calibration.chamber_setpoint_sd_degc", "must be in [0, 10] °C");
  }
  if (o.approaches.empty())
    throw OptionError("calibration.approaches", "needs at least one approach");
  for (Approach a : o.approaches) {
    if (a == Approach::sweep)
      throw OptionError("calibration.approaches",
                        "sweep is not a calibration approach (the calibration approach is the "
                        "chamber's sweep)");
  }
  check_start_up(o.warm_off_s, o.ramp_degc_per_min, "calibration");
  check_rate(o.output_rate_hz, "calibration.output_rate_hz");
  check_latitude(o.latitude_deg, "calibration.latitude_deg");
}

void validate(const NorthfindOptions& o, const std::string& name) {
  check_temps(o.temps_degc, name + ".temps_degc");
  if (o.findings < 1 || o.findings > 1000) {
    throw OptionError(name + ".findings", fmt::format("{} is outside [1, 1000]", o.findings));
  }
  if (!(o.position_s >= 20.0) || o.position_s > 36000.0) {
    throw OptionError(name + ".position_s",
                      fmt::format("{} s is outside [20, 36000]", o.position_s));
  }
  if (!(o.warmup_s >= 0.0)) throw OptionError(name + ".warmup_s", "must be >= 0 s");
  if (!(o.soak_s >= 0.0) || o.soak_s > 1e6) {
    throw OptionError(name + ".soak_s", fmt::format("{} s is outside [0, 1e6]", o.soak_s));
  }
  check_start_up(o.warm_off_s, o.ramp_degc_per_min, name);
  check_rate(o.output_rate_hz, name + ".output_rate_hz");
  check_latitude(o.latitude_deg, name + ".latitude_deg");
}

Approach approach_of(const CalibrationOptions& o, int repetition) {
  return o.approaches[static_cast<std::size_t>(repetition - 1) % o.approaches.size()];
}

Role role_of(const CalibrationOptions& o, int repetition) {
  return repetition > o.repetitions - o.test_repetitions ? Role::test : Role::train;
}

const std::vector<double>& temps_of(const CalibrationOptions& o, int repetition) {
  const bool afresh = approach_of(o, repetition) != Approach::calibration;
  return afresh && !o.start_up_temps_degc.empty() ? o.start_up_temps_degc : o.temps_degc;
}

SimulatedCampaign simulate_calibration(const Instrument& instrument, const CalibrationOptions& o) {
  validate(instrument);
  validate(o);
  SimulatedCampaign out;
  out.campaign.latitude_deg = o.latitude_deg;
  out.campaign.generator_json =
      generator_json("calibration", o.seed, o.output_rate_hz, nullptr, &o);
  const double cycle_s = o.soak_s + o.powered_s + o.ramp_s;

  for (int rep = 1; rep <= o.repetitions; ++rep) {
    const std::vector<double>& temps = temps_of(o, rep);
    const std::size_t n_temps = temps.size();
    // The chamber reaches each set point within its own control error, drawn per cycle.
    Rng chamber_rng(derive_seed(o.seed, kChamberStream + static_cast<std::uint64_t>(rep)));
    std::vector<double> reached(n_temps);
    for (std::size_t i = 0; i < n_temps; ++i) {
      reached[i] = temps[i] + o.chamber_setpoint_sd_degc * chamber_rng.normal();
    }
    // Air profile of one sweep: hold for soak + powered time, then ramp to the next set point.
    const AirProfile air = [&, cycle_s, n_temps](double t) {
      const double c = std::floor(t / cycle_s);
      const std::size_t i = static_cast<std::size_t>(std::clamp(c, 0.0, double(n_temps - 1)));
      const double into = t - static_cast<double>(i) * cycle_s;
      const double hold = o.soak_s + o.powered_s;
      if (into <= hold || i + 1 >= n_temps || o.ramp_s <= 0.0) return reached[i];
      const double f = std::min(1.0, (into - hold) / o.ramp_s);
      return reached[i] + f * (reached[i + 1] - reached[i]);
    };
    const Approach approach = approach_of(o, rep);
    // Each sweep starts from equilibrium at its first temperature: between sweeps the chamber
    // returns to it and soaks the instrument completely.
    NodeTemps start;
    start.fill(reached[0]);
    NfsSimulator nfs(instrument, start, 0.0);
    for (std::size_t i = 0; i < n_temps; ++i) {
      const double cycle_start = static_cast<double>(i) * cycle_s;
      if (approach == Approach::calibration)
        nfs.advance(cycle_start + o.soak_s - nfs.time_s(), air, false);
      // Other approaches start each cycle afresh at the reached set point, and their air is
      // that approach's (the simulator's clock reads 0 at power-on).
      AirProfile cycle_air = air;
      if (approach != Approach::calibration) {
        StartUp s =
            start_up(instrument, approach, reached[i], o.soak_s, o.warm_off_s, o.ramp_degc_per_min);
        nfs = std::move(s.simulator);
        cycle_air = std::move(s.air);
      }
      RecordSetup setup;
      setup.duration_s = o.powered_s;
      setup.output_rate_hz = o.output_rate_hz;
      setup.latitude_deg = o.latitude_deg;
      setup.platform = Platform(o.azimuth_deg, instrument.turntable.tilt_east_deg,
                                instrument.turntable.tilt_north_deg);
      setup.table = TurntableSchedule(0.0);
      setup.seed =
          derive_seed(o.seed, kCalibrationStream + static_cast<std::uint64_t>(rep) * 1000 + i);
      const double power_on = nfs.time_s();
      Recording rec = nfs.record(setup, cycle_air, power_on);
      if (approach == Approach::calibration) nfs.advance(o.ramp_s, air, false);

      CampaignEntry e;
      e.file = fmt::format("cal_r{}_{}.csv", rep, temperature_tag(temps[i]));
      e.scenario = Scenario::calibration;
      e.role = role_of(o, rep);
      e.repetition = rep;
      e.initial_temp_degc = temps[i];
      e.true_azimuth_deg = setup.platform.true_azimuth_deg();
      rec.source = e.file;
      out.campaign.recordings.push_back(e);
      out.recordings.push_back(std::move(rec));
    }
  }
  return out;
}

namespace {

SimulatedCampaign simulate_findings(const Instrument& instrument, const NorthfindOptions& o,
                                    Scenario scenario, std::uint64_t stream) {
  validate(instrument);
  validate(o, std::string(to_string(scenario)));
  SimulatedCampaign out;
  out.campaign.latitude_deg = o.latitude_deg;
  out.campaign.generator_json =
      generator_json(std::string(to_string(scenario)), o.seed, o.output_rate_hz, &o);
  const double rotation_s = 90.0 / instrument.turntable.rate_deg_per_s;
  if (rotation_s + 10.0 > o.position_s) {
    throw OptionError(std::string(to_string(scenario)) + ".position_s",
                      fmt::format("{} s leaves less than 10 s of dwell after a {} s rotation",
                                  o.position_s, rotation_s));
  }
  std::optional<NfsSimulator> after_previous;  // the instrument when the previous recording ends
  for (std::size_t i = 0; i < o.temps_degc.size(); ++i) {
    const std::uint64_t seed = derive_seed(o.seed, stream + i);
    Rng setup_rng(derive_seed(seed, 100));
    const double azimuth = 360.0 * setup_rng.uniform();
    const double t0 = o.temps_degc[i];

    RecordSetup setup;
    setup.duration_s = o.findings * 4 * o.position_s;
    setup.output_rate_hz = o.output_rate_hz;
    setup.latitude_deg = o.latitude_deg;
    setup.platform =
        Platform(azimuth, instrument.turntable.tilt_east_deg, instrument.turntable.tilt_north_deg);
    // Positions 0°, 90°, 180°, 270°, then on to 360° = 0° for the next finding. The table reaches
    // each position within its indexing error.
    const double index_sd_deg = instrument.turntable.indexing_error_arcsec / 3600.0;
    double error_deg = index_sd_deg * setup_rng.normal();
    setup.table = TurntableSchedule(error_deg);
    for (int p = 1; p < o.findings * 4; ++p) {
      const double next_error = index_sd_deg * setup_rng.normal();
      setup.table.add_move(p * o.position_s, 90.0 + next_error - error_deg,
                           instrument.turntable.rate_deg_per_s);
      error_deg = next_error;
    }
    setup.seed = seed;

    StartUp su = start_up(instrument, o.approach, t0, o.soak_s, o.warm_off_s, o.ramp_degc_per_min);
    if (o.approach == Approach::sweep && i > 0) {
      // Off since the previous recording ended: the chamber ramps to t0, then soaks.
      const double from = o.temps_degc[i - 1];
      const double ramp_s = std::abs(t0 - from) / o.ramp_degc_per_min * 60.0;
      const AirProfile between = [from, t0, ramp_s](double t) {
        return ramp_s <= 0.0 ? t0 : from + std::min(1.0, t / ramp_s) * (t0 - from);
      };
      su.simulator = std::move(*after_previous);
      su.simulator.restart_clock(0.0);
      su.simulator.advance(ramp_s + o.soak_s, between, false);
      su.simulator.restart_clock(0.0);
    }
    const AirProfile& air = su.air;
    NfsSimulator& nfs = su.simulator;
    nfs.advance(o.warmup_s, air, true);
    Recording rec = nfs.record(setup, air, 0.0);
    after_previous = std::move(nfs);

    CampaignEntry e;
    e.file = fmt::format("{}_{}.csv", scenario == Scenario::stable ? "stable" : "nf",
                         temperature_tag(t0));
    if (o.temps_degc.size() > 1 && std::count(o.temps_degc.begin(), o.temps_degc.end(), t0) > 1) {
      e.file = fmt::format("{}_{}_{}.csv", scenario == Scenario::stable ? "stable" : "nf",
                           temperature_tag(t0), i + 1);
    }
    e.scenario = scenario;
    e.role = Role::test;
    e.repetition = 1;
    e.initial_temp_degc = t0;
    e.true_azimuth_deg = setup.platform.true_azimuth_deg();
    rec.source = e.file;
    out.campaign.recordings.push_back(e);
    out.recordings.push_back(std::move(rec));
  }
  return out;
}

}  // namespace

SimulatedCampaign simulate_northfind(const Instrument& instrument, const NorthfindOptions& o) {
  return simulate_findings(instrument, o, Scenario::northfind, kNorthfindStream);
}

SimulatedCampaign simulate_stable(const Instrument& instrument, const NorthfindOptions& o) {
  return simulate_findings(instrument, o, Scenario::stable, kStableStream);
}

void write_campaign(const std::filesystem::path& dir, const SimulatedCampaign& sim, bool replace) {
  fill_directory_atomically(dir, replace, [&](const std::filesystem::path& tmp) {
    for (std::size_t i = 0; i < sim.recordings.size(); ++i) {
      write_recording(tmp / sim.campaign.recordings[i].file, sim.recordings[i]);
    }
    write_manifest(tmp, sim.campaign);
  });
}

}  // namespace fogdrift::sim
