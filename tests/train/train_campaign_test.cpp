// Training on a campaign folder (train_campaign.hpp): the same model as training its dataset
// directly, every data file's SHA-256 in the provenance, the choices it reports, its errors.
#include "fogdrift/train/train_campaign.hpp"

#include <gtest/gtest.h>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/sha256.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "test_util.hpp"

namespace fogdrift {
namespace {

sim::SimulatedCampaign small_campaign() {
  sim::CalibrationOptions o;
  o.temps_degc = {-20, 10, 40};
  o.repetitions = 2;
  o.powered_s = 900;
  o.seed = 4;
  return sim::simulate_calibration(sim::Instrument{}, o);
}

CampaignTrainOptions svr_options() {
  CampaignTrainOptions o;
  o.train.method = Method::svr;
  return o;
}

TEST(TrainCampaign, TrainsTheCampaignsTrainingRecordingsAndRecordsTheirDigests) {
  test::TempDir dir;
  const auto sc = small_campaign();
  sim::write_campaign(dir.path() / "cal", sc, false);
  const Campaign campaign = read_campaign(dir.path() / "cal");
  const CampaignTrainResult r = train_campaign(campaign, svr_options());
  EXPECT_TRUE(r.notes.empty());  // three thermometers at the default sampling: nothing to say
  // The same model as building the dataset with the resolved settings and training it.
  const Dataset direct = build_dataset(campaign, Role::train, Scenario::calibration, r.dataset);
  TrainResult expected = train(direct, r.dataset, svr_options().train);
  expected.model.provenance.files = r.trained.model.provenance.files;
  EXPECT_EQ(to_json(r.trained.model), to_json(expected.model));
  EXPECT_EQ(r.data.rows, direct.rows);
  // campaign.json and each training recording, with its digest.
  const auto& files = r.trained.model.provenance.files;
  ASSERT_EQ(files.size(), 1 + r.data.groups.size());
  EXPECT_EQ(files[0].path, "campaign.json");
  for (const auto& f : files) EXPECT_EQ(f.sha256, sha256_file_hex(campaign.dir / f.path));
  EXPECT_EQ(r.data.groups.size(), 3u);  // one repetition of three temperatures trains
}

TEST(TrainCampaign, ReportsTheChoicesItMadeAndTheFieldBehindEach) {
  test::TempDir dir;
  auto sc = small_campaign();
  for (auto& rec : sc.recordings) rec.temp_acc2_degc.clear();  // a unit with two thermometers
  sim::write_campaign(dir.path() / "two", sc, false);
  CampaignTrainOptions o = svr_options();
  o.block_s = 30;
  const CampaignTrainResult r = train_campaign(read_campaign(dir.path() / "two"), o);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0].field, "features");
  EXPECT_EQ(r.notes[0].text.rfind("2 thermometers: features '", 0), 0u) << r.notes[0].text;
  EXPECT_EQ(r.dataset.preprocessing.block.block_s, 30);
  EXPECT_EQ(r.trained.model.inputs(), r.data.feature_names.size());

  // Features as given are kept, and a campaign with nothing to train on is an error.
  o.auto_features = false;
  o.dataset.features = FeatureSpec::parse("T(fog),dT(fog)");
  EXPECT_EQ(train_campaign(read_campaign(dir.path() / "two"), o).trained.model.inputs(), 2u);
  for (auto& entry : sc.campaign.recordings) entry.role = Role::test;
  sim::write_campaign(dir.path() / "none", sc, false);
  EXPECT_THROW(train_campaign(read_campaign(dir.path() / "none"), o), InputError);
}

TEST(TrainCampaign, ACampaignInMemoryGivesTheWrittenCampaignsModelByteForByte) {
  test::TempDir dir;
  const auto sc = small_campaign();
  sim::write_campaign(dir.path() / "cal", sc, false);
  const CampaignTrainResult on_disk =
      train_campaign(read_campaign(dir.path() / "cal"), svr_options());
  // The manifest as text, its recordings never written: the digests are of the files they
  // would be, so the model is the same.
  const Campaign held = campaign_from_json(manifest_json(sc.campaign), "campaign");
  EXPECT_TRUE(held.dir.empty());
  const CampaignTrainResult in_memory = train_campaign(held, sc.recordings, svr_options());
  EXPECT_EQ(to_json(in_memory.trained.model), to_json(on_disk.trained.model));

  auto fewer = sc.recordings;
  fewer.pop_back();
  try {
    train_campaign(held, fewer, svr_options());
    FAIL() << "a recording short was trained";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("6 recordings in its manifest and 5 given"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fogdrift
