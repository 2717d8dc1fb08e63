// Reading text files: a folder is not a file; JSON nesting: every reader refuses arrays and objects
// nested deeper than kMaxJsonDepth, with the file, line and column, before the JSON library can
// recurse through them (docs/reliability.md, "JSON files").
#include "fogdrift/base/text_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <string>

#include "fogdrift/base/error.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/sim/instrument.hpp"

namespace fogdrift {
namespace {

std::string nested(std::size_t depth) {
  return std::string(depth, '[') + std::string(depth, ']');
}

std::string error_of(const std::function<void()>& read) {
  try {
    read();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ReadTextFile, AFolderIsSaidToBeOneNotReadAsAnEmptyFile) {
  const auto dir = std::filesystem::temp_directory_path();
  EXPECT_EQ(error_of([&] { read_text_file(dir); }), dir.string() + ": is a folder, not a file");
  // A campaign folder given where a model file belongs (fogdrift evaluate CAMPAIGN MODEL).
  EXPECT_NE(error_of([&] { load_compensation_model(dir); }).find("is a folder, not a file"),
            std::string::npos);
}

TEST(JsonNesting, SixtyFourLevelsPassAndTheSixtyFifthIsNamed) {
  EXPECT_NO_THROW(check_json_nesting("a.json", "{\"x\": " + nested(kMaxJsonDepth - 1) + "}"));
  const std::string deep = "{\n \"x\": " + nested(kMaxJsonDepth) + "}";
  // The 65th level, counting the outer brace: the 64th "[", line 2, column 6 + 64.
  EXPECT_EQ(error_of([&] { check_json_nesting("a.json", deep); }),
            "a.json:2:70: invalid JSON: arrays and objects nested deeper than 64 levels; no "
            "fogdrift file needs more");
}

TEST(JsonNesting, BracketsInsideStringsDoNotCount) {
  const std::string text = "{\"notes\": \"" + std::string(1000, '[') + "\\\"" +
                           std::string(1000, '{') + "\", \"n\": [1, {\"a\": []}]}";
  EXPECT_NO_THROW(check_json_nesting("a.json", text));
}

// Found by attack (issue 36, "crash"): 100,000 nested brackets in a campaign's notes overflowed
// the stack when the notes were written back out. Every reader now refuses them first.
TEST(JsonNesting, EveryReaderRefusesADeeplyNestedFile) {
  const std::string bomb = nested(100000);
  const std::string campaign =
      "{\"format\": \"fogdrift-campaign\", \"latitude_deg\": 30, \"notes\": " + bomb +
      ", \"recordings\": []}";
  EXPECT_NE(
      error_of([&] { campaign_from_json(campaign, "campaign.json"); }).find("campaign.json:1:"),
      std::string::npos);
  EXPECT_NE(error_of([&] {
              compensation_model_from_json(
                  "{\"format\": \"fogdrift-compensation-model\", \"x\": " + bomb + "}", "m.json");
            }).find("m.json:1:111: invalid JSON: arrays and objects nested deeper"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              sim::instrument_from_json("{\"fog\": " + bomb + "}", "i.json");
            }).find("i.json:1:72: invalid JSON: arrays and objects nested deeper"),
            std::string::npos);
}

}  // namespace
}  // namespace fogdrift
