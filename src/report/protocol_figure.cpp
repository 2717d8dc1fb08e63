// The studied protocols against their chamber hours (protocol_figure.hpp).
#include "fogdrift/report/protocol_figure.hpp"

#include <algorithm>

namespace fogdrift::report {
namespace {

// Shares far below zero (a protocol that never saw a condition) would squeeze the region that
// matters, 60–100 %, into a line: they are drawn at the floor, as the series' names say.
constexpr double kFloorPct = -100;

double floored(double pct) {
  return std::max(pct, kFloorPct);
}

}  // namespace

Figure protocol_front_figure(const std::vector<sim::PricedProtocol>& priced, double budget_hours) {
  Panel p;
  p.title = "Removable north-finding error removed, worst condition and path";
  p.x_label = "service chamber hours (test sweep left out)";
  p.y_label = "% (below -100 drawn at -100)";
  Series median{"worst median", {}, {}, true, false, true};
  Series p10{"worst 10th pct", {}, {}, true, false, true};
  Series front{"front", {}, {}, true, false, false};
  // The whole goal, none worse than raw included, which the two lines alone do not show.
  Series meets{"meets the goal", {}, {}, true, false, false};
  double most = budget_hours;
  for (const sim::PricedProtocol& q : priced) {
    median.x.push_back(q.service_hours);
    median.y.push_back(floored(q.worst_median_pct));
    p10.x.push_back(q.service_hours);
    p10.y.push_back(floored(q.worst_p10_pct));
    if (q.on_front) {
      front.x.push_back(q.service_hours);
      front.y.push_back(floored(q.worst_p10_pct));
    }
    if (q.meets_goal) {
      meets.x.push_back(q.service_hours);
      meets.y.push_back(floored(q.worst_p10_pct));
    }
    most = std::max(most, q.service_hours);
  }
  p.series = {median, p10, front, meets};
  p.series.push_back({"goal 85 %", {0, most}, {85, 85}, false, true, false});
  p.series.push_back({"goal 60 %", {0, most}, {60, 60}, false, true, false});
  p.series.push_back(
      {"budget", {budget_hours, budget_hours}, {kFloorPct, 100}, false, true, false});
  return Figure{"protocol_front", "Calibration protocols against their chamber hours", {p}};
}

}  // namespace fogdrift::report
