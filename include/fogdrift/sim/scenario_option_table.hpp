// The options of the simulator's protocols, described once (option_table.hpp, docs/options.md):
// `fogdrift simulate calibration|northfind|stable`'s flags and Python's fogdrift.simulate
// keywords come from these tables. What only decides how a front end runs (--out, --seed,
// --instrument, --force; out, seed, instrument, replace) each front end declares itself.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/sim/chamber.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace fogdrift::sim {

/// `simulate calibration`'s options (paper §4.1 and the start-up approaches).
const OptionTable<CalibrationOptions>& calibration_option_table();
/// `simulate northfind`'s and `simulate stable`'s options; stable's defaults are
/// stable_defaults()'s.
const OptionTable<NorthfindOptions>& northfind_option_table();
/// The chamber a protocol's hours are counted in (`fogdrift plan`; chamber.hpp).
const OptionTable<ChamberOptions>& chamber_option_table();

}  // namespace fogdrift::sim
