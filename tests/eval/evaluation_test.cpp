// A model's Table 2 on a campaign (evaluation.hpp): the campaign's test recordings, metrics that
// pool as metrics.hpp says, the JSON `fogdrift evaluate --json` prints, and its errors.
#include "fogdrift/eval/evaluation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/train_campaign.hpp"
#include "test_util.hpp"

namespace fogdrift::eval {
namespace {

struct Trained {
  test::TempDir dir;
  Campaign campaign;
  CompensationModel model;
};

// A small calibration campaign on disk and an SVR model trained on its training recordings,
// made once for the suite.
class EvaluationTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    t_ = std::make_unique<Trained>();
    sim::CalibrationOptions o;
    o.temps_degc = {-20, 10, 40};
    o.repetitions = 2;
    o.powered_s = 900;
    o.seed = 6;
    sim::write_campaign(t_->dir.path() / "cal", sim::simulate_calibration({}, o), false);
    t_->campaign = read_campaign(t_->dir.path() / "cal");
    CampaignTrainOptions train;
    train.train.method = Method::svr;
    t_->model = train_campaign(t_->campaign, train).trained.model;
  }
  static void TearDownTestSuite() { t_.reset(); }
  static const Trained& trained() { return *t_; }

 private:
  static std::unique_ptr<Trained> t_;
};

std::unique_ptr<Trained> EvaluationTest::t_;

TEST_F(EvaluationTest, TakesTheCampaignsTestRecordingsAndPoolsTheirMetrics) {
  const Trained& t = trained();
  const Evaluation e = evaluate(t.model, t.campaign, {.guarded = true, .allan = true});
  ASSERT_EQ(e.recordings.size(), 3u);  // the last repetition of three temperatures
  EXPECT_EQ(e.method, "svr");
  EXPECT_TRUE(e.simulated);
  std::vector<CompensationMetrics> per;
  std::size_t rows = 0;
  for (const RecordingEvaluation& r : e.recordings) {
    EXPECT_EQ(r.info.role, Role::test);
    EXPECT_EQ(r.info.repetition, 2);
    EXPECT_NEAR(r.duration_s, 899, 1e-9);
    ASSERT_TRUE(r.allan.has_value());
    EXPECT_GT(r.allan->raw.arw_deg_per_rt_h, 0);
    EXPECT_EQ(r.novelty.samples, 900u);
    per.push_back(r.metrics);
    rows += r.metrics.rows;
  }
  EXPECT_EQ(rows, e.rows);
  const CompensationMetrics all = pool(per);
  EXPECT_EQ(e.overall.std_after_dph, all.std_after_dph);
  EXPECT_EQ(e.overall.mae_dph, all.mae_dph);
  EXPECT_LT(e.overall.std_after_dph, e.overall.std_before_dph);  // the model helps
  // Without the guard the correction is the model's everywhere: never less applied.
  const Evaluation full = evaluate(t.model, t.campaign, {.guarded = false});
  EXPECT_FALSE(full.guarded);
  EXPECT_FALSE(full.recordings[0].allan.has_value());
}

TEST_F(EvaluationTest, WritesTheJsonOfTheCommandLine) {
  const Trained& t = trained();
  const Evaluation e = evaluate(t.model, t.campaign, {.guarded = true, .allan = true});
  const auto j = nlohmann::json::parse(to_json(e, "m.json", "cal"));
  EXPECT_EQ(j["model"], "m.json");
  EXPECT_EQ(j["source"], "cal");
  EXPECT_EQ(j["guard"], true);
  EXPECT_EQ(j["overall"]["std_compensated_dph"].get<double>(), e.overall.std_after_dph);
  ASSERT_EQ(j["recordings"].size(), 3u);
  const auto& r = j["recordings"][1];
  EXPECT_EQ(r["file"], e.recordings[1].info.file);
  EXPECT_EQ(r["rows"].get<std::size_t>(), e.recordings[1].metrics.rows);
  EXPECT_EQ(r["allan"]["raw"]["arw_deg_per_rt_h"].get<double>(),
            e.recordings[1].allan->raw.arw_deg_per_rt_h);
  EXPECT_GE(r["novelty_outside_share"].get<double>(), 0.0);
  EXPECT_TRUE(j["warnings"].is_array());
}

