#include "fogdrift/eval/metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace fogdrift::eval {
namespace {

// Hand-computed values.
TEST(CompensationMetrics, ClosedForm) {
  const std::vector<double> y{1, 2, 3, 4}, p{1.5, 2, 2, 4};  // residual 0.5·(−1), 0, 1, 0
  const CompensationMetrics m = compensation_metrics(y, p);
  EXPECT_EQ(m.rows, 4u);
  EXPECT_DOUBLE_EQ(m.mae_dph, 1.5 / 4);
  EXPECT_DOUBLE_EQ(m.rmse_dph, std::sqrt(1.25 / 4));
  EXPECT_DOUBLE_EQ(m.std_before_dph, std::sqrt(5.0 / 3));
  // residual −0.5, 0, 1, 0: mean 0.125, squares of deviations sum 1.1875
  EXPECT_DOUBLE_EQ(m.std_after_dph, std::sqrt(1.1875 / 3));
}

TEST(CompensationMetrics, OffsetsDoNotCountInTheStd) {
  const std::vector<double> y{1, 2, 3}, p{1.7, 2.7, 3.7};
  const CompensationMetrics m = compensation_metrics(y, p);
  EXPECT_NEAR(m.std_after_dph, 0, 1e-15);
  EXPECT_NEAR(m.mae_dph, 0.7, 1e-15);
}

TEST(CompensationMetrics, PoolsRecordings) {
  CompensationMetrics a, b;
  a.rows = 1, a.mae_dph = 1, a.rmse_dph = 1, a.std_before_dph = 3, a.std_after_dph = 1;
  b.rows = 3, b.mae_dph = 2, b.rmse_dph = 3, b.std_before_dph = 4, b.std_after_dph = 7;
  const std::vector<CompensationMetrics> v{a, b};
  const CompensationMetrics p = pool(v);
  EXPECT_EQ(p.rows, 4u);
  EXPECT_DOUBLE_EQ(p.mae_dph, 7.0 / 4);
  EXPECT_DOUBLE_EQ(p.rmse_dph, std::sqrt(28.0 / 4));
  EXPECT_DOUBLE_EQ(p.std_before_dph, std::sqrt(25.0 / 2));
  EXPECT_DOUBLE_EQ(p.std_after_dph, 5.0);
  // A recording without rows (a subset of a dataset keeps every group) does not dilute the STDs.
  const std::vector<CompensationMetrics> with_empty{a, CompensationMetrics{}, b};
  const CompensationMetrics q = pool(with_empty);
  EXPECT_EQ(q.rows, p.rows);
  EXPECT_EQ(q.std_before_dph, p.std_before_dph);
  EXPECT_EQ(q.std_after_dph, p.std_after_dph);
  EXPECT_EQ(q.mae_dph, p.mae_dph);
  EXPECT_THROW(compensation_metrics(std::vector<double>{1}, std::vector<double>{1, 2}),
               std::invalid_argument);
}

TEST(CompensationMetrics, PooledStdKeepsTheOffsetsBetweenRecordings) {
  // Two recordings, each flat before compensation but at different offsets.
  const std::vector<double> y1{1, 1, 1}, y2{-2, -2, -2, -2}, p1{1, 1, 1}, p2{0, 0, 0, 0};
  const std::vector<CompensationMetrics> v{compensation_metrics(y1, p1),
                                           compensation_metrics(y2, p2)};
  const CompensationMetrics p = pool(v);
  EXPECT_DOUBLE_EQ(p.std_before_dph, 0.0);  // Table 2's STD: offsets do not count
  // All seven rows pooled: 1,1,1,−2,−2,−2,−2 has mean −5/7; by hand, Σ(x − mean)² = 108/7.
  EXPECT_NEAR(p.pooled_std_before_dph, std::sqrt(108.0 / 7 / 6), 1e-15);
  // After: residuals 0,0,0,−2,−2,−2,−2: mean −8/7, Σ(x − mean)² = 48/7.
  EXPECT_NEAR(p.pooled_std_after_dph, std::sqrt(48.0 / 7 / 6), 1e-15);
  EXPECT_DOUBLE_EQ(p.mae_before_dph, 11.0 / 7);  // mean |y|
  EXPECT_DOUBLE_EQ(p.mae_dph, 8.0 / 7);
}

// Rows are grouped by recording, in the dataset's group order, whatever order the rows are in.
TEST(CompensationMetrics, PerRecordingFollowsTheGroups) {
  Dataset d;
  d.feature_names = {"x"};
  d.groups.resize(3);
  d.rows = 5;
  d.x = {0, 0, 0, 0, 0};
  d.y = {1, 10, 2, 20, 3};
  d.group = {0, 2, 0, 2, 0};
  const std::vector<double> predicted{1, 10, 1, 10, 1};
  const auto per = metrics_per_recording(d, predicted);
  ASSERT_EQ(per.size(), 3u);
  EXPECT_EQ(per[0].rows, 3u);
  EXPECT_EQ(per[1].rows, 0u);
  EXPECT_EQ(per[2].rows, 2u);
  EXPECT_DOUBLE_EQ(per[0].mae_dph, 1.0);         // residuals 0, 1, 2
  EXPECT_DOUBLE_EQ(per[2].mae_dph, 5.0);         // residuals 0, 10
  EXPECT_DOUBLE_EQ(per[0].std_before_dph, 1.0);  // 1, 2, 3
  EXPECT_THROW(metrics_per_recording(d, std::vector<double>{1}), std::invalid_argument);
}

}  // namespace
}  // namespace fogdrift::eval

