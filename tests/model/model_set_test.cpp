// A model set: one model per gyro axis in one file, each model's own text and checksum kept.
#include "fogdrift/model/model_set.hpp"

#include <gtest/gtest.h>

#include <string>

#include "fogdrift/base/error.hpp"
#include "fogdrift/train/train.hpp"
#include "synthetic_dataset.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

/// A small polynomial model of the synthetic data, for the axis `target`.
CompensationModel model_for(const std::string& target, std::uint64_t seed) {
  TrainOptions o;
  o.method = Method::poly;
  DatasetOptions d = test::kDefaultDataset;
  d.target_column = target;
  return train(test::synthetic(seed), d, o).model;
}

ModelSet three_axes() {
  ModelSet set;
  set.models = {model_for("gyro_dph", 1), model_for("gyro_y_dph", 2), model_for("gyro_z_dph", 3)};
  return set;
}

std::string error_of(const std::string& text, const ModelLoadOptions& load = {}) {
  try {
    model_set_from_json(text, "set.json", load);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ModelSet, EveryModelReadsBackAsWrittenWithItsTargetColumn) {
  const ModelSet set = three_axes();
  const std::string text = to_json(set);
  const ModelSet back = model_set_from_json(text, "set.json");
  EXPECT_EQ(back.targets(), (std::vector<std::string>{"gyro_dph", "gyro_y_dph", "gyro_z_dph"}));
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(to_json(back.models[i]), to_json(set.models[i]));  // byte for byte
  EXPECT_EQ(to_json(back), text);
  // Each model is its own file inside the set, verbatim, checksum and all.
  for (const auto& m : set.models) {
    std::string own = to_json(m);
    own.pop_back();  // the final line end
    EXPECT_NE(text.find(own), std::string::npos);
  }
  // A gyro_dph model's file does not name its target, so files written before are unchanged;
  // another axis's does.
  EXPECT_EQ(to_json(set.models[0]).find("\"column\""), std::string::npos);
  EXPECT_NE(to_json(set.models[1]).find("\"column\": \"gyro_y_dph\""), std::string::npos);
  EXPECT_EQ(compensation_model_from_json(to_json(set.models[2]), "z.json").dataset.target_column,
            "gyro_z_dph");
}

TEST(ModelSet, APlainModelFileIsASetOfOne) {
  const std::string text = to_json(model_for("gyro_dph", 1));
  const ModelSet set = model_set_from_json(text, "model.json");
  ASSERT_EQ(set.models.size(), 1u);
  EXPECT_EQ(&choose_model(set, std::nullopt), &set.models[0]);
}

TEST(ModelSet, AnEditedModelInsideIsCaughtByItsOwnChecksum) {
  std::string text = to_json(three_axes());
  // Change one digit of the second model's drift scaler mean.
  const std::size_t second = text.find("\"column\": \"gyro_y_dph\"");
  const std::size_t at = text.find("\"drift_dph\": {", second);
  ASSERT_NE(at, std::string::npos);
  const std::size_t digit = text.find_first_of("123456789", text.find("\"mean\"", at));
  text[digit] = text[digit] == '9' ? '8' : static_cast<char>(text[digit] + 1);
  const std::string error = error_of(text);
  EXPECT_NE(error.find("set.json (models[1])"), std::string::npos) << error;
  EXPECT_NE(error.find("checksum"), std::string::npos) << error;
  EXPECT_EQ(error_of(text, {.allow_edited = true}), "(no error)");
}

TEST(ModelSet, TargetsThatDoNotMatchTheModelsAreRefused) {
  std::string text = to_json(three_axes());
  const std::string listed = R"(["gyro_dph","gyro_y_dph","gyro_z_dph"])";
  ASSERT_NE(text.find(listed), std::string::npos);
  std::string swapped = text;
  swapped.replace(swapped.find(listed), listed.size(), R"(["gyro_dph","gyro_z_dph","gyro_y_dph"])");
  EXPECT_NE(error_of(swapped).find("targets: lists gyro_dph, gyro_z_dph, gyro_y_dph but the models "
                                   "compensate gyro_dph, gyro_y_dph, gyro_z_dph"),
            std::string::npos);
  std::string newer = text;
  newer.replace(newer.find("\"version\": 1"), 12, "\"version\": 2");
  EXPECT_NE(error_of(newer).find("version: model set version 2 is not supported"),
            std::string::npos);
  std::string not_models = text;
  not_models.replace(not_models.find("\"models\": ["), 11, "\"models\": [1, ");
  EXPECT_NE(error_of(not_models).find("models: every element must be a model file"),
            std::string::npos);
  ModelSet twice;
  twice.models = {model_for("gyro_y_dph", 1), model_for("gyro_y_dph", 2)};
  EXPECT_THROW(to_json(twice), OptionError);
  EXPECT_THROW(to_json(ModelSet{}), OptionError);
}

TEST(ModelSet, ChoosingOneAxisNamesTheAxesThereAre) {
  const ModelSet set = three_axes();
  EXPECT_EQ(choose_model(set, "gyro_z_dph").dataset.target_column, "gyro_z_dph");
  try {
    choose_model(set, std::nullopt, "--target");
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "--target");
    EXPECT_NE(std::string(e.what()).find("3 axes (gyro_dph, gyro_y_dph, gyro_z_dph)"),
              std::string::npos);
  }
  EXPECT_THROW(choose_model(set, "gyro_q_dph"), OptionError);
}

}  // namespace
}  // namespace fogdrift
