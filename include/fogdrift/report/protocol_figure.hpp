// The protocols studied on the population against their chamber hours, as a figure
// (`fogdrift plan --hours H --figures DIR`; docs/field.md, "Protocols worth their hours").
#pragma once

#include <vector>

#include "fogdrift/report/figure.hpp"
#include "fogdrift/sim/protocol_front.hpp"

namespace fogdrift::report {

/// One panel, service chamber hours across: every priced protocol's worst median and worst 10th
/// percentile (over the conditions it was priced under, batch and causal), the front through
/// the 10th percentiles no cheaper protocol reaches, the goal's 85 % and 60 % dashed, and
/// the budget as a dashed vertical line; a share below −100 % is drawn at −100 % (the y axis
/// says so; `plan --json` has every figure as measured). The figure is named protocol_front.
Figure protocol_front_figure(const std::vector<sim::PricedProtocol>& priced, double budget_hours);

}  // namespace fogdrift::report
