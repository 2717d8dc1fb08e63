// `fogdrift plan`'s options (plan_option_table.hpp): the chamber's table lifted onto
// PlanOptions::chamber, then the budget and the service conditions. Defaults are PlanOptions'.
#include "fogdrift/sim/plan_option_table.hpp"

#include "fogdrift/sim/scenario_option_table.hpp"

namespace fogdrift::sim {
namespace {

OptionTable<PlanOptions> make_plan_table() {
  using O = PlanOptions;
  OptionTable<O> t = lifted<O>(
      chamber_option_table(), [](auto& p) -> auto& { return p.chamber; });
  t.push_back(number_or_none_option<O>(
      {"hours",
       "--hours",
       {},
       "h",
       above(0),
       "Instead of pricing the protocol given, choose one: of the protocols studied on the "
       "population, the one whose worst 10th percentile under {service} (over every set of "
       "search seeds it was studied with) is highest within this many service chamber hours "
       "(the test sweep left out), priced for this instrument and chamber, and whether it "
       "meets the goal (every median ≥ 85 %, every 10th percentile ≥ 60 %, none worse than "
       "raw) or which protocol is the cheapest that does (docs/field.md, \"Protocols worth "
       "their hours\"); none: price the protocol given",
       {}},
      [](auto& o) -> auto& { return o.hours; }));
  t.push_back(
      {{"service",
        "--service",
        OptionType::names,
        "",
        "calibration, soaked, warm, ramping",
        "With {hours}: the start-up conditions the unit will meet in service",
        {}},
       [](const O& o) { return approaches_to_string(o.service); },
       [](O& o, const std::string& text) { o.service = approaches_from_string(text, "service"); }});
  return t;
}

}  // namespace

const OptionTable<PlanOptions>& plan_option_table() {
  static const OptionTable<PlanOptions> table = make_plan_table();
  return table;
}

}  // namespace fogdrift::sim
