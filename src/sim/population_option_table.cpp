// `simulate population`'s options (population_option_table.hpp). Defaults are PopulationOptions'.
#include "fogdrift/sim/population_option_table.hpp"

namespace fogdrift::sim {
namespace {

OptionTable<PopulationOptions> make_population_table() {
  using O = PopulationOptions;
  OptionTable<O> t;
  t.push_back(whole_option<O>(
      {"count",
       "--count",
       {},
       "",
       between(1, 999),
       "Instruments to draw, written unit_01.json … unit_NN.json; unit k does not depend on the "
       "count",
       {}},
      [](auto& o) -> auto& { return o.count; }));
  return t;
}

}  // namespace

const OptionTable<PopulationOptions>& population_option_table() {
  static const OptionTable<PopulationOptions> table = make_population_table();
  return table;
}

}  // namespace fogdrift::sim