TEST_F(EvaluationTest, ARecordingWithoutAThermometerTheModelReadsIsAnErrorNamingIt) {
  const Trained& t = trained();
  std::vector<RecordingInput> inputs = read_inputs(t.campaign, Role::test);
  for (auto& in : inputs) in.recording.temp_acc2_degc.clear();
  try {
    evaluate(t.model, inputs, {}, "unit7.json");
    FAIL() << "a recording without temp_acc2_degc was evaluated";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(inputs[0].recording.source), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("has no temp_acc2_degc column"), std::string::npos)
        << e.what();
  }
}

TEST_F(EvaluationTest, JudgesTheModelBesideItsBaselinesFromItsFile) {
  const Trained& t = trained();
  // The model file keeps the training rows' ranges and line, and reads them back exactly.
  ASSERT_TRUE(t.model.baselines.has_ranges());
  ASSERT_TRUE(t.model.baselines.line.has_value());
  EXPECT_EQ(t.model.baselines.line->input, "T_fog_degc");
  const CompensationModel back = compensation_model_from_json(to_json(t.model), "m.json");
  EXPECT_EQ(back.baselines.input_min, t.model.baselines.input_min);
  EXPECT_EQ(back.baselines.input_max, t.model.baselines.input_max);
  EXPECT_EQ(back.baselines.line->slope, t.model.baselines.line->slope);
  const Evaluation e = evaluate(t.model, t.campaign);
  EXPECT_EQ(e.line_input, "T_fog_degc");
  EXPECT_TRUE(e.ranges_known);
  for (const RecordingEvaluation& r : e.recordings) {
    // The simulated unit's drift is no line in T: the model beats all three, on every recording.
    EXPECT_TRUE(r.baselines.harms.empty()) << r.info.file;
    EXPECT_LT(r.baselines.model_rmse, r.baselines.line_rmse);
    EXPECT_LT(r.baselines.model_std, r.baselines.raw_std);
    // The comparison's model RMSE is the metrics' own.
    EXPECT_NEAR(r.baselines.model_rmse, r.metrics.rmse_dph, 1e-12 * r.metrics.rmse_dph);
    EXPECT_NEAR(r.baselines.raw_std, r.metrics.std_before_dph, 1e-12 * r.metrics.std_before_dph);
    // The held-out temperatures lie inside the training ranges (-20, 10 and 40 °C each twice).
    ASSERT_FALSE(r.extrapolation.empty());
    EXPECT_EQ(r.extrapolation[0].input, t.model.feature_names[0]);
  }
  EXPECT_EQ(verdict(e), "beats its baselines");
  const auto j = nlohmann::json::parse(to_json(e, "m.json", "cal"));
  EXPECT_EQ(j["verdict"], "beats its baselines");
  EXPECT_EQ(j["baselines"]["line_input"], "T_fog_degc");
  EXPECT_TRUE(j["recordings"][0]["baselines"].contains("line_rmse_dph"));
  EXPECT_TRUE(j["recordings"][0].contains("extrapolation"));

  // A model the evaluation's recordings make worse is flagged: its drift turned upside down.
  CompensationModel upside_down = t.model;
  upside_down.y_scaler.scale[0] = -upside_down.y_scaler.scale[0];
  const Evaluation bad = evaluate(upside_down, t.campaign, {.guarded = false});
  EXPECT_EQ(verdict(bad), "harms");
  EXPECT_EQ(bad.harmed.size(), 3u);

  // A file whose baselines were edited to nonsense is refused, naming the field.
  auto refused_field = [&](const std::string& from, const std::string& to) -> std::string {
    std::string text = to_json(t.model);
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    try {
      compensation_model_from_json(text, "m.json", {.allow_edited = true});
    } catch (const InputError& err) {
      return err.what();
    }
    return "";
  };
  EXPECT_NE(refused_field("\"input\": \"T_fog_degc\"", "\"input\": \"T_air_degc\"")
                .find("baselines.line.input"),
            std::string::npos);
  EXPECT_NE(refused_field("\"input_max\": [", "\"input_max\": [-1e30,").find("baselines"),
            std::string::npos);
}

}  // namespace
}  // namespace fogdrift::eval
