#include "fogdrift/report/paper.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <functional>

#include <cmath>
#include <nlohmann/json.hpp>

#include "fogdrift/base/error.hpp"
#include "fogdrift/report/paper_report.hpp"

namespace fogdrift::report {
namespace {

// A small experiment: three calibration temperatures of three repetitions, 20 minutes powered,
// two north-finding temperatures, a tiny search and a short BP training. It keeps every
// structure of the full one and runs in seconds even under the sanitizers.
PaperOptions small_options() {
  PaperOptions o;
  o.seeds = 2;
  o.population = 5;
  o.iterations = 1;
  o.calibration.temps_degc = {0, 20, 40};
  o.calibration.repetitions = 3;
  o.calibration.powered_s = 1200;
  o.northfind.temps_degc = {10, 30};
  o.northfind.findings = 2;
  o.stable.findings = 2;
  o.stable.warmup_s = 600;
  o.mlp.max_epochs = 300;
  o.mlp.patience = 50;
  return o;
}

TEST(Paper, RunsEveryMethodOnEverySeedAndReportsIt) {
  ThreadPool pool(2);
  PaperOptions o = small_options();
  o.pool = &pool;
  const PaperResult r = run_paper(o);
  ASSERT_EQ(r.seeds.size(), 2u);
  EXPECT_EQ(r.seeds[0].seed, 1u);
  EXPECT_EQ(r.seeds[1].seed, 2u);
  for (const SeedRun& s : r.seeds) {
    ASSERT_EQ(s.methods.size(), std::size(kPaperMethods));
    EXPECT_GT(s.denoised_std_dph, 0.001);
    EXPECT_EQ(s.raw_rmse_deg.size(), 2u);
    EXPECT_GT(s.stable_rmse_deg, 0.0);
    // The simulator's true drift subtracted: the floor of every method, below raw.
    ASSERT_EQ(s.oracle_rmse_deg.size(), 2u);
    EXPECT_LT(s.oracle_mean_rmse_deg, s.raw_mean_rmse_deg);
    EXPECT_DOUBLE_EQ(s.oracle_mean_rmse_deg, (s.oracle_rmse_deg[0] + s.oracle_rmse_deg[1]) / 2);
    for (const MethodRun& m : s.methods) {
      EXPECT_EQ(m.rmse_deg.size(), 2u) << to_string(m.method);
      // Every model compensates part of the drift on the test repetition.
      EXPECT_LT(m.table2.std_after_dph, s.denoised_std_dph) << to_string(m.method);
      EXPECT_EQ(m.table2.std_before_dph, s.denoised_std_dph) << to_string(m.method);
      EXPECT_TRUE(std::isfinite(m.mean_rmse_deg)) << to_string(m.method);
    }
  }
  // The two seeds simulate different campaigns.
  EXPECT_NE(r.seeds[0].denoised_std_dph, r.seeds[1].denoised_std_dph);
  // Studies on the first seed: every calibration temperature, SSA-SVR and BP.
  ASSERT_EQ(r.loto.size(), 6u);
  EXPECT_EQ(r.loto[0].temp_degc, 0.0);
  EXPECT_EQ(r.loto[0].method, Method::ssa_svr);
  EXPECT_EQ(r.loto[1].method, Method::bp);
  for (const LotoRow& l : r.loto) {
    EXPECT_GT(l.denoised_std_dph, 0.0);
    EXPECT_GT(l.std_loto_dph, 0.0);
  }
  ASSERT_EQ(r.fitness.size(), 2u);
  EXPECT_EQ(r.fitness[0].fitness, tune::Fitness::cv);
  EXPECT_EQ(r.fitness[1].fitness, tune::Fitness::train);
  EXPECT_EQ(r.fitness[0].c, r.seeds[0].method(Method::ssa_svr).hyperparameter("C"));
  EXPECT_EQ(r.figures.size(), 5u);

  // The JSON follows the schema.
  const auto j = nlohmann::json::parse(paper_json(r));
  EXPECT_GT(j["table1"]["C"].get<double>(), 0.0);
  EXPECT_TRUE(j["table1"].contains("sigma_sd"));
  EXPECT_TRUE(j["table2"]["denoised"].contains("std_dph"));
  for (const Method method : kPaperMethods) {
    const std::string name = to_string(method);
    EXPECT_TRUE(j["table2"][name].contains("mae_dph")) << name;
    EXPECT_TRUE(j["table2"][name].contains("std_dph_sd")) << name;
    EXPECT_EQ(j["table3"][name]["rmse_deg"].size(), 2u) << name;
    EXPECT_TRUE(j["table3"][name].contains("mean_deg_sd")) << name;
  }
  EXPECT_EQ(j["table3"]["temps_degc"], nlohmann::json::array({10.0, 30.0}));
  EXPECT_EQ(j["table3"]["raw"]["rmse_deg"].size(), 2u);
  EXPECT_GT(j["stable_rmse_deg"].get<double>(), 0.0);
  EXPECT_EQ(j["seeds"], 2);
  EXPECT_GT(j["elapsed_s"].get<double>(), 0.0);
  EXPECT_FALSE(j["goals"].contains("ssa_northfind_halved"));  // restated (docs/paper.md)
  EXPECT_NEAR(j["goals"]["ssa_northfind_over_floor"].get<double>(),
              j["table3"]["ssa-svr"]["mean_deg"].get<double>() /
                  j["table3"]["oracle"]["mean_deg"].get<double>(),
              1e-12);
  EXPECT_EQ(j["table3"]["oracle"]["rmse_deg"].size(), 2u);
  EXPECT_NEAR(j["goals"]["true_drift_subtracted_over_raw"].get<double>(),
              j["table3"]["oracle"]["mean_deg"].get<double>() /
                  j["table3"]["raw"]["mean_deg"].get<double>(),
              1e-12);
  // The tuned SVR methods named as worse than BP are exactly those whose mean STD is above.
  nlohmann::json worse = nlohmann::json::array();
  for (const char* m : {"pso-svr", "gwo-svr", "ssa-svr"})
    if (j["table2"][m]["std_dph"].get<double>() > j["table2"]["bp"]["std_dph"].get<double>())
      worse.push_back(m);
  EXPECT_EQ(j["goals"]["tuned_svr_worse_than_bp"], worse);
  EXPECT_EQ(j["goals"]["tuned_svr_no_worse_than_bp"].get<bool>(), worse.empty());
  // The start-up conditions table: every approach, raw, floor and every method; the share SSA-SVR
  // removes is computed from them, and a method worse than raw is named.
  ASSERT_EQ(j["start_ups"].size(), 4u);
  for (const char* a : {"calibration", "soaked", "warm", "ramping"}) {
    const auto& x = j["start_ups"][a];
    const double raw = x["raw_mean_deg"], floor = x["floor_mean_deg"],
                 comp = x["ssa-svr"]["mean_deg"];
    EXPECT_NEAR(j["goals"]["ssa_removed_by_start_up"][a].get<double>(),
                (raw * raw - comp * comp) / (raw * raw - floor * floor), 1e-12)
        << a;
    for (const Method method : kPaperMethods) {
      const std::string m = to_string(method);
      // Finding by finding: the drift's own error, of which no model removes more than all.
      EXPECT_LE(x[m]["drift_error_removed"].get<double>(), 1.0) << m << " " << a;
      const bool worse_than_raw = x[m]["mean_deg"].get<double>() > raw;
      bool named = false;
      for (const auto& w : j["goals"]["worse_than_raw"])
        named = named || w == fmt::format("{} under {}", m, a);
      EXPECT_EQ(named, worse_than_raw) << m << " " << a;
    }
  }
  // The start-ups of the calibration approach are Table 3's own.
  EXPECT_NEAR(j["start_ups"]["calibration"]["raw_mean_deg"].get<double>(),
              j["table3"]["raw"]["mean_deg"].get<double>(), 1e-12);
  EXPECT_NEAR(j["start_ups"]["calibration"]["ssa-svr"]["mean_deg"].get<double>(),
              j["table3"]["ssa-svr"]["mean_deg"].get<double>(), 1e-12);
  // A mean is the mean of the per-seed values.
  const double s1 = j["per_seed"][0]["methods"]["bp"]["std_dph"];
  const double s2 = j["per_seed"][1]["methods"]["bp"]["std_dph"];
  EXPECT_NEAR(j["table2"]["bp"]["std_dph"].get<double>(), (s1 + s2) / 2, 1e-15);
  EXPECT_NEAR(j["table2"]["bp"]["std_dph_sd"].get<double>(), std::abs(s1 - s2) / std::sqrt(2.0),
              1e-15);

  // report.md puts the paper's numbers beside fogdrift's.
  const std::string md = paper_markdown(r);
  for (const char* s :
       {"## Table 1", "1.0520", "## Table 2", "0.0134", "0.0031", "## Table 3", "0.012",
        "Leave one temperature out", "Training-loss against", "![Fig. 1", "fig_northfind.png",
        "| true drift subtracted |", "times the floor", "## Start-up conditions", "| ssa-svr |",
        "No method worse than raw under any start-up condition"}) {
    EXPECT_NE(md.find(s), std::string::npos) << s;
  }
  // The paper's own Table 3 is shown only for its own temperatures.
  EXPECT_EQ(md.find("The paper's Table 3 at the same temperatures"), std::string::npos);
}

// A method beyond the paper's, from the registry, is a row of every table (docs/gp.md).
TEST(Paper, AnotherMethodIsARowOfEveryTable) {
  PaperOptions o = small_options();
  o.seeds = 1;
  o.studies = false;
  o.causal = false;
  o.methods = {Method::bp, Method::ssa_svr};  // the two the report needs: a short run
  const PaperResult paper = run_paper(o);
  o.methods.push_back(Method{"gp"});
  const PaperResult r = run_paper(o);
  // The paper's rows are the same with the row added.
  for (const MethodRun& m : paper.seeds[0].methods) {
    EXPECT_EQ(r.seeds[0].method(m.method).table2.std_after_dph, m.table2.std_after_dph);
    EXPECT_EQ(r.seeds[0].method(m.method).rmse_deg, m.rmse_deg);
  }
  ASSERT_EQ(r.seeds[0].methods.size(), 3u);
  const MethodRun& gp = r.seeds[0].method(Method{"gp"});
  EXPECT_LT(gp.table2.std_after_dph, r.seeds[0].denoised_std_dph);
  EXPECT_EQ(gp.rmse_deg.size(), 2u);
  EXPECT_EQ(gp.start_up_rmse_deg.size(), o.start_ups.size());
  EXPECT_GT(gp.hyperparameter("length_scale"), 0.0);
  const std::string md = paper_markdown(r);
  EXPECT_NE(md.find("| gp | "), std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(paper_json(r));
  EXPECT_TRUE(j.at("table2").contains("gp")) << j.at("table2").dump();
}

TEST(Paper, SameSeedSameResultWhateverTheThreads) {
  PaperOptions o = small_options();
  o.seeds = 1;
  o.studies = true;  // the fitness study's search runs beside the method tasks
  ThreadPool one(1), two(2);
  o.pool = &one;
  const PaperResult a = run_paper(o);
  o.pool = &two;
  const PaperResult b = run_paper(o);
  const SeedRun& sa = a.seeds[0];
  const SeedRun& sb = b.seeds[0];
  EXPECT_EQ(sa.denoised_std_dph, sb.denoised_std_dph);
  EXPECT_EQ(sa.raw_rmse_deg, sb.raw_rmse_deg);
  for (std::size_t k = 0; k < sa.methods.size(); ++k) {
    EXPECT_EQ(sa.methods[k].hyperparameters, sb.methods[k].hyperparameters);
    EXPECT_EQ(sa.methods[k].rmse_deg, sb.methods[k].rmse_deg);
    EXPECT_EQ(sa.methods[k].table2.std_after_dph, sb.methods[k].table2.std_after_dph);
  }
  ASSERT_EQ(a.fitness.size(), b.fitness.size());
  for (std::size_t k = 0; k < a.fitness.size(); ++k) {
    EXPECT_EQ(a.fitness[k].c, b.fitness[k].c);
    EXPECT_EQ(a.fitness[k].sigma, b.fitness[k].sigma);
    EXPECT_EQ(a.fitness[k].mean_rmse_deg, b.fitness[k].mean_rmse_deg);
  }
  ASSERT_EQ(a.loto.size(), b.loto.size());
  for (std::size_t k = 0; k < a.loto.size(); ++k)
    EXPECT_EQ(a.loto[k].std_loto_dph, b.loto[k].std_loto_dph);
}

// The library names its fields; the CLI's table maps them to flags (tests/cli/paper_test.sh).
TEST(Paper, ImpossibleOptionsNameTheField) {
  auto expect_option = [](PaperOptions o, const std::string& option) {
    try {
      validate(o);
      ADD_FAILURE() << "accepted, expected an error for " << option;
    } catch (const OptionError& e) {
      EXPECT_EQ(e.option(), option) << e.what();
    }
  };
  // The defaults with one change, in fresh options each time (reassigning one struct drew GCC 12's
  // false maybe-uninitialized warnings).
  auto expect_field = [&](const std::function<void(PaperOptions&)>& change,
                          const std::string& option) {
    PaperOptions o;
    change(o);
    expect_option(o, option);
  };
  expect_field([](PaperOptions& o) { o.seeds = 0; }, "seeds");
  expect_field([](PaperOptions& o) { o.population = 3; }, "population");
  expect_field([](PaperOptions& o) { o.iterations = 0; }, "iterations");
  expect_field([](PaperOptions& o) { o.calibration.temps_degc = {}; }, "calibration.temps_degc");
  expect_field([](PaperOptions& o) { o.northfind.temps_degc = {500}; }, "northfind.temps_degc");
  expect_field([](PaperOptions& o) { o.northfind.findings = 0; }, "northfind.findings");
  expect_field([](PaperOptions& o) { o.calibration.repetitions = 1; }, "calibration.repetitions");
  expect_field([](PaperOptions& o) { o.epsilon = -0.1; }, "epsilon");
  expect_field([](PaperOptions& o) { o.methods = {Method::bp, Method::svr}; }, "methods");
  expect_field([](PaperOptions& o) { o.methods.push_back(Method::bp); }, "methods");
  // The folds against each scheme, on one set of options.
  PaperOptions o;
  o.cv.scheme = tune::CvScheme::temperature;
  o.cv.folds = 12;  // eleven calibration temperatures
  expect_option(o, "cv.folds");
  o.cv.folds = 11;
  EXPECT_NO_THROW(validate(o));
  o.cv.scheme = tune::CvScheme::recording;
  o.cv.folds = 45;  // 11 temperatures × 4 training repetitions
  expect_option(o, "cv.folds");
  expect_field(
      [](PaperOptions& p) {
        p.cv.scheme = tune::CvScheme::repetition;
        p.calibration.test_repetitions = 4;  // one training repetition left
      },
      "cv.scheme");
}

}  // namespace
}  // namespace fogdrift::report
