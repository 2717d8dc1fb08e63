// The population of instruments: seeded, inside its documented ranges, drawn as documented (a
// log-uniform range has its median at the geometric mean of its ends), and with the default
// instrument an ordinary member.
#include "fogdrift/sim/population.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fogdrift/sim/fog_error_model.hpp"

namespace fogdrift::sim {
namespace {

double value_of(Instrument& in, const std::string& path) {
  for (const auto& f : instrument_fields(in))
    if (f.path == path) return *f.value;
  ADD_FAILURE() << "no field " << path;
  return 0;
}

TEST(Population, SameSeedAndIndexSameInstrumentWhateverWasDrawnBefore) {
  const std::string third = to_json(draw_instrument(7, 3));
  for (int i = 1; i <= 5; ++i) draw_instrument(7, static_cast<std::uint64_t>(i));
  EXPECT_EQ(to_json(draw_instrument(7, 3)), third);
  EXPECT_NE(to_json(draw_instrument(7, 4)), third);
  EXPECT_NE(to_json(draw_instrument(8, 3)), third);
}

TEST(Population, EveryDrawIsValidAndInsideItsRanges) {
  for (std::uint64_t i = 1; i <= 50; ++i) {
    Instrument in = draw_instrument(1, i);
    EXPECT_NO_THROW(validate(in));
    for (const PopulationRange& r : population_ranges()) {
      const double v = value_of(in, r.path);
      EXPECT_GE(v, r.low) << r.path;
      EXPECT_LE(v, r.high) << r.path;
    }
  }
}

TEST(Population, LogUniformRangesHaveTheirMedianAtTheGeometricMean) {
  // Over 801 draws the sample median of a log-uniform variable lies within ±0.05 of the middle of
  // its log range with overwhelming probability (σ of the median quantile ≈ 0.018).
  std::vector<double> housing, lag;
  for (std::uint64_t i = 1; i <= 801; ++i) {
    Instrument in = draw_instrument(2, i);
    housing.push_back(in.thermal.capacity_j_per_k[0]);
    lag.push_back(in.thermometer_fog.lag_s);
  }
  auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + 400, v.end());
    return v[400];
  };
  EXPECT_NEAR(std::log(median(housing) / 2000.0) / std::log(4.0), 0.0, 0.05);
  EXPECT_NEAR(std::log(median(lag) / std::sqrt(60.0)) / std::log(15.0), 0.0, 0.05);
}

TEST(Population, TheDefaultInstrumentIsAnOrdinaryMember) {
  const auto positions = default_positions();
  const auto& ranges = population_ranges();
  ASSERT_EQ(positions.size(), ranges.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    EXPECT_GE(positions[i], 0.0) << ranges[i].path;
    EXPECT_LE(positions[i], 1.0) << ranges[i].path;
    // A placement cannot be nearer the node than on it: the one range the default ends.
    if (ranges[i].path.ends_with("housing_share")) continue;
    EXPECT_GT(positions[i], 0.1) << ranges[i].path;
    EXPECT_LT(positions[i], 0.9) << ranges[i].path;
  }
}

TEST(Population, TheTableListsEveryRange) {
  const std::string table = population_table_markdown();
  for (const PopulationRange& r : population_ranges())
    EXPECT_NE(table.find("`" + r.path + "`"), std::string::npos) << r.path;
}

TEST(ThermalDrift, TermsOutsideThePapersFormInClosedForm) {
  FogParams f;
  f.filtered_rate_dph_per_kps = 12.0;
  f.electronics_dph_per_k = 0.002;
  const DriftTerms d = thermal_drift(f, 25.0, 0.0, 0.0, {0.01, 35.0});
  EXPECT_NEAR(d.filtered_dph, 0.12, 1e-15);
  EXPECT_NEAR(d.electronics_dph, 0.02, 1e-15);
  EXPECT_NEAR(d.total_dph(), 0.14, 1e-15);
  // Absent from the default instrument, whatever the hidden state.
  EXPECT_EQ(thermal_drift(FogParams{}, 25.0, 0.0, 0.0, {1.0, 80.0}).total_dph(), 0.0);
}

}  // namespace
}  // namespace fogdrift::sim
