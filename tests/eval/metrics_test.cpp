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
  EXPECT_THROW(compensation_metrics(std::vector<double>{1}, std::vector<double>{1, 2}),
               std::invalid_argument);
}

}  // namespace
}  // namespace fogdrift::eval
