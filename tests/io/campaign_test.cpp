#include "fogdrift/io/campaign.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

TEST(Campaign, ManifestRoundTrip) {
  test::TempDir dir;
  test::write_file(dir / "a.csv", "x");
  test::write_file(dir / "b.csv", "x");
  Campaign c;
  c.latitude_deg = -33.5;
  c.generator_json = R"({"tool":"test","seed":3})";
  c.notes_json = R"("chamber B")";
  CampaignEntry a;
  a.file = "a.csv";
  a.scenario = Scenario::calibration;
  a.role = Role::train;
  a.repetition = 2;
  a.initial_temp_degc = -40;
  CampaignEntry b;
  b.file = "b.csv";
  b.scenario = Scenario::northfind;
  b.role = Role::test;
  b.initial_temp_degc = 17.25;
  b.true_azimuth_deg = 359.999;
  b.input_rate_dph = 1.5;
  b.references = {{"accel_z_g", 1.0}, {"sf_fog_ppm", -12.5}};
  c.recordings = {a, b};
  write_manifest(dir.path(), c);

  const Campaign back = read_campaign(dir.path());
  EXPECT_EQ(back.latitude_deg, -33.5);
  ASSERT_EQ(back.recordings.size(), 2u);
  EXPECT_EQ(back.recordings[0].repetition, 2);
  EXPECT_EQ(back.recordings[0].scenario, Scenario::calibration);
  EXPECT_FALSE(back.recordings[0].true_azimuth_deg.has_value());
  EXPECT_EQ(back.recordings[1].role, Role::test);
  EXPECT_EQ(*back.recordings[1].true_azimuth_deg, 359.999);
  EXPECT_EQ(*back.recordings[1].input_rate_dph, 1.5);
  EXPECT_TRUE(back.recordings[0].references.empty());
  EXPECT_EQ(back.recordings[1].references, b.references);
  EXPECT_EQ(back.path_of(back.recordings[1]), dir / "b.csv");
  EXPECT_EQ(manifest_json(back), test::read_file(dir / "campaign.json"));
  // The manifest path itself is accepted as well as the folder.
  EXPECT_EQ(read_campaign(dir / "campaign.json").recordings.size(), 2u);
}

TEST(Campaign, AManifestInMemoryIsCheckedAsAFileButNeedsNoRecordingFiles) {
  const std::string text =
      R"({"format":"fogdrift-campaign/1","latitude_deg":30,"recordings":[)"
      R"({"file":"nowhere/a.csv","scenario":"calibration","role":"train","initial_temp_degc":25}]})";
  const Campaign c = campaign_from_json(text, "campaign");
  ASSERT_EQ(c.recordings.size(), 1u);
  EXPECT_EQ(c.recordings[0].file, "nowhere/a.csv");
  EXPECT_TRUE(c.dir.empty());
  EXPECT_EQ(campaign_from_json(manifest_json(c), "campaign").recordings[0].file, "nowhere/a.csv");
  for (const auto& [bad, rule] : std::vector<std::pair<std::string, std::string>>{
           {R"({"recordings":[]})", "campaign: format: required field is missing"},
           {R"({"format":"fogdrift-campaign/1","recordings":[{"file":"a.csv"}]})",
            "recordings[0].scenario: required field is missing"},
           {"{", "campaign:1:"},
           {R"({"format":"fogdrift-campaign/1","recordings":[{"file":"a.csv","scenario":)"
            R"("calibration","role":"train","initial_temp_degc":25,"references":)"
            R"({"temp_fog_degc":0}}]})",
            "recordings[0].references: \"temp_fog_degc\" is not a target column"},
           {R"({"format":"fogdrift-campaign/1","recordings":[{"file":"a.csv","scenario":)"
            R"("calibration","role":"train","initial_temp_degc":25,"references":)"
            R"({"accel_x_g":"up"}}]})",
            "recordings[0].references.accel_x_g"}}) {
    try {
      campaign_from_json(bad, "campaign");
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(rule), std::string::npos) << e.what();
    }
  }
}

TEST(Campaign, MissingManifestNamesTheFile) {
  test::TempDir dir;
  try {
    read_campaign(dir.path());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("campaign.json: not found"), std::string::npos);
  }
}

TEST(Campaign, AzimuthMustBeBelow360) {
  test::TempDir dir;
  test::write_file(dir / "a.csv", "x");
  test::write_file(dir / "campaign.json",
                   R"({"format":"fogdrift-campaign/1","latitude_deg":30,"recordings":[)"
                   R"({"file":"a.csv","scenario":"stable","role":"test","initial_temp_degc":25,)"
                   R"("true_azimuth_deg":360}]})");
  try {
    read_campaign(dir.path());
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("recordings[0].true_azimuth_deg: 360 is outside [0, 360)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fogdrift
