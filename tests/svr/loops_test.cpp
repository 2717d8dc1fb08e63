// The SVR engine's inner loops (src/svr/loops.hpp): both kernels' exponentials against std::exp,
// every function of every instruction set's table bit for bit against the portable table, a
// closed-form case, and the choice of the table through FOGDRIFT_ISA.
#include "svr/loops.hpp"
#include "svr/loops_scalar.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "fogdrift/svr/svr.hpp"

namespace fogdrift::svr {
namespace {

using detail::Isa;
using detail::Loops;

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

TEST(FastExp, ItsTableIsTheNearestDoubles) {
  // 2^(j/16) in long double (64 significant bits) rounded to double: the nearest double unless
  // the value lay within 2^-64 of a midpoint, which none of these does.
  for (std::size_t j = 0; j < 16; ++j)
    EXPECT_EQ(detail::scalar::kExp2Sixteenths[j],
              static_cast<double>(std::exp2(static_cast<long double>(j) / 16.0L)))
        << j;
}

/// How many floats lie between a and b (0 when equal).
long float_steps(float a, float b) {
  long steps = 0;
  while (a != b && steps < 1000) {
    a = std::nextafter(a, b);
    ++steps;
  }
  return steps;
}

TEST(KernelExp, IsWithinTwoFloatStepsOfStdExp) {
  // The reference is std::exp in double, rounded to float: the float the kernel would hold if
  // every step were exact. Scored by agreeing floats: most equal, none more than two steps off.
  Rng rng(3);
  const int n = 400000;
  int same = 0;
  long worst = 0;
  for (int k = 0; k < n; ++k) {
    const float y = static_cast<float>(-rng.uniform(0, 87));
    const float a = detail::kernel_exp(y);
    const float b = static_cast<float>(std::exp(static_cast<double>(y)));
    same += a == b;
    worst = std::max(worst, float_steps(a, b));
  }
  EXPECT_LE(worst, 2);
  EXPECT_GE(same, n * 2 / 3) << "of " << n;  // 72 % when written
  RecordProperty("same_float_as_std_exp", std::to_string(same) + " of " + std::to_string(n));
  EXPECT_EQ(detail::kernel_exp(0.0f), 1.0f);
  EXPECT_EQ(detail::kernel_exp(-0.0f), 1.0f);
  // Far points: clamped at e^−87, below float's smallest normal e^−87.34 × 1.4, never infinite
  // or negative.
  const float far = detail::kernel_exp(-1e30f);
  EXPECT_GT(far, 0.0f);
  EXPECT_LT(far, 2e-38f);
}

TEST(KernelExp, ItsTableIsTheNearestFloats) {
  // 2^(j/8) in long double rounded to float, twice over.
  for (std::size_t j = 0; j < 16; ++j)
    EXPECT_EQ(detail::scalar::kExp2Eighths[j],
              static_cast<float>(std::exp2(static_cast<long double>(j % 8) / 8.0L)))
        << j;
  EXPECT_EQ(detail::scalar::kEighthsPerNat, static_cast<float>(8.0L / std::log(2.0L)));
  // ln 2 / 8 as a high part of twelve fractional bits (so n·high is exact in float for
  // |n| < 2^15) and a low part whose
  // sum is ln 2 / 8 to within the low part's own rounding.
  const float high = detail::scalar::kLn2HiEighth;
  EXPECT_EQ(std::ldexp(high, 15) - std::floor(std::ldexp(high, 15)), 0.0f);
  EXPECT_NEAR(static_cast<double>(static_cast<long double>(high) + detail::scalar::kLn2LoEighth),
              static_cast<double>(std::log(2.0L) / 8.0L), 2e-12);
}

TEST(KernelExp, RowsAgreeWithTheKernelInDouble) {
  // A row in float against exp(−γ·‖x_i − x_j‖²) in double from the same (float-rounded)
  // features: relative error within a few float steps, near points and far ones.
  Rng rng(5);
  const std::size_t n = 300, d = 12;
  std::vector<float> x(n * d), xt(n * d);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t f = 0; f < d; ++f)
      xt[f * n + i] = x[i * d + f] = static_cast<float>(rng.normal() * (i % 2 ? 1.0 : 1e-2));
  std::vector<float> row(n);
  double worst = 0;
  for (const double gamma : {1e-3, 0.02, 0.5, 20.0}) {
    for (std::size_t i = 0; i < n; i += 7) {
      detail::loops().rbf_row(&x[i * d], xt.data(), n, n, d, gamma, row.data());
      for (std::size_t j = 0; j < n; ++j) {
        double dist = 0;
        for (std::size_t f = 0; f < d; ++f) {
          const double diff = static_cast<double>(x[i * d + f]) - x[j * d + f];
          dist += diff * diff;
        }
        const double y = -static_cast<double>(static_cast<float>(gamma)) * dist;
        const double exact = std::exp(y);
        if (exact < 1e-30) continue;
        // The distance's relative rounding error is multiplied by |y| in the exponential's.
        worst = std::max(worst, std::fabs(row[j] - exact) / exact / (1.0 - y));
      }
      EXPECT_EQ(row[i], 1.0f);
    }
  }
  // float's step is 1.2e-7 relative: the distance's and the exponential's roundings stay within
  // a few steps per unit of |y| = γ·d² (which multiplies the distance's relative error).
  EXPECT_LT(worst, 5e-7);
  RecordProperty("worst_relative_error", std::to_string(worst));
}

/// The vector tables this processor has, each to be compared with the portable one.
std::vector<const Loops*> vector_tables() {
  std::vector<const Loops*> out;
  for (const Isa isa : {Isa::avx2, Isa::avx512})
    if (const Loops* t = detail::loops_for(isa)) out.push_back(t);
  return out;
}

const Loops& portable() {
  return detail::portable_loops();
}

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(Loops, KernelRowsAreBitForBitThePortableOnes) {
  // The vector rows must give the floats the portable row gives, so that a fit takes the same
  // path on every processor: lengths around the vector widths, one and many features, near and
  // far points (e^x from 1 down to underflow), and distances from the matrix.
  Rng rng(11);
  int checked = 0;
  for (const Loops* table : vector_tables()) {
    SCOPED_TRACE(std::string(detail::isa_name(table->isa)));
    for (const std::size_t d : {std::size_t{1}, std::size_t{9}, std::size_t{17}}) {
      for (const std::size_t n : {1, 3, 4, 7, 8, 9, 15, 16, 17, 100, 257, 600}) {
        std::vector<double> x(n * d), xt(n * d), sq(n);
        std::vector<float> x32(n * d), xt32(n * d);
        for (std::size_t i = 0; i < n; ++i) {
          const double spread = i % 3 == 0 ? 1e-3 : (i % 3 == 1 ? 1.0 : 30.0);
          for (std::size_t f = 0; f < d; ++f) {
            x[i * d + f] = rng.normal() * spread;
            xt[f * n + i] = x[i * d + f];
            xt32[f * n + i] = x32[i * d + f] = static_cast<float>(x[i * d + f]);
            sq[i] += x[i * d + f] * x[i * d + f];
          }
        }
        std::vector<float> a(n), b(n), dist_a(n), dist_b(n);
        for (std::size_t i = 0; i < n; i += 1 + n / 5) {
          const double* xi = &x[i * d];
          const float* xi32 = &x32[i * d];
          table->linear_row(xi, xt.data(), n, n, d, a.data());
          portable().linear_row(xi, xt.data(), n, n, d, b.data());
          ASSERT_TRUE(same_bits(a, b)) << "linear " << n << " " << d;
          table->distance_row(xi32, xt32.data(), n, n, d, dist_a.data());
          portable().distance_row(xi32, xt32.data(), n, n, d, dist_b.data());
          ASSERT_TRUE(same_bits(dist_a, dist_b)) << "distances " << n << " " << d;
          for (const double gamma : {1e-3, 0.5, 20.0}) {
            table->libsvm_rbf_row(xi, sq[i], xt.data(), n, sq.data(), n, d, gamma, a.data());
            portable().libsvm_rbf_row(xi, sq[i], xt.data(), n, sq.data(), n, d, gamma, b.data());
            ASSERT_TRUE(same_bits(a, b)) << "libsvm rbf " << n << " " << d;
            table->rbf_row(xi32, xt32.data(), n, n, d, gamma, a.data());
            portable().rbf_row(xi32, xt32.data(), n, n, d, gamma, b.data());
            ASSERT_TRUE(same_bits(a, b)) << "rbf " << n << " " << d;
            // Columns [begin, n) alone, read with the full row's stride: the same floats.
            const std::size_t begin = n / 3;
            std::vector<float> part(n - begin);
            table->rbf_row(xi32, xt32.data() + begin, n, n - begin, d, gamma, part.data());
            ASSERT_EQ(0, std::memcmp(part.data(), b.data() + begin, part.size() * sizeof(float)));
            // From the distances: the same floats as the row.
            table->rbf_row_from_distances(dist_b.data(), n, gamma, a.data());
            ASSERT_TRUE(same_bits(a, b)) << "rbf from distances " << n << " " << d;
            portable().rbf_row_from_distances(dist_b.data(), n, gamma, a.data());
            ASSERT_TRUE(same_bits(a, b)) << "portable rbf from distances " << n << " " << d;
            ++checked;
          }
        }
      }
    }
  }
  RecordProperty("vectorised_rows_checked", checked);
}

TEST(Loops, RowsAtOnceAreTheRowsOneByOne) {
  // rbf_rows reads each column once for several rows; every row must be the floats rbf_row gives
  // it, in every table (the portable one included): row counts around kRowsAtOnce, lengths
  // around the vector widths, a leading dimension wider than the row, columns read at a stride.
  Rng rng(13);
  std::vector<const Loops*> tables = vector_tables();
  tables.push_back(&portable());
  for (const Loops* table : tables) {
    SCOPED_TRACE(std::string(detail::isa_name(table->isa)));
    for (const std::size_t d : {std::size_t{1}, std::size_t{12}}) {
      for (const std::size_t n : {1, 7, 8, 15, 16, 17, 31, 32, 33, 100, 257}) {
        const std::size_t stride = n + 5, ld = n + 3;
        std::vector<float> xt(stride * d);
        for (float& v : xt) v = static_cast<float>(rng.normal());
        for (const std::size_t m : {1, 2, 3, 4, 5, 9}) {
          std::vector<float> xs(m * d);
          for (float& v : xs) v = static_cast<float>(rng.normal() * (m % 2 == 0 ? 0.1 : 3.0));
          const float sentinel = -7.0f;
          std::vector<float> at_once(m * ld, sentinel), one(n);
          table->rbf_rows(xs.data(), m, xt.data(), stride, n, d, 0.3, at_once.data(), ld);
          for (std::size_t r = 0; r < m; ++r) {
            portable().rbf_row(xs.data() + r * d, xt.data(), stride, n, d, 0.3, one.data());
            ASSERT_EQ(0, std::memcmp(one.data(), at_once.data() + r * ld, n * sizeof(float)))
                << "row " << r << " of " << m << ", n " << n << ", d " << d;
            for (std::size_t j = n; j < ld; ++j)  // nothing written past a row's n entries
              ASSERT_EQ(sentinel, at_once[r * ld + j]) << "row " << r << " of " << m;
          }
        }
      }
    }
  }
}

TEST(Loops, GradientUpdatesAreBitForBitThePortableOnes) {
  Rng rng(12);
  for (const Loops* table : vector_tables()) {
    SCOPED_TRACE(std::string(detail::isa_name(table->isa)));
    for (int trial = 0; trial < 200; ++trial) {
      const std::size_t len = 1 + static_cast<std::size_t>(rng.uniform(0, 300));
      std::vector<double> g(len);
      std::vector<std::int8_t> y(len);
      std::vector<float> k_i(len), k_j(len);
      for (std::size_t t = 0; t < len; ++t) {
        g[t] = rng.normal();
        y[t] = rng.uniform() < 0.5 ? 1 : -1;
        k_i[t] = static_cast<float>(rng.uniform());
        k_j[t] = static_cast<float>(rng.uniform());
      }
      const double a_i = rng.normal(), a_j = rng.normal();
      const std::size_t begin = static_cast<std::size_t>(rng.uniform(0, static_cast<double>(len)));
      std::vector<double> g1 = g, g2 = g;
      table->update_gradient(g1.data(), y.data(), k_i.data(), k_j.data(), a_i, a_j, len);
      portable().update_gradient(g2.data(), y.data(), k_i.data(), k_j.data(), a_i, a_j, len);
      ASSERT_TRUE(same_bits(g1, g2)) << "update_gradient " << len;
      table->add_scaled(g1.data(), y.data(), k_i.data(), a_i, begin, len);
      portable().add_scaled(g2.data(), y.data(), k_i.data(), a_i, begin, len);
      ASSERT_TRUE(same_bits(g1, g2)) << "add_scaled " << len;
      table->add_row(g1.data(), k_j.data(), a_j, begin, len);
      portable().add_row(g2.data(), k_j.data(), a_j, begin, len);
      ASSERT_TRUE(same_bits(g1, g2)) << "add_row " << len;
    }
  }
}

TEST(Loops, LibsvmSelectionsAgreeWithThePortableOnesIncludingTies) {
  Rng rng(5);
  int checked = 0;
  for (const Loops* table : vector_tables()) {
    SCOPED_TRACE(std::string(detail::isa_name(table->isa)));
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
      const auto a = table->select_i(g.data(), y.data(), status.data(), len);
      const auto b = portable().select_i(g.data(), y.data(), status.data(), len);
      ASSERT_EQ(a.index, b.index);
      if (a.index < 0) continue;
      ASSERT_EQ(a.value, b.value);
      const auto c = table->select_j(g.data(), y.data(), status.data(), k.data(), qd.data(), 1.0,
                                     a.value, 1e-12, len);
      const auto e = portable().select_j(g.data(), y.data(), status.data(), k.data(), qd.data(),
                                         1.0, a.value, 1e-12, len);
      ASSERT_EQ(c.index, e.index);
      ASSERT_EQ(c.g_max2, e.g_max2);
      ++checked;
    }
  }
  RecordProperty("vectorised_selections_checked", checked);
}

