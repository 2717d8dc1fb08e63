#include "fogdrift/sim/instrument.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"

namespace fogdrift::sim {
namespace {

std::string message_of(const std::string& json) {
  try {
    instrument_from_json(json, "unit.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Instrument, DefaultsAreValidAndRoundTripThroughJson) {
  Instrument in;
  EXPECT_NO_THROW(validate(in));
  in.fog.arw_deg_per_rth = 0.00123456789012345;
  in.thermal.capacity_j_per_k[3] = 321.5;
  const Instrument back = instrument_from_json(to_json(in), "x.json");
  EXPECT_EQ(to_json(back), to_json(in));
  EXPECT_EQ(back.fog.arw_deg_per_rth, 0.00123456789012345);
}

TEST(Instrument, PartialFileKeepsOtherDefaults) {
  const Instrument in = instrument_from_json(R"({"fog": {"bias_dph": 0.5}})", "x.json");
  EXPECT_EQ(in.fog.bias_dph, 0.5);
  EXPECT_EQ(in.fog.arw_deg_per_rth, Instrument{}.fog.arw_deg_per_rth);
}

TEST(Instrument, BadFilesNameTheParameterAndTheRule) {
  EXPECT_NE(message_of(R"({"fog": {"arw": 1}})").find("unit.json: fog.arw: unknown parameter"),
            std::string::npos);
  EXPECT_NE(message_of(R"({"fog": {"arw_deg_per_rth": "big"}})").find("must be a number"),
            std::string::npos);
  EXPECT_NE(message_of(R"({"thermal": {"capacity_j_per_k": {"housing": -1}}})")
                .find("instrument.thermal.capacity_j_per_k.housing: -1 is outside (0"),
            std::string::npos);
  EXPECT_NE(message_of(R"({"format": "other/2"})").find("format"), std::string::npos);
  EXPECT_NE(message_of("{ nope").find("invalid JSON"), std::string::npos);
  // Found by fuzzing: a number beyond a double escaped as the JSON library's exception.
  EXPECT_NE(
      message_of(R"({"fog": {"bias_dph": 1e999}})")
          .find("unit.json:1:22: invalid JSON: the number 1e999 is beyond the range of a double"),
      std::string::npos)
      << message_of(R"({"fog": {"bias_dph": 1e999}})");
}

// Found by fuzzing: the empty document is every default (it used to fail on an empty path).
TEST(Instrument, EmptyDocumentIsTheDefaults) {
  const Instrument in = instrument_from_json("{}", "x.json");
  EXPECT_EQ(in.fog.bias_dph, Instrument{}.fog.bias_dph);
}

TEST(Instrument, ParameterTableListsEveryField) {
  Instrument in;
  const std::string table = parameter_table_markdown();
  for (const auto& f : instrument_fields(in)) {
    EXPECT_NE(table.find("`" + f.path + "`"), std::string::npos) << f.path;
  }
}

}  // namespace
}  // namespace fogdrift::sim
