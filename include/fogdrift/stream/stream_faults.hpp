// What the streaming compensator does when the sensor stream is faulty (docs/compensation.md,
// "Sensor faults"): the policy's settings, the per-sample flags it raises, and their names.
//
// An instrument cannot stop compensating because one sample was bad, nor pass a NaN on to the
// north-finder. The policy in brief (the docs give the full rule; StreamingCompensator and the C
// header of `export-c --stream-rate-hz` run the same one):
//  * a thermometer reading that is not a number, lies outside [temp_min_degc, temp_max_degc],
//    jumps by more than temp_jump_degc from its last good value continued along its last rate,
//    or is stuck is replaced by that continuation ("bridged"), for up to bridge_s; a jump that
//    lasts longer is a real step, and the reading is taken again; a time gap up to bridge_s is
//    bridged by interpolating the missing samples;
//  * beyond bridge_s the thermometer (or the gap) is "out": the rate filters start again, and the
//    drift is held at its last good value until a full rate window of good samples has come in
//    ("held"), and if that takes longer than hold_s after the last good drift, the correction
//    stops (the drift is the model's mean drift, as the novelty guard at weight 0: "stopped");
//  * a sample whose time does not advance is skipped (its output repeats the last one); time going
//    back by more than bridge_s is a restart: the compensator starts again as at power-on;
//  * a gyro reading that is not a number or beyond gyro_limit_dph gets the last good compensated
//    value; so does a reading of another target (an accelerometer, a scale-factor channel:
//    target.hpp) that is not a number, whatever its size.
// The drift is always a finite number, and without faults the output is unchanged, bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace fogdrift {

struct FaultPolicy {
  /// Thermometer readings outside [temp_min_degc, temp_max_degc] are faults, °C. The defaults
  /// hold the −40 … 60 °C ambient range with the instrument's self-heating and a margin.
  double temp_min_degc = -60;
  double temp_max_degc = 125;
  /// A gyro reading whose magnitude exceeds this is a fault, °/h (3.6e6 °/h = 1000 °/s).
  double gyro_limit_dph = 3.6e6;
  /// The longest thermometer outage or time gap bridged by substituted samples, s, ≥ 0; time
  /// going back by more than this is a restart, by less a sample out of order.
  double bridge_s = 5;
  /// The longest the drift is held at its last good value before the correction stops, s,
  /// ≥ bridge_s. The default outlasts the refill of a 121 s rate window after an outage: a start-up
  /// drift moves by hundredths of °/h in minutes, while stopping the correction is a step of
  /// the whole drift.
  double hold_s = 300;
  /// A thermometer whose reading has not changed for stuck_s while another thermometer the model
  /// reads moved by stuck_delta_degc or more is stuck, s; 0 switches the check off. A quantised
  /// thermometer in a steady instrument reads the same value for minutes, so the check needs
  /// another thermometer to show the instrument is not steady; with one thermometer it never
  /// fires.
  double stuck_s = 300;
  double stuck_delta_degc = 2;
  /// A thermometer reading this far from its last good reading continued along its last rate is
  /// a jump, °C, bridged like a bad reading; 0 switches the check off. A unit's thermometer moves
  /// by hundredths of a degree a second, so a bus glitch of +100 °C inside the range limits is
  /// caught, while a step that lasts beyond bridge_s is taken as real (the rates start again).
  double temp_jump_degc = 10;
};

/// Throws OptionError naming the field (faults.temp_min_degc, faults.bridge_s, …) and the rule.
void validate(const FaultPolicy& policy);

/// The policy's timings for a model whose features are formed every `model_dt_s` seconds with a
/// rate window of `rate_window_s` (docs/compensation.md, "Sensor faults"): the defaults above,
/// which suit a model at 1 Hz or faster, stretched for a slower one so that each still means what
/// it says in samples of the model:
///   bridge_s = max(5 s, 2 intervals)          one missing model sample is bridged
///   hold_s   = max(300 s, 2 rate windows)     the hold outlasts the refill of the rate window
///   stuck_s  = max(300 s, 5 intervals)
/// The thermometer and gyro limits are the defaults'.
FaultPolicy fault_policy_for(double model_dt_s, double rate_window_s);

/// A step is "at the interval" within ±10 % of it, in every streaming path (StreamingCompensator,
/// stream, the C header's PREFIX_INTERVAL_TOLERANCE); a step of 0.5 to 1.5 intervals outside that
/// is flagged fault::off_interval, shorter is out of order, longer a gap.
inline constexpr double kIntervalTolerance = 0.10;

/// Whether a step of `step_s` between samples is off the interval `dt_s` (kIntervalTolerance).
inline bool off_interval(double step_s, double dt_s) noexcept {
  return step_s < (1 - kIntervalTolerance) * dt_s || step_s > (1 + kIntervalTolerance) * dt_s;
}

/// Per-sample flags of the streaming compensator, OR-ed together.
namespace fault {
constexpr std::uint32_t temp_bad = 1u << 0;      ///< a thermometer not a number or out of range
constexpr std::uint32_t temp_stuck = 1u << 1;    ///< a thermometer stuck
constexpr std::uint32_t gyro_bad = 1u << 2;      ///< the gyro not a number or out of range
constexpr std::uint32_t time_bad = 1u << 3;      ///< time not a number; taken as one step on
constexpr std::uint32_t gap = 1u << 4;           ///< samples missing before this one
constexpr std::uint32_t out_of_order = 1u << 5;  ///< time did not advance; sample skipped
constexpr std::uint32_t restart = 1u << 6;       ///< time went back: started again
constexpr std::uint32_t bridged = 1u << 7;       ///< the drift uses substituted temperatures
constexpr std::uint32_t held = 1u << 8;          ///< the drift is the last good one, held
constexpr std::uint32_t stopped = 1u << 9;       ///< the correction stopped: the mean drift
constexpr std::uint32_t temp_jump = 1u << 10;    ///< a thermometer jumped (temp_jump_degc)
/// time stepped by neither the interval (within kIntervalTolerance) nor a gap: data at another
/// rate than the one given; the sample is taken as one interval, and flagged
constexpr std::uint32_t off_interval = 1u << 11;
constexpr std::size_t count = 12;
/// The flags' names, bit k at index k: "temp_bad", "temp_stuck", …
const std::array<std::string_view, count>& names();
/// "temp_bad|bridged", or "" for no flags.
std::string describe(std::uint32_t flags);
}  // namespace fault

}  // namespace fogdrift
