#include "fogdrift/signal/differentiate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/random.hpp"
#include "signal/signal_reference.hpp"

namespace fogdrift::signal {
namespace {

using test::agreeing_digits;
using test::relative_error;
using test::signal_reference;

// The centred differentiator is SciPy's savgol_filter(deriv=1, mode='interp'), edges included.
TEST(Differentiate, CentredMatchesScipySavgol) {
  const auto& cases = signal_reference().at("savgol");
  ASSERT_EQ(cases.size(), 15u);
  double worst = 0.0;
  for (const auto& c : cases) {
    const double dt = c.at("dt_s").get<double>();
    DifferentiatorOptions options;
    options.poly_order = c.at("poly_order").get<int>();
    options.window_s = c.at("window").get<double>() * dt;
    ASSERT_EQ(window_samples(options, dt), c.at("window").get<std::size_t>());
    const auto x = c.at("x").get<std::vector<double>>();
    const auto ref = c.at("derivative").get<std::vector<double>>();
    const auto d = differentiate(x, dt, options);
    const double err = relative_error(d, ref);
    EXPECT_LE(err, 1e-9) << "W=" << c.at("window") << " p=" << options.poly_order
                         << " N=" << x.size();
    worst = std::max(worst, err);
  }
  std::cout << "[ digits ] centred differentiator vs scipy.signal.savgol_filter: worst "
            << agreeing_digits(worst) << " digits\n";
}

// Known derivatives: a polynomial of degree <= p is differentiated exactly, everywhere, by both
// variants (the causal one after its first p samples).
TEST(Differentiate, ExactOnPolynomials) {
  const double dt = 0.5;
  std::vector<double> x(200), dx(200);
  for (int p = 1; p <= 3; ++p) {
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double t = static_cast<double>(i) * dt;
      x[i] = 3.0 + 0.2 * t + (p >= 2 ? -0.004 * t * t : 0.0) + (p >= 3 ? 1e-5 * t * t * t : 0.0);
      dx[i] = 0.2 + (p >= 2 ? -0.008 * t : 0.0) + (p >= 3 ? 3e-5 * t * t : 0.0);
    }
    for (auto causality : {Causality::centred, Causality::causal}) {
      const DifferentiatorOptions options{21.0, p, causality};
      const auto d = differentiate(x, dt, options);
      // The causal warm-up takes the unit at rest before power-on (WarmUpTakesTheUnitAtRest).
      const std::size_t first = warmup_samples(options, dt);
      for (std::size_t i = first; i < x.size(); ++i) {
        ASSERT_NEAR(d[i], dx[i], 1e-9) << to_string(causality) << " p=" << p << " i=" << i;
      }
    }
  }
}

// The documented delay and noise gain, measured: a causal line fit lags a parabola by (W-1)/2
// samples, and white noise comes out with the predicted standard deviation.
TEST(Differentiate, DelayAndNoiseGainAsDocumented) {
  const double dt = 1.0;
  DifferentiatorOptions line{61.0, 1, Causality::causal};
  const auto props = differentiator_properties(line, dt);
  EXPECT_EQ(props.window, 61u);
  EXPECT_NEAR(props.delay_s, 30.0, 1e-9);
  const double gain = std::sqrt(12.0 / (61.0 * (61.0 * 61.0 - 1.0)));
  EXPECT_NEAR(props.noise_gain_per_s, gain, 1e-12);
  DifferentiatorOptions centred{61.0, 2, Causality::centred};
  EXPECT_NEAR(differentiator_properties(centred, dt).delay_s, 0.0, 1e-12);
  EXPECT_NEAR(differentiator_properties(centred, dt).noise_gain_per_s, gain, 1e-12);
  DifferentiatorOptions quad{61.0, 2, Causality::causal};
  const auto qprops = differentiator_properties(quad, dt);
  EXPECT_NEAR(qprops.delay_s, 0.0, 1e-9);
  EXPECT_GT(qprops.noise_gain_per_s, 3.5 * gain);

  // Parabola x = a t^2 / 2: the causal line fit returns a (t - 30).
  std::vector<double> x(400);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 0.5 * 0.01 * double(i) * double(i);
  const auto d = differentiate(x, dt, line);
  for (std::size_t i = 60; i < x.size(); ++i) ASSERT_NEAR(d[i], 0.01 * (double(i) - 30.0), 1e-9);

  // White noise of sd 0.05: output sd = 0.05 * gain, within 5 % over 100,000 samples.
  std::mt19937_64 rng(9);
  std::normal_distribution<double> normal(0.0, 0.05);
  std::vector<double> noise(100000);
  for (auto& v : noise) v = normal(rng);
  for (const auto& options : {line, centred}) {
    const auto dn = differentiate(noise, dt, options);
    double ss = 0.0;
    for (std::size_t i = 100; i + 100 < dn.size(); ++i) ss += dn[i] * dn[i];
    const double sd = std::sqrt(ss / double(dn.size() - 200));
    EXPECT_NEAR(sd, 0.05 * gain, 0.05 * 0.05 * gain) << to_string(options.causality);
  }
}

// Causal means causal: changing a future sample never changes an earlier output.
TEST(Differentiate, CausalUsesOnlyThePast) {
  std::vector<double> x(300);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::sin(double(i) / 20.0);
  DifferentiatorOptions options{31.0, 2, Causality::causal};
  const auto before = differentiate(x, 1.0, options);
  x[150] += 1.0;
  const auto after = differentiate(x, 1.0, options);
  for (std::size_t i = 0; i < 150; ++i) ASSERT_EQ(before[i], after[i]) << i;
  EXPECT_NE(before[150], after[150]);
  EXPECT_EQ(before[0], 0.0);
}

// The first W − 1 causal rates are the full window's fit to the signal with the samples before
// power-on equal to the first one (docs/signal.md §2, "Warm-up"): checked against the full filter
// run on that padded signal, built independently. Their noise is what their taps say, and at most
// a few times the full window's, where a fit to the few samples there are is mostly noise.
TEST(Differentiate, WarmUpTakesTheUnitAtRest) {
  Rng rng(11);
  for (int p = 1; p <= 2; ++p) {
    const DifferentiatorOptions options{31.0, p, Causality::causal};
    const std::size_t w = 31;
    ASSERT_EQ(warmup_samples(options, 1.0), w - 1);
    std::vector<double> x(100);
    for (std::size_t i = 0; i < x.size(); ++i)
      x[i] = 20.0 + 0.01 * static_cast<double>(i) + 0.01 * rng.normal();
    std::vector<double> padded(w - 1, x[0]);
    padded.insert(padded.end(), x.begin(), x.end());
    const auto d = differentiate(x, 1.0, options);
    const auto reference = differentiate(padded, 1.0, options);
    for (std::size_t i = 0; i < x.size(); ++i)
      ASSERT_NEAR(d[i], reference[i + w - 1], 1e-12) << "p=" << p << " i=" << i;
    EXPECT_EQ(d[0], 0.0);
    const std::vector<double> constant(w, 7.25);
    for (double r : differentiate(constant, 1.0, options)) EXPECT_NEAR(r, 0.0, 1e-15);

    // Noise: each warm-up output's standard deviation over many realisations of white noise,
    // against √Σ taps² and against the full window's gain.
    const CausalDifferentiator filter(options, 1.0);
    const double gain = differentiator_properties(options, 1.0).noise_gain_per_s;
    std::vector<double> sum_sq(w - 1, 0.0);
    const int trials = 20000;
    for (int t = 0; t < trials; ++t) {
      std::vector<double> noise(w - 1);
      for (double& v : noise) v = rng.normal();
      const auto n = differentiate(noise, 1.0, options);
      for (std::size_t i = 0; i < n.size(); ++i) sum_sq[i] += n[i] * n[i];
    }
    for (std::size_t i = 1; i < sum_sq.size(); ++i) {
      double power = 0.0;
      for (double h : filter.taps(i + 1)) power += h * h;
      const double measured = std::sqrt(sum_sq[i] / trials);
      EXPECT_NEAR(measured, std::sqrt(power), 0.03 * std::sqrt(power)) << "p=" << p << " i=" << i;
      EXPECT_LE(measured, 3.0 * gain) << "p=" << p << " i=" << i;
    }
    // A fit to the first three samples alone would have a noise gain of √(12 / 24) = 0.71 /s.
    EXPECT_LT(std::sqrt(sum_sq[2] / trials), 0.1);
  }
}

TEST(Differentiate, BadOptionsNameTheField) {
  auto message = [](const DifferentiatorOptions& o, double dt, std::size_t n) {
    try {
      validate(o, dt, n);
    } catch (const OptionError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({121.0, 2, Causality::centred}, 1.0, 100).find("longer than the signal (100"),
            std::string::npos);
  EXPECT_NE(message({2.0, 2, Causality::causal}, 1.0, 100).find("needs at least 4"),
            std::string::npos);
  EXPECT_NE(message({-1.0, 2, Causality::causal}, 1.0, 100).find("window_s"), std::string::npos);
  EXPECT_NE(message({21.0, 7, Causality::causal}, 1.0, 100).find("outside 1..4"),
            std::string::npos);
  EXPECT_NE(message({21.0, 2, Causality::causal}, 0.0, 100).find("dt_s"), std::string::npos);
  EXPECT_EQ(message({121.0, 2, Causality::causal}, 1.0, 100), "no error");  // causal: any length
  EXPECT_THROW(parse_causality("future"), OptionError);
}

}  // namespace
}  // namespace fogdrift::signal