TEST(Loops, PairLoopsAgreeWithThePortableOnesIncludingTies) {
  Rng rng(6);
  const double offsets[] = {0.25, -0.25, detail::kNoVariable};
  int checked = 0;
  for (const Loops* table : vector_tables()) {
    SCOPED_TRACE(std::string(detail::isa_name(table->isa)));
    for (int trial = 0; trial < 300; ++trial) {
      const std::size_t len = 1 + static_cast<std::size_t>(rng.uniform(0, 200));
      std::vector<double> f(len), up(len), low(len), qd(len, 1.0);
      std::vector<float> k_i(len), k_j(len);
      // Every third trial a diagonal that is not uniform (a linear kernel's); the others give
      // select_low no diagonal, as the pair solver does for the RBF kernel's 1.
      const bool uniform = trial % 3 != 0;
      for (std::size_t t = 0; t < len; ++t) {
        // Halves and quarters, few distinct values: the best is tied in most trials, several
        // times per vector lane, and every product is exact. K_ik reaches 1.25, so that the
        // curvature QD_i + QD_k − 2·K_ik is zero or negative for some k (τ instead).
        f[t] = std::round(rng.uniform(-4, 4)) / 2;
        up[t] = offsets[static_cast<int>(rng.uniform(0, 3))];
        low[t] = offsets[static_cast<int>(rng.uniform(0, 3))];
        k_i[t] = static_cast<float>(std::round(rng.uniform(0, 5)) / 4);
        k_j[t] = static_cast<float>(std::round(rng.uniform(0, 2)) / 4);
        if (!uniform) qd[t] = std::round(rng.uniform(1, 6)) / 4;
      }
      const double* diagonal = uniform ? nullptr : qd.data();
      std::vector<double> f2 = f;
      const auto a =
          table->update_and_select_up(f.data(), up.data(), k_i.data(), k_j.data(), 0.5, -0.25, len);
      const auto b = portable().update_and_select_up(f2.data(), up.data(), k_i.data(), k_j.data(),
                                                     0.5, -0.25, len);
      ASSERT_EQ(f, f2);
      ASSERT_EQ(a.index, b.index);
      ASSERT_EQ(table->select_up(f.data(), up.data(), len).index, a.index);
      ASSERT_EQ(portable().select_up(f.data(), up.data(), len).index, a.index);
      if (a.index < 0) continue;
      ASSERT_EQ(a.value, b.value);
      const auto c =
          table->select_low(f.data(), low.data(), k_i.data(), diagonal, 1.0, a.value, 1e-12, len);
      const auto e = portable().select_low(f.data(), low.data(), k_i.data(), diagonal, 1.0, a.value,
                                           1e-12, len);
      ASSERT_EQ(c.index, e.index);
      ASSERT_EQ(c.g_max2, e.g_max2);
      if (uniform) {  // no diagonal means QD_k = QD_i for every k
        const auto ones = portable().select_low(f.data(), low.data(), k_i.data(), qd.data(), 1.0,
                                                a.value, 1e-12, len);
        ASSERT_EQ(ones.index, e.index);
      }
      // The conjugate step's loop: K·d in place, f along it, the next select_up.
      std::vector<double> kd(len), kd2;
      for (std::size_t t = 0; t < len; ++t) kd[t] = std::round(rng.uniform(-4, 4)) / 4;
      kd2 = kd;
      f2 = f;
      const auto g = table->conjugate_update_and_select_up(f.data(), up.data(), k_i.data(),
                                                           k_j.data(), kd.data(), -0.5, 0.25, len);
      const auto h = portable().conjugate_update_and_select_up(
          f2.data(), up.data(), k_i.data(), k_j.data(), kd2.data(), -0.5, 0.25, len);
      ASSERT_EQ(kd, kd2);
      ASSERT_EQ(f, f2);
      ASSERT_EQ(g.index, h.index);
      ASSERT_EQ(g.value, h.value);
      ASSERT_EQ(table->select_up(f.data(), up.data(), len).index, g.index);
      ++checked;
    }
  }
  RecordProperty("vectorised_versions_checked", checked);
}

