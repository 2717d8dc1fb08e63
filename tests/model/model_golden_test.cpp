// Model files of every format version fogdrift has written load, and predict what they predicted
// when they were written, bit for bit (tests/data/models; docs/tuning.md, "The model file").
#include <gtest/gtest.h>

#include <array>
#include <filesystem>

#include "fogdrift/base/error.hpp"
#include "fogdrift/model/model.hpp"
#include "test_util.hpp"

#ifndef FOGDRIFT_TEST_DATA
#error "FOGDRIFT_TEST_DATA must name tests/data"
#endif

namespace fogdrift {
namespace {

const std::filesystem::path kModels = std::filesystem::path(FOGDRIFT_TEST_DATA) / "models";

// Feature rows in the spec's order (T ×3 °C, dT ×3 °C/s, grad ×3 °C): inside and outside the
// training region, so the guard's weight is exercised too.
constexpr std::array<std::array<double, 9>, 4> kRows = {{
    {0.5, 1.2, 0.9, 2e-3, 1.5e-3, 1.8e-3, -0.7, -0.4, 0.3},
    {20.3, 21.0, 20.8, 5e-4, 4e-4, 4.5e-4, -0.7, -0.5, 0.2},
    {41.0, 41.9, 41.5, 1e-4, 8e-5, 9e-5, -0.9, -0.5, 0.4},
    {-30.0, -28.0, -29.0, 1e-2, 1e-2, 1e-2, -2.0, -1.0, 1.0},
}};

// Drift and guarded drift of every row, °/h, as the version that wrote the file computed them.
using Expected = std::array<std::array<double, 2>, kRows.size()>;

void expect_predictions(const CompensationModel& m, const Expected& expected) {
  std::vector<double> work(m.inputs());
  for (std::size_t r = 0; r < kRows.size(); ++r) {
    const DriftPrediction p = m.predict(kRows[r], work);
    EXPECT_EQ(p.drift_dph, expected[r][0]) << "row " << r;
    EXPECT_EQ(m.guarded_dph(p.drift_dph, p.target_weight), expected[r][1]) << "row " << r;
  }
}

// Written by fogdrift 0.1.0 (format version 2, no checksum): BP on a 3-temperature campaign.
// With nothing to show whether it was edited, it loads only when the user says so.
TEST(ModelGolden, Version2BpLoadsAndPredictsAsWritten) {
  try {
    load_compensation_model(kModels / "bp_v2.json");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bp_v2.json: version: format version 2 carries no "
                                         "checksum"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("--allow-old-format"), std::string::npos) << e.what();
  }
  const CompensationModel m =
      load_compensation_model(kModels / "bp_v2.json", {.allow_old_format = true});
  expect_predictions(m, {{{-0.11121513549865335, -0.11121513549865335},
                          {-0.078817792715530077, -0.078817792715530077},
                          {-0.075606512049865987, -0.075606512049865987},
                          {-0.12048486650446188, -0.088543084360135568}}});
}

// Written by fogdrift 0.1.0 (format version 3, with its checksum): untuned SVR on the same
// campaign. Loading it checks the checksum.
TEST(ModelGolden, Version3SvrLoadsAndPredictsAsWritten) {
  const CompensationModel m = load_compensation_model(kModels / "svr_v3.json");
  expect_predictions(m, {{{-0.068716735962559963, -0.068716735962559963},
                          {-0.071589399346321594, -0.071589399346321594},
                          {-0.070285368200171255, -0.071182229593399954},
                          {-0.075945968218800924, -0.083416954658316181}}});
}

// Found by fuzzing: a count written as a float (7.7e80 prototypes) was converted to an integer
// type unchecked, which is undefined behaviour. It is now an error naming the field.
TEST(ModelGolden, ACountThatIsNotAWholeNumberIsRejected) {
  std::string text = test::read_file(kModels / "svr_v3.json");
  const std::string key = "\"prototypes\": ";
  const auto at = text.find(key);
  ASSERT_NE(at, std::string::npos);
  const auto end = text.find_first_of(",\n}", at + key.size());
  text.replace(at + key.size(), end - at - key.size(), "7.7e80");
  try {
    compensation_model_from_json(text, "edited.json", {true});
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("edited.json: guard"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("must be a whole number"), std::string::npos) << e.what();
  }
}

// Found by fuzzing: a number beyond a double is an error with its line and column.
TEST(ModelGolden, ANumberBeyondADoubleIsRejected) {
  try {
    compensation_model_from_json(
        "{\"format\": \"fogdrift-compensation-model\",\n\"version\": 3e999}", "m.json");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "m.json:2:12: invalid JSON: the number 3e999 is beyond the range of a double");
  }
}

}  // namespace
}  // namespace fogdrift
