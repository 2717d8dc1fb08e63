// What a calibration protocol costs in a thermal chamber (docs/field.md, "Chamber hours").
//
// A protocol is what `simulate calibration` runs: sweeps of the set points, each starting its
// recordings up by an approach (calibration, soaked, warm, ramping; scenarios.hpp). The chamber
// has to give each start-up the history the simulator gives it, and no more:
//   calibration  the paper's cycle at every set point, ascending: soak soak_s, powered powered_s,
//                ramp ramp_s to the next; the pass begins at equilibrium at its first set point
//   soaked       equilibrium at the set point (unpowered), then powered_s
//   warm         equilibrium, powered 30 minutes, off warm_off_s, powered_s; right after a soaked
//                start-up at the same set point (whose powered_s of 30 minutes is that first
//                run) only off warm_off_s and powered_s: chained, the same history
//   ramping      equilibrium 10 °C below, then powered_s while the air ramps up at
//                ramp_degc_per_min; ascending, each start-up's end is the next one's soak
// Equilibrium is every node of the instrument's thermal network within settled_within_degc of
// the air, found by running the network from the state the previous step left, unpowered; the
// chamber moves between set points at chamber_ramp_degc_per_min. The passes (a sweep, or a soaked
// sweep with the warm sweep chained to it) run in the protocol's order; a pass that may go either
// way (soaked, warm) runs from the end of the set points nearer the chamber, which saves the
// return of a whole range.
#pragma once

#include <string>
#include <vector>

#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace fogdrift::sim {

struct ChamberOptions {
  double start_degc = 20.0;                ///< the unit's temperature when the chamber starts, °C
  double chamber_ramp_degc_per_min = 1.0;  ///< moves between set points, °C/min
  double settled_within_degc = 0.1;        ///< equilibrium: every node this close to the air, °C
  bool chain_warm = true;                  ///< a warm sweep rides on a soaked one where it can
};

/// Throws OptionError naming the field of an impossible setting.
void validate(const ChamberOptions& options);

/// One thing the chamber does, in order.
struct ChamberStep {
  int repetition = 0;  ///< the sweep (repetition) it serves, 1 …; 0 for a move between passes
  Approach approach = Approach::calibration;
  double set_point_degc = 0;
  std::string action;  ///< "ramp", "settle", "soak", "powered", "off", "powered (recorded)"
  double air_from_degc = 0, air_to_degc = 0;
  double seconds = 0;
};

struct ChamberSchedule {
  std::vector<ChamberStep> steps;
  double hours = 0;                        ///< the whole protocol
  double test_hours = 0;                   ///< of which the test repetitions' own steps
  std::vector<double> repetition_hours;    ///< each repetition's own steps, 1 … repetitions
  double move_hours = 0;                   ///< moves between passes
  double settle_10degc_s = 0;              ///< equilibrium after a 10 °C step from equilibrium, s
  std::size_t chained_warm_start_ups = 0;  ///< warm start-ups that rode on a soaked one
};

/// The chamber schedule of `protocol` for `instrument` (header).
ChamberSchedule chamber_schedule(const Instrument& instrument, const CalibrationOptions& protocol,
                                 const ChamberOptions& options = {});

/// Seconds for the unpowered instrument, at equilibrium at `from_degc`, to come within
/// `within_degc` of air held at `to_degc` on every node (the air jumps: no ramp).
double settle_seconds(const Instrument& instrument, double from_degc, double to_degc,
                      double within_degc);

}  // namespace fogdrift::sim