TEST(Loops, ConjugateLoopComputesTheDirectionAndTheGradient) {
  // kd = (K_i − K_j) + λ·kd, f += t·kd, in numbers exact in binary; 19 samples so that the
  // vector tables run full vectors and a tail.
  for (const Isa isa : {Isa::portable, Isa::avx2, Isa::avx512}) {
    const Loops* table = detail::loops_for(isa);
    if (table == nullptr) continue;
    SCOPED_TRACE(std::string(detail::isa_name(isa)));
    std::vector<double> f, up, kd;
    std::vector<float> k_i, k_j;
    for (int rep = 0; rep < 7; ++rep) {  // the three samples below, repeated; 19 in all
      f.insert(f.end(), {1.0, -0.5, 0.25});
      up.insert(up.end(), {0.25, -0.25, detail::kNoVariable});
      kd.insert(kd.end(), {2.0, -1.0, 0.5});
      k_i.insert(k_i.end(), {1.0F, 0.5F, 0.25F});
      k_j.insert(k_j.end(), {0.5F, 0.5F, 1.0F});
    }
    const std::size_t len = 19;
    const auto s = table->conjugate_update_and_select_up(f.data(), up.data(), k_i.data(),
                                                         k_j.data(), kd.data(), 0.5, 2.0, len);
    for (std::size_t k = 0; k < len; ++k) {
      EXPECT_EQ(kd[k], (std::vector<double>{1.5, -0.5, -0.5})[k % 3]) << k;
      EXPECT_EQ(f[k], (std::vector<double>{4.0, -1.5, -0.75})[k % 3]) << k;
    }
    EXPECT_EQ(kd[19], -1.0);  // beyond len: untouched
    // up − f: −3.75, 1.25, and none for the third; the last of the tied maxima is sample 16.
    EXPECT_EQ(s.index, 16);
    EXPECT_EQ(s.value, 1.25);
  }
}

