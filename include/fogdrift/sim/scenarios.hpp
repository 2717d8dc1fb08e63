// The paper's protocols as simulated campaigns (docs/method.md §3; docs/simulator.md §4).
//
//   calibration  paper §4.1: from −40 °C to 60 °C in 10 °C steps, one-hour cycles (20 min soak,
//                30 min powered and recorded, 10 min ramp to the next temperature), repeated 4
//                times; repetitions 1–3 train, 4 test.
//   northfind    paper §4.2: at each initial temperature the instrument powers on as it does in
//                calibration (Approach) and makes five four-position north-findings back to back.
//   stable       the same north-findings after a long powered warm-up at room temperature.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/recording.hpp"
#include "fogdrift/sim/instrument.hpp"

namespace fogdrift::sim {

/// How a start-up's instrument reaches its initial temperature before power-on: north-finding
/// start-ups (NorthfindOptions) and calibration cycles (CalibrationOptions) alike.
enum class Approach {
  /// Soaked to equilibrium at the initial temperature.
  soaked,
  /// The temperatures are one chamber sweep in the given order: after each recording the
  /// instrument is off while the chamber ramps to the next at ramp_degc_per_min and soaks for
  /// soak_s. The first starts soaked.
  sweep,
  /// The calibration's protocol, its sweep shifted to end at the initial temperature t0: from
  /// equilibrium at t0 − 10n °C, a cycle at t0 − 10n, …, t0 − 10 (soak soak_s, 30 min powered,
  /// ramp 10 °C in 10 min), then the soak at t0, where n is the number of cycles the default
  /// calibration (−40, −30, …, 60 °C) runs before its temperature nearest t0. The instrument
  /// powers on as it does in calibration, not yet at the chamber's temperature and with the lag
  /// the calibration's cycles leave — but at a temperature calibration did not visit. This is
  /// the paper's claim under test, and the default.
  calibration,
  /// A warm restart: soaked at the initial temperature, powered for 30 minutes, off for
  /// warm_off_s, then powered on again — a power cut in the field.
  warm,
  /// Powered on while the chamber (or the sun on an enclosure) still warms it: from equilibrium
  /// 10 °C below, the air ramps to the initial temperature at ramp_degc_per_min from power-on.
  ramping,
};

struct CalibrationOptions {
  /// Chamber temperatures of the cycles, °C, in order (default −40, −30, …, 60).
  std::vector<double> temps_degc{-40, -30, -20, -10, 0, 10, 20, 30, 40, 50, 60};
  /// Set points of the repetitions that start each cycle afresh (soaked, warm, ramping), °C, in
  /// order; empty: temps_degc. A calibration repetition keeps temps_degc: its start-ups' history
  /// is the sweep's steps between them. A soaked start-up costs hours of settling a set point,
  /// so fewer of them is most of what a cheaper protocol saves (docs/field.md, "Protocols worth
  /// their hours").
  std::vector<double> start_up_temps_degc;
  int repetitions = 4;        ///< whole temperature sweeps, >= 1
  int test_repetitions = 1;   ///< the last this many repetitions get role "test", >= 0
  double soak_s = 1200.0;     ///< unpowered soak at the cycle temperature before power-on, s
  double powered_s = 1800.0;  ///< powered and recorded time per cycle, s
  double ramp_s = 600.0;      ///< unpowered ramp to the next temperature, s
  double chamber_setpoint_sd_degc = 0.2;  ///< σ of the chamber's reached set point per cycle, °C
  double azimuth_deg = 0.0;               ///< heading of the FOG axis in the chamber, ° from north
  double latitude_deg = 30.0;             ///< site latitude, °
  double output_rate_hz = 1.0;            ///< logger rate, Hz
  /// How each repetition's start-ups begin (Approach): repetition r uses
  /// approaches[(r − 1) mod size]. Default: the paper's chamber protocol for every repetition.
  /// `calibration` is the sweep described above; `soaked`, `warm` and `ramping` start every
  /// cycle afresh at the reached set point (see Approach); `sweep` is not a calibration approach.
  std::vector<Approach> approaches{Approach::calibration};
  double warm_off_s = 600.0;       ///< power-off before a warm restart (Approach::warm), s
  double ramp_degc_per_min = 1.0;  ///< chamber ramp into the set point (Approach::ramping), °C/min
  std::uint64_t seed = 1;
};

/// The approach repetition `repetition` (1 …) starts up by: approaches[(repetition − 1) mod
/// their count].
Approach approach_of(const CalibrationOptions& options, int repetition);
/// Role::test for the last test_repetitions repetitions, Role::train for the others.
Role role_of(const CalibrationOptions& options, int repetition);
/// The set points repetition `repetition` (1 …) visits, in order: start_up_temps_degc for a
/// soaked, warm or ramping one where given, else temps_degc.
const std::vector<double>& temps_of(const CalibrationOptions& options, int repetition);

std::string_view to_string(Approach approach);
/// Throws OptionError naming `option` for an unknown name.
Approach approach_from_string(std::string_view name, const std::string& option);
/// A comma-separated list of approaches ("calibration,soaked,warm"); errors name `option`.
std::vector<Approach> approaches_from_string(std::string_view list, const std::string& option);
/// The list approaches_from_string reads back: "calibration,soaked,warm".
std::string approaches_to_string(const std::vector<Approach>& approaches);
/// Every approach's name, "calibration, soaked, …", without sweep unless `with_sweep`
/// (calibration has no sweep).
std::string approach_names(bool with_sweep);
/// The calibration protocol docs/field.md recommends: the paper's chamber cycles, with the
/// start-ups of repetitions 1–4 begun as calibration, soaked, warm and ramping, and a fifth
/// repetition (the chamber's protocol again) to test on.
CalibrationOptions field_calibration();

/// The calibration's step between set points, and how far below the initial temperature a
/// ramping start-up begins, °C: the simulator and the chamber's schedule (chamber.hpp) both.
inline constexpr double kStepDegc = 10.0;

/// Every approach, in the order reports list them.
inline constexpr std::array<Approach, 5> kApproaches = {
    Approach::calibration, Approach::soaked, Approach::warm, Approach::ramping, Approach::sweep};

struct NorthfindOptions {
  /// Initial (chamber) temperatures, °C; one recording each (default: the paper's seven).
  std::vector<double> temps_degc{-32, -16, -5, 17, 28, 43, 54};
  int findings = 5;          ///< four-position findings per recording, back to back, >= 1
  double position_s = 90.0;  ///< time per position including the rotation into it, s
  double warmup_s = 0.0;     ///< powered time before recording starts (0: start-up), s
  /// How the instrument reaches each initial temperature before power-on (Approach).
  Approach approach = Approach::calibration;
  double soak_s = 1200.0;          ///< unpowered soak at each temperature before power-on, s
  double ramp_degc_per_min = 1.0;  ///< chamber ramp for sweep and ramping, °C/min
  double warm_off_s = 600.0;       ///< power-off before a warm restart (Approach::warm), s
  double latitude_deg = 30.0;      ///< site latitude, °
  double output_rate_hz = 1.0;     ///< logger rate, Hz
  std::uint64_t seed = 1;
};

/// The stable-stage protocol: 20 findings at 25 °C after a 2-hour warm-up.
NorthfindOptions stable_defaults();

/// Recordings in memory with the manifest that describes them.
struct SimulatedCampaign {
  Campaign campaign;
  std::vector<Recording> recordings;  ///< same order as campaign.recordings
};

/// Throws OptionError naming the field and the rule for impossible settings: the field's path
/// from the options ("calibration.temps_degc"; for north-finding, `name` is the scenario, so
/// "northfind.findings" or "stable.warmup_s").
void validate(const CalibrationOptions& options);
void validate(const NorthfindOptions& options, const std::string& name = "northfind");

SimulatedCampaign simulate_calibration(const Instrument& instrument,
                                       const CalibrationOptions& options);
SimulatedCampaign simulate_northfind(const Instrument& instrument, const NorthfindOptions& options);
SimulatedCampaign simulate_stable(const Instrument& instrument, const NorthfindOptions& options);

/// Writes every recording and campaign.json into `dir` atomically (all or nothing).
void write_campaign(const std::filesystem::path& dir, const SimulatedCampaign& campaign,
                    bool replace);

/// "m40C", "25C", "m2.5C": a temperature as it appears in file names.
std::string temperature_tag(double temp_degc);

}  // namespace fogdrift::sim
