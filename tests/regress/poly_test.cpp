#include "fogdrift/regress/poly.hpp"

#include <gtest/gtest.h>

#include <set>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"

namespace fogdrift {
namespace {

std::size_t binomial(std::size_t n, std::size_t k) {
  std::size_t r = 1;
  for (std::size_t i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

TEST(Poly, MonomialsAreEveryExponentVectorOnce) {
  for (std::size_t n : {1u, 2u, 3u, 9u}) {
    for (std::size_t d : {1u, 2u, 3u, 4u}) {
      const auto e = monomials(n, d);
      ASSERT_EQ(e.size(), binomial(n + d, d) * n) << n << " " << d;
      std::set<std::vector<std::uint8_t>> seen;
      std::size_t last_total = 0;
      for (std::size_t t = 0; t < e.size() / n; ++t) {
        std::vector<std::uint8_t> row(e.begin() + t * n, e.begin() + (t + 1) * n);
        std::size_t total = 0;
        for (auto v : row) total += v;
        EXPECT_LE(total, d);
        EXPECT_GE(total, last_total);  // graded
        last_total = total;
        EXPECT_TRUE(seen.insert(row).second);
      }
    }
  }
}

// A noise-free cubic in two variables is recovered exactly (closed form: the data lie on it).
TEST(Poly, RecoversAKnownPolynomial) {
  Data data;
  data.cols = 2;
  Rng rng(3);
  for (int i = 0; i < 200; ++i) {
    const double a = rng.uniform(-2, 2), b = rng.uniform(-2, 2);
    data.x.insert(data.x.end(), {a, b});
    data.y.push_back(0.5 - 1.5 * a + 0.25 * b + 2 * a * b - 0.75 * a * a * b + 0.1 * b * b * b);
    ++data.rows;
  }
  const Poly p = fit_poly(data, 3, 0);
  EXPECT_EQ(p.terms(), 10u);
  for (std::size_t i = 0; i < data.rows; ++i) ASSERT_NEAR(p.predict(data.row(i)), data.y[i], 1e-9);
  const double x[2] = {0.3, -1.1};
  EXPECT_NEAR(p.predict(x), 0.5 - 0.45 - 0.275 - 0.66 + 0.07425 - 0.1331, 1e-9);
  // Degree 1 cannot; degree 4 still recovers it.
  const Poly low = fit_poly(data, 1);
  double worst = 0;
  for (std::size_t i = 0; i < data.rows; ++i)
    worst = std::max(worst, std::abs(low.predict(data.row(i)) - data.y[i]));
  EXPECT_GT(worst, 0.5);
  const Poly high = fit_poly(data, 4, 0);
  EXPECT_NEAR(high.predict(x), p.predict(x), 1e-8);
}

TEST(Poly, RejectsImpossibleDegrees) {
  Data data{3, 2, {0, 1, 1, 0, 1, 1}, {1, 2, 3}, {}};
  EXPECT_THROW(fit_poly(data, 0), OptionError);
  EXPECT_THROW(fit_poly(data, 7), OptionError);
  EXPECT_THROW(fit_poly(data, 2), OptionError);  // 6 terms, 3 rows
}

TEST(Poly, JsonRoundTripAndBadExponents) {
  Poly p;
  p.inputs = 2;
  p.degree = 2;
  p.exponents = monomials(2, 2);
  p.coef = {0.5, 1.0, -2.0, 0.25, 0.125, -0.75};
  const Poly back = poly_from_json(to_json(p), "p.json");
  const double x[2] = {0.3, -1.7};
  EXPECT_EQ(back.predict(x), p.predict(x));
  EXPECT_EQ(back.exponents, p.exponents);
  p.exponents[3] = 3;  // above the degree
  try {
    poly_from_json(to_json(p), "p.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.message().find("exponents: exponent 3 is outside 0 … degree"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace fogdrift
