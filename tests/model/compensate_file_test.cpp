// A recording file compensated: the input's fields as written, then each axis's four columns,
// equal to the batch prediction; refusals leave nothing written.
#include "fogdrift/model/compensate_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/train.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

struct Trained {
  ModelSet set;
  Recording test;
};

const Trained& trained() {
  static const Trained t = [] {
    sim::CalibrationOptions co;
    co.temps_degc = {-20, 30};
    co.repetitions = 2;
    co.powered_s = 600;
    const sim::SimulatedCampaign sc = sim::simulate_calibration(sim::Instrument{}, co);
    DatasetOptions dataset;
    TrainOptions o;
    o.method = Method::poly;
    Trained out;
    out.set.models.push_back(
        train(build_dataset(recording_inputs(sc.campaign, sc.recordings, std::nullopt), dataset),
              dataset, o)
            .model);
    out.test = sc.recordings.back();
    return out;
  }();
  return t;
}

TEST(CompensateFile, CopiesTheFieldsAndAddsEachAxissColumns) {
  test::TempDir dir;
  const Trained& t = trained();
  const auto input = dir.path() / "in.csv";
  const std::string text = to_csv(t.test);
  test::write_file(input, text);
  const auto output = dir.path() / "out.csv";
  const std::vector<CompensatedAxis> axes = compensate_file(t.set, input, output, {});
  ASSERT_EQ(axes.size(), 1U);
  EXPECT_EQ(axes[0].columns,
            (std::vector<std::string>{"drift_dph", "gyro_comp_dph", "novelty", "guard_weight"}));
  const RecordingPrediction p = t.set.models[0].predict(t.test, true);
  EXPECT_EQ(axes[0].prediction.drift_dph, p.drift_dph);
  std::istringstream lines(test::read_file(output));
  std::istringstream original(text);
  std::string line, before;
  std::size_t i = 0;
  std::getline(lines, line);
  std::getline(original, before);
  EXPECT_EQ(line, before + ",drift_dph,gyro_comp_dph,novelty,guard_weight");
  while (std::getline(lines, line) && std::getline(original, before)) {
    EXPECT_EQ(line.substr(0, before.size() + 1), before + ",");
    const std::string drift =
        line.substr(before.size() + 1, line.find(',', before.size() + 1) - before.size() - 1);
    EXPECT_EQ(*csv::parse_number(drift), p.drift_dph[i]) << "row " << i;
    const std::size_t comp_at = line.find(',', before.size() + 1) + 1;
    const std::string comp = line.substr(comp_at, line.find(',', comp_at) - comp_at);
    EXPECT_EQ(*csv::parse_number(comp), t.test.gyro_dph[i] - p.drift_dph[i]) << "row " << i;
    ++i;
  }
  EXPECT_EQ(i, t.test.size());
  EXPECT_EQ(
      compensated_columns("gyro_y_dph"),
      (std::vector<std::string>{"drift_y_dph", "gyro_y_comp_dph", "novelty_y", "guard_weight_y"}));
}

TEST(CompensateFile, RefusesAFileAlreadyCompensatedAndWritesNothing) {
  test::TempDir dir;
  const Trained& t = trained();
  const auto input = dir.path() / "in.csv";
  test::write_file(input, to_csv(t.test));
  compensate_file(t.set, input, dir.path() / "once.csv", {});
  try {
    compensate_file(t.set, dir.path() / "once.csv", dir.path() / "twice.csv", {});
    FAIL() << "compensated twice";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1U);
    EXPECT_NE(e.message().find("already has a drift_dph column"), std::string::npos);
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "twice.csv"));
}

}  // namespace
}  // namespace fogdrift