namespace fogdrift::eval {
namespace {

// A drift ramp a·t: any two windows of P seconds, 2P apart, differ by 2aP exactly.
TEST(FindingMetrics, OppositeDifferenceOfARampIsTwiceItsRiseOverAPosition) {
  std::vector<double> t, r;
  for (int i = 0; i < 180; ++i) {
    t.push_back(5.0 + 10.0 * i);
    r.push_back(0.002 * t.back());
  }
  const auto [startup, opposite] = finding_metrics(t, r, {300.0, 90.0});
  EXPECT_NEAR(opposite, 2 * 0.002 * 90.0, 1e-12);
  EXPECT_GT(startup, 0.0);
}

// 1 °/h for the first 300 s of 1800 s, then 0: the mean is 1/6, so the first five minutes sit
// 5/6 above it.
TEST(FindingMetrics, StartupResidualIsTheFirstMinutesAgainstTheWholeMean) {
  std::vector<double> t, r;
  for (int i = 0; i < 180; ++i) {
    t.push_back(10.0 * i);
    r.push_back(t.back() < 300.0 ? 1.0 : 0.0);
  }
  EXPECT_NEAR(finding_metrics(t, r).first, 5.0 / 6.0, 1e-12);
  // Shorter than three positions: no opposite difference (n/a, not 0).
  EXPECT_TRUE(std::isnan(
      finding_metrics(std::span<const double>(t).first(20), std::span<const double>(r).first(20))
          .second));
  // Found by a new user (issue 32): a window that starts 51 minutes after power-on has no
  // start-up residual, and rows 305 s apart no opposite difference.
  std::vector<double> late = t, sparse;
  for (double& v : late) v += 51 * 60.0;
  EXPECT_TRUE(std::isnan(finding_metrics(late, r).first));
  for (int i = 0; i < 10; ++i) sparse.push_back(305.0 * i);
  EXPECT_TRUE(std::isnan(finding_metrics(sparse, std::span<const double>(r).first(10)).second));
  EXPECT_TRUE(std::isfinite(finding_metrics(sparse, std::span<const double>(r).first(10)).first));
}

TEST(FindingMetrics, PoolingSkipsRecordingsTheyDoNotApplyTo) {
  CompensationMetrics a, b;
  a.rows = b.rows = 10;
  a.startup_before_dph = 3.0;
  b.startup_before_dph = kNotApplicable;
  a.opposite_before_dph = b.opposite_before_dph = kNotApplicable;
  const std::vector<CompensationMetrics> both = {a, b};
  const CompensationMetrics p = pool(both);
  EXPECT_EQ(p.startup_before_dph, 3.0);
  EXPECT_TRUE(std::isnan(p.opposite_before_dph));
}

}  // namespace
}  // namespace fogdrift::eval
