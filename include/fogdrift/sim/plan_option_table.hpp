// `fogdrift plan`'s options, described once (option_table.hpp, docs/options.md): the chamber
// (chamber_option_table) and the choice of a protocol within a budget of chamber hours
// (protocol_front.hpp). The protocol to price is `simulate calibration`'s flags, read by that
// table; the instrument, --schedule, --json and --figures the command declares itself.
#pragma once

#include <optional>
#include <vector>

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/sim/chamber.hpp"
#include "fogdrift/sim/protocol_front.hpp"
#include "fogdrift/sim/scenarios.hpp"

namespace fogdrift::sim {

struct PlanOptions {
  ChamberOptions chamber;
  /// Service chamber hours to choose a protocol within; none: price the protocol given.
  std::optional<double> hours;
  /// The start-up conditions the unit will meet in service, a subset of kServiceConditions.
  std::vector<Approach> service{kServiceConditions.begin(), kServiceConditions.end()};
};

const OptionTable<PlanOptions>& plan_option_table();

}  // namespace fogdrift::sim
