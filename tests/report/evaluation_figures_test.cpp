// A user's own evaluation drawn (evaluation_figures.hpp): the figures' series are the
// evaluation's rows, and what a model lacks leaves its figure out.
#include "fogdrift/report/evaluation_figures.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fogdrift::report {
namespace {

eval::Evaluation two_rows() {
  eval::Evaluation e;
  e.method = "poly";
  e.line_input = e.temperature_input = "T_fog_degc";
  e.rate_input = "dT_fog_degc_per_s";
  e.region_temperature = {10, 20};
  e.region_rate = {0.001, -0.001};
  eval::RecordingEvaluation r;
  r.info.file = "a.csv";
  r.series = eval::RecordingSeries{{60, 120},  {1.0, 2.0}, {0.9, 2.1},
                                   {1.5, 1.5}, {11, 12},   {0.0005, 0.0002}};
  r.baselines.harms = {"worse than raw"};
  e.recordings.push_back(r);
  e.harmed = {"a.csv"};
  return e;
}

TEST(EvaluationFigures, SeriesAreTheEvaluationsRows) {
  TrainingBaselines b;
  b.input_min = {0.0, -0.002};
  b.input_max = {30.0, 0.002};
  const std::vector<std::string> names = {"T_fog_degc", "dT_fog_degc_per_s"};
  const std::vector<Figure> f = evaluation_figures(two_rows(), b, names, "gyro_z_dph_");
  ASSERT_EQ(f.size(), 3u);
  EXPECT_EQ(f[0].name, "gyro_z_dph_recordings");
  EXPECT_NE(f[0].title.find("verdict: harms"), std::string::npos) << f[0].title;
  const Panel& rec = f[0].panels.at(0);
  EXPECT_NE(rec.title.find("HARMED"), std::string::npos);
  ASSERT_EQ(rec.series.size(), 3u);  // raw, after the line, after the model
  EXPECT_EQ(rec.series[0].x, (std::vector<double>{1.0, 2.0}));  // minutes
  EXPECT_EQ(rec.series[0].y, (std::vector<double>{1.0, 2.0}));
  EXPECT_NEAR(rec.series[1].y[0], -0.5, 1e-15);
  EXPECT_NEAR(rec.series[2].y[1], -0.1, 1e-15);
  EXPECT_EQ(f[1].name, "gyro_z_dph_residual_vs_T");
  EXPECT_EQ(f[1].panels[0].series[1].x, (std::vector<double>{11, 12}));
  EXPECT_EQ(f[2].name, "gyro_z_dph_region");
  const Panel& region = f[2].panels[0];
  EXPECT_EQ(region.series[0].y, (std::vector<double>{0.001, -0.001}));              // prototypes
  EXPECT_EQ(region.series[1].x, (std::vector<double>{0.0, 30.0, 30.0, 0.0, 0.0}));  // ranges
  EXPECT_TRUE(region.series[1].dashed);
  EXPECT_EQ(region.series[2].name, "a.csv");
}

TEST(EvaluationFigures, WhatTheModelLacksLeavesItsFigureOut) {
  eval::Evaluation e = two_rows();
  e.rate_input.clear();
  EXPECT_EQ(evaluation_figures(e, {}, {}, "").size(), 2u);  // no region without a rate
  e.temperature_input.clear();
  EXPECT_EQ(evaluation_figures(e, {}, {}, "").size(), 1u);
  e.recordings[0].series.reset();
  EXPECT_THROW(evaluation_figures(e, {}, {}, ""), std::invalid_argument);
}

}  // namespace
}  // namespace fogdrift::report
