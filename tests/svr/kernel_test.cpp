// Kernel rows, the fast exponential and the vectorised selections, each against a plain
// reference computation.
#include "fogdrift/svr/kernel.hpp"

#include <gtest/gtest.h>

#include <thread>

#include <cfloat>
#include <cmath>
#include <cstring>

#include "fogdrift/random.hpp"
#include "svr/datasets.hpp"
#include "svr/loops.hpp"
#include "svr/row_arena.hpp"
#include "svr/smo_parts.hpp"

namespace fogdrift::svr {
namespace {

TEST(FastExp, RoundsToTheSameFloatAsStdExp) {
  Rng rng(3);
  int differ = 0;
  const int n = 200000;
  for (int k = 0; k < n; ++k) {
    const double x = -rng.uniform(0, 110);
    const float a = detail::exp_to_float(x);
    const float b = static_cast<float>(std::exp(x));
    if (a != b) {
      ++differ;
      // Only a double rounding near a float boundary can differ, by one float ulp.
      EXPECT_EQ(std::nextafter(a, b), b) << x;
    }
  }
  EXPECT_LE(differ, 2) << "of " << n;
  EXPECT_EQ(detail::exp_to_float(0.0), 1.0f);
  EXPECT_EQ(detail::exp_to_float(-800.0), 0.0f);
}

TEST(KernelRows, MatchLibsvmsFormulaInDouble) {
  const Data d = testing::smooth(300, 5, 0.0, 2);
  const TrainingSet set(d);
  for (const Kernel k : {Kernel::rbf_sigma(0.8), Kernel::linear()}) {
    std::vector<float> row(d.rows);
    int differ = 0;
    for (std::size_t i = 0; i < d.rows; i += 13) {
      set.kernel_row(k, i, row.data());
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
      }
    }
    EXPECT_LE(differ, 1);
  }
}

TEST(KernelRows, DistanceMatrixGivesTheSameRowsToFloatRounding) {
  const Data d = testing::smooth(200, 30, 0.0, 3);
  const TrainingSet direct(d, TrainingSet::Options{0, 24, nullptr});
  const TrainingSet with_distances(d);
  ASSERT_FALSE(direct.has_distances());
  ASSERT_TRUE(with_distances.has_distances());
  std::vector<float> a(d.rows), b(d.rows);
  for (double sigma : {1.0, 3.0, 10.0}) {
    const Kernel k = Kernel::rbf_sigma(sigma);
    for (std::size_t i = 0; i < d.rows; i += 17) {
      direct.kernel_row(k, i, a.data());
      with_distances.kernel_row(k, i, b.data());
      for (std::size_t j = 0; j < d.rows; ++j) EXPECT_NEAR(a[j], b[j], 1e-5) << sigma;
    }
  }
}

TEST(KernelRows, VectorisedRowsAreBitForBitThePortableOnes) {
  // The AVX2 and AVX-512 rows must give the floats the portable row gives, so that a fit takes
  // the same path on every processor: lengths around the vector widths, one and many features,
  // near and far points (e^x from 1 down to underflow), and distances from the matrix.
  using detail::Isa;
  Rng rng(11);
  int checked = 0;
  for (Isa isa : {Isa::avx2, Isa::avx512}) {
    if (!detail::available(isa)) continue;  // this processor lacks it
    SCOPED_TRACE(isa == Isa::avx2 ? "AVX2" : "AVX-512");
    for (const std::size_t d : {std::size_t{1}, std::size_t{9}, std::size_t{17}}) {
      for (const std::size_t n : {1, 3, 4, 7, 8, 9, 15, 16, 17, 100, 257}) {
        std::vector<double> x(n * d), xt(n * d), sq(n);
        for (std::size_t i = 0; i < n; ++i) {
          const double spread = i % 3 == 0 ? 1e-3 : (i % 3 == 1 ? 1.0 : 30.0);
          for (std::size_t f = 0; f < d; ++f) {
            x[i * d + f] = rng.normal() * spread;
            xt[f * n + i] = x[i * d + f];
            sq[i] += x[i * d + f] * x[i * d + f];
          }
        }
        std::vector<float> a(n), b(n), da(n), db(n), dist(n);
        for (const double gamma : {1e-3, 0.5, 20.0}) {
          for (std::size_t i = 0; i < n; i += 1 + n / 5) {
            detail::rbf_row_with(isa, &x[i * d], sq[i], xt.data(), n, sq.data(), n, d, gamma,
                                 a.data());
            detail::rbf_row_with(Isa::portable, &x[i * d], sq[i], xt.data(), n, sq.data(), n, d,
                                 gamma, b.data());
            ASSERT_EQ(0, std::memcmp(a.data(), b.data(), n * sizeof(float))) << n << " " << d;
            // Columns [begin, n) alone, read with the full row's stride: the same floats.
            const std::size_t begin = n / 3;
            std::vector<float> part(n - begin);
            detail::rbf_row_with(isa, &x[i * d], sq[i], xt.data() + begin, n, sq.data() + begin,
                                 n - begin, d, gamma, part.data());
            ASSERT_EQ(0, std::memcmp(part.data(), b.data() + begin, part.size() * sizeof(float)));
            detail::distance_row(&x[i * d], sq[i], xt.data(), sq.data(), n, d, dist.data());
            detail::rbf_row_from_distances_with(isa, dist.data(), n, gamma, da.data());
            detail::rbf_row_from_distances_with(Isa::portable, dist.data(), n, gamma, db.data());
            ASSERT_EQ(0, std::memcmp(da.data(), db.data(), n * sizeof(float))) << n << " " << d;
            ++checked;
          }
        }
      }
    }
  }
  RecordProperty("vectorised_rows_checked", checked);
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

TEST(OrderedRows, RowsCatchUpWithEveryRoundOfSwaps) {
  // Rows in solver order are brought up to date only when asked for, by replaying the swaps of
  // the rounds they missed or by gathering (computing) again; either way they must equal the
  // kernel row read through the current order, bit for bit, whether they are gathered from the
  // KernelCache or computed in order from features that follow the swaps. Small budgets make
  // both caches evict, rounds of up to 400 swaps make rows replay, start again, and outlive the
  // bounded swap log.
  const Data d = testing::smooth(300, 4, 0.1, 5);
  const TrainingSet set(d);
  for (const Kernel k : {Kernel::rbf_sigma(0.7), Kernel::linear()}) {
    for (const bool direct : {false, true}) {
      SCOPED_TRACE(direct ? "computed in order" : "gathered");
      KernelCache q(set, k, 0.02);
      const std::size_t n = d.rows;
      std::vector<std::int32_t> index(n);
      for (std::size_t t = 0; t < n; ++t) index[t] = static_cast<std::int32_t>(t);
      detail::OrderedRows rows(q, index.data(), n, n, 0.03, direct);
      std::vector<float> expected(n);
      Rng rng(8);
      for (int round = 0; round < 60; ++round) {
        const int swaps = static_cast<int>(rng.uniform(0, round % 7 == 6 ? 400 : 20));
        for (int s = 0; s < swaps; ++s) {
          const auto a = static_cast<std::size_t>(rng.uniform(0, static_cast<double>(n)));
          const auto b = static_cast<std::size_t>(rng.uniform(0, static_cast<double>(n)));
          if (a == b) continue;
          std::swap(index[a], index[b]);
          rows.swapped(a, b);
        }
        rows.apply_swaps();
        for (int r = 0; r < 30; ++r) {
          const auto row = static_cast<std::int32_t>(rng.uniform(0, 40));  // a few, reused
          const auto len = static_cast<std::size_t>(rng.uniform(1, static_cast<double>(n) + 1));
          const float* got = rows.row(row, len);
          set.kernel_row(k, static_cast<std::size_t>(row), expected.data());
          for (std::size_t t = 0; t < len; ++t)
            ASSERT_EQ(got[t], expected[static_cast<std::size_t>(index[t])])
                << "round " << round << " row " << row << " position " << t;
        }
      }
      EXPECT_EQ(rows.rows_computed() > 0, direct);
    }
  }
}

TEST(Selections, VectorisedAndPortableAgreeIncludingTies) {
  Rng rng(5);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t len = 1 + static_cast<std::size_t>(rng.uniform(0, 90));
    std::vector<double> g(len), qd(len);
    std::vector<std::int8_t> y(len);
    std::vector<std::uint8_t> status(len);
    std::vector<float> k(len);
    for (std::size_t t = 0; t < len; ++t) {
      // Few distinct values, so that ties are common.
      g[t] = std::round(rng.uniform(-3, 3));
      y[t] = rng.uniform() < 0.5 ? 1 : -1;
      status[t] = static_cast<std::uint8_t>(rng.uniform(0, 3));
      k[t] = static_cast<float>(std::round(rng.uniform(0, 4)) / 4);
      qd[t] = 1.0;
    }
    const auto a = detail::select_i(g.data(), y.data(), status.data(), len);
    const auto b = detail::select_i_reference(g.data(), y.data(), status.data(), len);
    ASSERT_EQ(a.index, b.index);
    if (a.index < 0) continue;
    ASSERT_EQ(a.value, b.value);
    const auto c = detail::select_j(g.data(), y.data(), status.data(), k.data(), qd.data(), 1.0,
                                    a.value, 1e-12, len);
    const auto e = detail::select_j_reference(g.data(), y.data(), status.data(), k.data(),
                                              qd.data(), 1.0, a.value, 1e-12, len);
    ASSERT_EQ(c.index, e.index);
    ASSERT_EQ(c.g_max2, e.g_max2);
  }
}

TEST(Selections, PairLoopsVectorisedAndPortableAgreeIncludingTies) {
  using detail::Isa;
  Rng rng(6);
  const double offsets[] = {0.25, -0.25, detail::kNoVariable};
  int checked = 0;
  for (Isa isa : {Isa::avx2, Isa::avx512}) {
    if (!detail::available(isa)) continue;  // this processor lacks it
    SCOPED_TRACE(isa == Isa::avx2 ? "AVX2" : "AVX-512");
    for (int trial = 0; trial < 300; ++trial) {
      const std::size_t len = 1 + static_cast<std::size_t>(rng.uniform(0, 200));
      std::vector<double> f(len), up(len), low(len), qd(len, 1.0);
      std::vector<float> k_i(len), k_j(len);
      for (std::size_t t = 0; t < len; ++t) {
        // Halves and quarters, few distinct values: the best is tied in most trials, several
        // times per vector lane, and every product is exact.
        f[t] = std::round(rng.uniform(-4, 4)) / 2;
        up[t] = offsets[static_cast<int>(rng.uniform(0, 3))];
        low[t] = offsets[static_cast<int>(rng.uniform(0, 3))];
        k_i[t] = static_cast<float>(std::round(rng.uniform(0, 2)) / 4);
        k_j[t] = static_cast<float>(std::round(rng.uniform(0, 2)) / 4);
      }
      std::vector<double> f2 = f;
      const auto a = detail::update_and_select_up_with(isa, f.data(), up.data(), k_i.data(),
                                                       k_j.data(), 0.5, -0.25, len);
      const auto b = detail::update_and_select_up_with(Isa::portable, f2.data(), up.data(),
                                                       k_i.data(), k_j.data(), 0.5, -0.25, len);
      ASSERT_EQ(f, f2);
      ASSERT_EQ(a.index, b.index);
      ASSERT_EQ(detail::select_up(f.data(), up.data(), len).index, a.index);
      if (a.index < 0) continue;
      ASSERT_EQ(a.value, b.value);
      const auto c = detail::select_low_with(isa, f.data(), low.data(), k_i.data(), qd.data(), 1.0,
                                             a.value, 1e-12, len);
      const auto e = detail::select_low_with(Isa::portable, f.data(), low.data(), k_i.data(),
                                             qd.data(), 1.0, a.value, 1e-12, len);
      ASSERT_EQ(c.index, e.index);
      ASSERT_EQ(c.g_max2, e.g_max2);
      // The conjugate step's loop: K·d in place, f along it, the next select_up.
      std::vector<double> kd(len), kd2;
      for (std::size_t t = 0; t < len; ++t) kd[t] = std::round(rng.uniform(-4, 4)) / 4;
      kd2 = kd;
      f2 = f;
      const auto g = detail::conjugate_update_and_select_up_with(
          isa, f.data(), up.data(), k_i.data(), k_j.data(), kd.data(), -0.5, 0.25, len);
      const auto h = detail::conjugate_update_and_select_up_with(
          Isa::portable, f2.data(), up.data(), k_i.data(), k_j.data(), kd2.data(), -0.5, 0.25, len);
      ASSERT_EQ(kd, kd2);
      ASSERT_EQ(f, f2);
      ASSERT_EQ(g.index, h.index);
      ASSERT_EQ(g.value, h.value);
      ASSERT_EQ(detail::select_up(f.data(), up.data(), len).index, g.index);
      ++checked;
    }
  }
  RecordProperty("vectorised_versions_checked", checked);
}

TEST(Selections, ConjugateLoopComputesTheDirectionAndTheGradient) {
  // kd = (K_i − K_j) + λ·kd, f += t·kd, in numbers exact in binary.
  std::vector<double> f = {1.0, -0.5, 0.25}, up = {0.25, -0.25, detail::kNoVariable};
  std::vector<double> kd = {2.0, -1.0, 0.5};
  const std::vector<float> k_i = {1.0F, 0.5F, 0.25F}, k_j = {0.5F, 0.5F, 1.0F};
  const auto s = detail::conjugate_update_and_select_up(f.data(), up.data(), k_i.data(), k_j.data(),
                                                        kd.data(), 0.5, 2.0, 3);
  EXPECT_EQ(kd, (std::vector<double>{1.5, -0.5, -0.5}));
  EXPECT_EQ(f, (std::vector<double>{4.0, -1.5, -0.75}));
  EXPECT_EQ(s.index, 1);  // up − f: −3.75, 1.25, and none for the third
  EXPECT_EQ(s.value, 1.25);
}

TEST(RowArena, AThreadReusesTheMemoryOfItsLastFitAndANewThreadDoesNot) {
  // On a thread of its own, which starts with nothing kept.
  std::thread([] {
    float* first = nullptr;
    {
      detail::RowArena a(8, 1000);
      first = a.row(0);
      for (std::size_t r = 0; r < 8; ++r) a.row(r)[999] = static_cast<float>(r);  // writable
      EXPECT_EQ(a.row(7)[999], 7.0f);
      EXPECT_EQ(a.row(1) - a.row(0), 1000);
    }
    {
      detail::RowArena again(4, 1000);  // smaller: the kept block serves it
      EXPECT_EQ(again.row(0), first);
    }
    float* other = nullptr;
    std::thread([&] {
      detail::RowArena a(8, 1000);
      other = a.row(0);
      a.row(7)[999] = 1.0f;
    }).join();
    EXPECT_NE(other, first);
    detail::RowArena mine(8, 1000);
    EXPECT_EQ(mine.row(0), first);
    detail::RowArena empty(0, 1000);  // nothing reserved
    EXPECT_EQ(empty.rows(), 0u);
  }).join();
}

}  // namespace
}  // namespace fogdrift::svr
