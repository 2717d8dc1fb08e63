// Kernel rows against LIBSVM's formula, and the kernel cache. The inner loops are tested in
// loops_test, rows in solver order and row memory in rows_test.
#include "fogdrift/svr/kernel.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <vector>

#include "fogdrift/base/random.hpp"
#include "svr/datasets.hpp"

namespace fogdrift::svr {
namespace {

TEST(KernelRows, MatchLibsvmsFormulaInDouble) {
  // The libsvm arithmetic gives LIBSVM's floats; the single one agrees with the exact kernel of
  // the float-rounded features to a few float steps (scored in float steps: loops_test).
  const Data d = testing::smooth(300, 5, 0.0, 2);
  const TrainingSet set(d);
  for (const Kernel k : {Kernel::rbf_sigma(0.8), Kernel::linear()}) {
    std::vector<float> row(d.rows), single(d.rows);
    int differ = 0;
    double worst_single = 0;
    for (std::size_t i = 0; i < d.rows; i += 13) {
      set.kernel_row(k, i, row.data());
      set.kernel_row(k, i, single.data(), KernelArithmetic::single);
      double sq_i = 0;
      for (std::size_t f = 0; f < d.cols; ++f) sq_i += d.row(i)[f] * d.row(i)[f];
      for (std::size_t j = 0; j < d.rows; ++j) {
        double dot = 0, sq_j = 0;
        for (std::size_t f = 0; f < d.cols; ++f) {
          dot += d.row(i)[f] * d.row(j)[f];
          sq_j += d.row(j)[f] * d.row(j)[f];
        }
        const double v =
            k.type == KernelType::linear ? dot : std::exp(-k.gamma * ((sq_i + sq_j) - 2 * dot));
        if (static_cast<float>(v) != row[j]) ++differ;
        EXPECT_NEAR(row[j], v, 1e-6);
        if (k.type == KernelType::linear) {
          EXPECT_EQ(single[j], row[j]);
        } else {
          double dist = 0;
          for (std::size_t f = 0; f < d.cols; ++f) {
            const double diff = static_cast<double>(static_cast<float>(d.row(i)[f])) -
                                static_cast<float>(d.row(j)[f]);
            dist += diff * diff;
          }
          const double y = -static_cast<float>(k.gamma) * dist;
          const double exact = std::exp(y);
          // Relative to a float step per unit of |y|, which multiplies the distance's rounding.
          worst_single = std::max(worst_single, std::fabs(single[j] - exact) / exact / (1.0 - y));
        }
      }
      if (k.type != KernelType::linear) {
        EXPECT_EQ(single[i], 1.0f);
        EXPECT_EQ(set.kernel_diagonal(k, i, KernelArithmetic::single), 1.0);
      }
    }
    EXPECT_LE(differ, 1);
    EXPECT_LT(worst_single, 5e-7);
  }
}

TEST(KernelRows, ThePointsOwnRowIsTheSamplesRow) {
  // A point equal to sample i gives sample i's row, float for float; any point, LIBSVM's formula.
  const Data d = testing::smooth(300, 5, 0.0, 2);
  const TrainingSet set(d);
  for (const Kernel k : {Kernel::rbf_sigma(0.8), Kernel::linear()}) {
    std::vector<float> of_point(d.rows), of_sample(d.rows);
    for (std::size_t i = 0; i < d.rows; i += 29) {
      set.kernel_row_of(k, d.row(i), of_point.data());
      set.kernel_row(k, i, of_sample.data());
      EXPECT_EQ(std::memcmp(of_point.data(), of_sample.data(), d.rows * sizeof(float)), 0);
    }
    const std::vector<double> x{0.3, -1.2, 0.5, 2.0, -0.1};
    set.kernel_row_of(k, x.data(), of_point.data());
    for (std::size_t j = 0; j < d.rows; j += 17) {
      double dot = 0, sq_x = 0, sq_j = 0;
      for (std::size_t f = 0; f < d.cols; ++f) {
        dot += x[f] * d.row(j)[f];
        sq_x += x[f] * x[f];
        sq_j += d.row(j)[f] * d.row(j)[f];
      }
      EXPECT_NEAR(
          of_point[j],
          k.type == KernelType::linear ? dot : std::exp(-k.gamma * ((sq_x + sq_j) - 2 * dot)),
          1e-6);
    }
  }
}

TEST(KernelRows, DistanceMatrixGivesTheSameRowsToFloatRounding) {
  // The matrix holds the float arithmetic's distances: its rows are that arithmetic's rows, float
  // for float; LIBSVM's arithmetic computes its rows from the features either way.
  const Data d = testing::smooth(200, 30, 0.0, 3);
  const TrainingSet direct(d, TrainingSet::Options{0, 24, nullptr});
  const TrainingSet with_distances(d);
  ASSERT_FALSE(direct.has_distances());
  ASSERT_TRUE(with_distances.has_distances());
  std::vector<float> a(d.rows), b(d.rows);
  for (double sigma : {1.0, 3.0, 10.0}) {
    const Kernel k = Kernel::rbf_sigma(sigma);
    for (std::size_t i = 0; i < d.rows; i += 17) {
      direct.kernel_row(k, i, a.data(), KernelArithmetic::single);
      with_distances.kernel_row(k, i, b.data(), KernelArithmetic::single);
      EXPECT_EQ(std::memcmp(a.data(), b.data(), d.rows * sizeof(float)), 0) << sigma;
      direct.kernel_row(k, i, a.data());
      with_distances.kernel_row(k, i, b.data());
      EXPECT_EQ(std::memcmp(a.data(), b.data(), d.rows * sizeof(float)), 0) << sigma;
    }
  }
}

TEST(KernelCache, EvictsTheLeastRecentlyUsedRow) {
  const Data d = testing::smooth(64, 2, 0.0, 4);
  const TrainingSet set(d);
  const double three_rows_mb = 3.0 * 64 * 4 / (1 << 20);
  KernelCache cache(set, Kernel::rbf_sigma(1.0), three_rows_mb);
  EXPECT_EQ(cache.capacity_rows(), 3u);
  cache.row(0);
  cache.row(1);
  cache.row(2);
  cache.row(0);  // 1 is now the oldest
  cache.row(3);  // evicts 1
  EXPECT_EQ(cache.rows_computed(), 4);
  cache.row(0);
  cache.row(2);
  EXPECT_EQ(cache.rows_computed(), 4);
  const float* r1 = cache.row(1);
  EXPECT_EQ(cache.rows_computed(), 5);
  std::vector<float> expect(64);
  set.kernel_row(Kernel::rbf_sigma(1.0), 1, expect.data());
  EXPECT_EQ(0, std::memcmp(r1, expect.data(), 64 * sizeof(float)));
}

}  // namespace
}  // namespace fogdrift::svr
