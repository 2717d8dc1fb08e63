// The front figure holds every priced protocol, the front's points, those meeting the whole goal
// and the goal's lines.
#include "fogdrift/report/protocol_figure.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace fogdrift::report {
namespace {

TEST(ProtocolFigure, EveryProtocolAndTheFront) {
  const std::vector<sim::Approach> all(sim::kServiceConditions.begin(),
                                       sim::kServiceConditions.end());
  const auto priced = sim::price_protocols(sim::Instrument{}, sim::ChamberOptions{}, all);
  const Figure f = protocol_front_figure(priced, 60);
  EXPECT_EQ(f.name, "protocol_front");
  ASSERT_EQ(f.panels.size(), 1u);
  const auto& s = f.panels[0].series;
  ASSERT_EQ(s.size(), 7u);
  ASSERT_EQ(s[1].x.size(), priced.size());
  std::size_t on_front = 0;
  std::vector<double> meeting;
  for (std::size_t i = 0; i < priced.size(); ++i) {
    if (priced[i].meets_goal) meeting.push_back(priced[i].service_hours);
    EXPECT_EQ(s[0].y[i], std::max(-100.0, priced[i].worst_median_pct));
    EXPECT_EQ(s[1].x[i], priced[i].service_hours);
    EXPECT_EQ(s[1].y[i], std::max(-100.0, priced[i].worst_p10_pct));
    on_front += priced[i].on_front ? 1 : 0;
  }
  EXPECT_EQ(s[2].x.size(), on_front);
  EXPECT_TRUE(std::is_sorted(s[2].y.begin(), s[2].y.end()));  // the front only rises
  // Only the protocols meeting the whole goal: the seven sweeps, not the five, which leave an
  // instrument's warm start-ups worse than raw with 10th percentiles above the goal's line.
  EXPECT_EQ(s[3].x, meeting);
  EXPECT_FALSE(meeting.empty());
  EXPECT_LT(meeting.size(), priced.size());
  EXPECT_EQ(s[6].x, (std::vector<double>{60, 60}));
  EXPECT_NE(to_json(f).find("\"worst 10th pct\""), std::string::npos);
}

}  // namespace
}  // namespace fogdrift::report
