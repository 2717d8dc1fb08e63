// `fogdrift simulate population`'s options, described once (option_table.hpp,
// docs/options.md): how many instruments to draw (population.hpp). The folder, the seed and
// --force the command declares itself.
#pragma once

#include "fogdrift/base/option_table.hpp"

namespace fogdrift::sim {

struct PopulationOptions {
  /// Instruments to draw, unit_01 … unit_NN; unit k does not depend on the count.
  unsigned count = 20;
};

const OptionTable<PopulationOptions>& population_option_table();

}  // namespace fogdrift::sim
