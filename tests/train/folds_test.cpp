// Grouped folds (folds.hpp): which scheme `auto` picks, folds that never split a recording and
// span the temperatures, and splits standardised with their training rows only.
#include "fogdrift/train/folds.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "fogdrift/base/error.hpp"
#include "synthetic_dataset.hpp"

namespace fogdrift::tune {
namespace {

using test::synthetic;

// The automatic folds: k folds of whole temperatures when there are at least max(3, k)
// temperatures, else leave one repetition out (else recordings).
TEST(GroupedFolds, AutomaticFoldsAreTemperaturesWhenThereAreEnough) {
  const Dataset d = synthetic();
  std::set<double> temps;
  for (const auto& g : d.groups) temps.insert(g.initial_temp_degc);
  ASSERT_GE(temps.size(), 3u);
  const auto automatic = grouped_folds(d);
  const auto by_temperature = grouped_folds(d, {CvScheme::temperature, 3});
  ASSERT_EQ(automatic.size(), by_temperature.size());
  for (std::size_t f = 0; f < automatic.size(); ++f) {
    EXPECT_EQ(automatic[f].name, by_temperature[f].name);
    EXPECT_EQ(automatic[f].test_rows, by_temperature[f].test_rows);
  }
  // Two temperatures: leave one repetition out.
  std::vector<std::size_t> two;
  const double first = *temps.begin(), second = *std::next(temps.begin());
  for (std::size_t g = 0; g < d.groups.size(); ++g)
    if (d.groups[g].initial_temp_degc == first || d.groups[g].initial_temp_degc == second)
      two.push_back(g);
  const auto fallback = grouped_folds(d.select_groups(two));
  EXPECT_EQ(fallback.front().name, "repetition 1");
  // More folds asked than temperatures: repetitions too.
  EXPECT_EQ(grouped_folds(d, {CvScheme::automatic, temps.size() + 1}).front().name, "repetition 1");
}

TEST(GroupedFolds, LeaveOneRepetitionOutNeverSplitsARecording) {
  const Dataset d = synthetic();
  const auto folds = grouped_folds(d, {CvScheme::repetition});
  ASSERT_EQ(folds.size(), 3u);
  std::set<std::size_t> tested;
  for (std::size_t f = 0; f < 3; ++f) {
    EXPECT_EQ(folds[f].name, fmt::format("repetition {}", f + 1));
    EXPECT_EQ(folds[f].train_rows.size() + folds[f].test_rows.size(), d.rows);
    std::set<std::size_t> train_groups, test_groups;
    for (auto i : folds[f].train_rows) train_groups.insert(d.group[i]);
    for (auto i : folds[f].test_rows) {
      test_groups.insert(d.group[i]);
      EXPECT_EQ(d.groups[d.group[i]].repetition, static_cast<int>(f + 1));
      EXPECT_TRUE(tested.insert(i).second) << "row tested twice";
    }
    for (auto g : test_groups) EXPECT_FALSE(train_groups.contains(g));
  }
  EXPECT_EQ(tested.size(), d.rows);
}

TEST(GroupedFolds, RecordingFoldsSpanTheTemperatures) {
  const Dataset d = synthetic();
  CvOptions o;
  o.scheme = CvScheme::recording;
  o.folds = 3;
  const auto folds = grouped_folds(d, o);
  ASSERT_EQ(folds.size(), 3u);
  for (const Fold& f : folds) {
    std::set<double> temps;
    std::set<std::size_t> test_groups, train_groups;
    for (auto i : f.test_rows)
      temps.insert(d.groups[d.group[i]].initial_temp_degc), test_groups.insert(d.group[i]);
    for (auto i : f.train_rows) train_groups.insert(d.group[i]);
    EXPECT_EQ(temps.size(), 4u) << f.name;
    EXPECT_EQ(test_groups.size(), 4u) << f.name;
    for (auto g : test_groups) EXPECT_FALSE(train_groups.contains(g));
  }
  // One repetition only: automatic falls back to recording folds; repetition is an error.
  Dataset one = synthetic();
  for (auto& g : one.groups) g.repetition = 1;
  EXPECT_EQ(grouped_folds(one).size(), 3u);
  CvOptions rep;
  rep.scheme = CvScheme::repetition;
  EXPECT_THROW(grouped_folds(one, rep), OptionError);
  o.folds = 13;
  EXPECT_THROW(grouped_folds(d, o), OptionError);
}

TEST(GroupedFolds, TemperatureFoldsHoldOutWholeTemperatures) {
  const Dataset d = synthetic();  // temperatures -20, 0, 20, 40; three repetitions each
  CvOptions o;
  o.scheme = CvScheme::temperature;
  o.folds = 3;
  const auto folds = grouped_folds(d, o);
  ASSERT_EQ(folds.size(), 3u);
  // Dealt in turn: -20 and 40 in the first fold, 0 in the second, 20 in the third.
  const std::vector<std::set<double>> held = {{-20.0, 40.0}, {0.0}, {20.0}};
  EXPECT_EQ(folds[0].name, "temperatures -20,40 °C");
  EXPECT_EQ(folds[1].name, "temperatures 0 °C");
  std::set<std::size_t> tested;
  for (std::size_t f = 0; f < folds.size(); ++f) {
    std::set<double> test_temps, train_temps;
    for (auto i : folds[f].test_rows) {
      test_temps.insert(d.groups[d.group[i]].initial_temp_degc);
      EXPECT_TRUE(tested.insert(i).second) << "row tested twice";
    }
    for (auto i : folds[f].train_rows) train_temps.insert(d.groups[d.group[i]].initial_temp_degc);
    EXPECT_EQ(test_temps, held[f]) << folds[f].name;
    for (double t : test_temps) EXPECT_FALSE(train_temps.contains(t)) << folds[f].name;
    EXPECT_EQ(folds[f].train_rows.size() + folds[f].test_rows.size(), d.rows);
  }
  EXPECT_EQ(tested.size(), d.rows);
  o.folds = 5;  // only four temperatures
  try {
    grouped_folds(d, o);
    ADD_FAILURE() << "five folds of four temperatures accepted";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "folds");
    EXPECT_NE(std::string(e.what()).find("2 to 4"), std::string::npos) << e.what();
  }
}

TEST(ScaleSplit, StandardisesWithTrainingRowsOnly) {
  const Dataset d = synthetic();
  const auto folds = grouped_folds(d);
  const ScaledSplit s = scale_split(d, folds[0].train_rows, folds[0].test_rows);
  for (std::size_t c = 0; c < 3; ++c) {
    double sum = 0, ss = 0;
    for (std::size_t r = 0; r < s.train.rows; ++r) sum += s.train.row(r)[c];
    const double mean = sum / s.train.rows;
    for (std::size_t r = 0; r < s.train.rows; ++r) ss += std::pow(s.train.row(r)[c] - mean, 2);
    EXPECT_NEAR(mean, 0, 1e-12);
    EXPECT_NEAR(std::sqrt(ss / (s.train.rows - 1)), 1, 1e-12);
  }
  EXPECT_EQ(s.test.rows, folds[0].test_rows.size());
  // The test rows use the training statistics, not their own.
  const double raw = d.row(folds[0].test_rows[0])[1];
  EXPECT_DOUBLE_EQ(s.test.row(0)[1], (raw - s.x_scaler.mean[1]) / s.x_scaler.scale[1]);
}

}  // namespace
}  // namespace fogdrift::tune