TEST(Loops, FogdriftIsaNamesTheTableOrFailsClearly) {
  EXPECT_EQ(detail::loops_named("portable").isa, Isa::portable);
  const Isa best = detail::loops_named("").isa;
  EXPECT_EQ(detail::loops_named("auto").isa, best);
  for (const Isa isa : {Isa::avx2, Isa::avx512}) {
    if (detail::loops_for(isa) != nullptr) {
      EXPECT_EQ(detail::loops_named(detail::isa_name(isa)).isa, isa);
      EXPECT_GE(static_cast<int>(best), static_cast<int>(isa));
    } else {
      try {
        detail::loops_named(detail::isa_name(isa));
        ADD_FAILURE() << "a missing instruction set was accepted";
      } catch (const OptionError& e) {
        EXPECT_EQ(e.option(), "FOGDRIFT_ISA");
        EXPECT_NE(std::string(e.what()).find("this processor cannot run"), std::string::npos);
      }
    }
  }
  try {
    detail::loops_named("sse2");
    ADD_FAILURE() << "an unknown name was accepted";
  } catch (const OptionError& e) {
    EXPECT_STREQ(e.what(),
                 "option FOGDRIFT_ISA: 'sse2' is not an instruction set (portable, avx2, avx512)");
  }
  // The process's own choice is one of the tables and is stable.
  const std::string_view chosen = instruction_set();
  EXPECT_EQ(chosen, instruction_set());
  EXPECT_NE(detail::loops_for(detail::loops().isa), nullptr);
}

}  // namespace
}  // namespace fogdrift::svr
