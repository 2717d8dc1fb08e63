#include "fogdrift/signal/denoise.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fogdrift/base/error.hpp"
#include "signal/signal_reference.hpp"

namespace fogdrift::signal {
namespace {

using test::agreeing_digits;
using test::relative_error;
using test::signal_reference;

// The whole denoiser against an independent numpy + PyWavelets implementation: five wavelet and
// mode settings, four rules, soft and hard, odd and even lengths.
TEST(Denoise, MatchesNumpyAndPyWavelets) {
  const auto& cases = signal_reference().at("denoise");
  ASSERT_EQ(cases.size(), 2u * 5u * 4u * 2u);
  double worst = 0.0;
  for (const auto& c : cases) {
    DenoiseOptions options;
    options.wavelet = c.at("wavelet").get<std::string>();
    options.extension = parse_extension(c.at("mode").get<std::string>());
    if (!c.at("level").is_null()) options.level = c.at("level").get<int>();
    options.threshold = parse_threshold_rule(c.at("rule").get<std::string>());
    options.shrinkage = parse_shrinkage(c.at("shrink").get<std::string>());
    const auto x = c.at("x").get<std::vector<double>>();
    const auto ref = c.at("denoised").get<std::vector<double>>();
    const auto out = denoise(x, options);
    const double err = relative_error(out.signal, ref);
    EXPECT_LE(err, 1e-10) << c.at("wavelet") << " " << c.at("mode") << " " << c.at("rule") << " "
                          << c.at("shrink") << " N=" << x.size();
    worst = std::max(worst, err);
  }
  std::cout << "[ digits ] denoise vs numpy+PyWavelets: worst " << agreeing_digits(worst)
            << " digits over " << cases.size() << " cases\n";
}

TEST(Denoise, MadSigmaIsTheMedianNotTheMean) {
  // |d| = 1, 1, 1, 100: the mean absolute deviation would be 25.75, the median is 1.
  EXPECT_DOUBLE_EQ(mad_sigma(std::vector<double>{1, -1, 1, -100}), 1.0 / 0.6745);
  EXPECT_DOUBLE_EQ(mad_sigma(std::vector<double>{-3, 1, 2}), 2.0 / 0.6745);
  EXPECT_DOUBLE_EQ(mad_sigma(std::vector<double>{}), 0.0);
  // Gaussian noise: the estimate is within 3 % of the true sigma for 20,000 samples.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal(0.0, 0.7);
  std::vector<double> d(20000);
  for (auto& v : d) v = normal(rng);
  EXPECT_NEAR(mad_sigma(d), 0.7, 0.02);
}

// SURE's minimiser against a brute-force scan of Stein's risk over a fine grid of thresholds.
TEST(Denoise, SureThresholdMinimisesSteinsRisk) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<double> d(200);
    for (std::size_t i = 0; i < d.size(); ++i) d[i] = normal(rng) + (i % 10 == 0 ? 6.0 : 0.0);
    const double sigma = 1.0 + 0.1 * trial;
    for (auto& v : d) v *= sigma;
    auto risk = [&](double t) {  // SURE(t) on w = d / sigma, soft thresholding
      double r = static_cast<double>(d.size());
      for (double v : d) {
        const double w = std::fabs(v / sigma);
        r += w <= t ? -2.0 + w * w : t * t;
      }
      return r;
    };
    const double t_star = sure_threshold(d, sigma) / sigma;
    for (double t = 0.0; t < 8.0; t += 0.01) ASSERT_GE(risk(t), risk(t_star) - 1e-9) << t;
  }
}

TEST(Denoise, ShrinkageConventions) {
  std::vector<double> soft{-2, -1, 0, 1, 2, 0.5};
  EXPECT_EQ(shrink(soft, 1.0, Shrinkage::soft), 2u);
  EXPECT_EQ(soft, (std::vector<double>{-1, 0, 0, 0, 1, 0}));
  std::vector<double> hard{-2, -1, 0, 1, 2, 0.5};
  EXPECT_EQ(shrink(hard, 1.0, Shrinkage::hard), 4u);  // |d| == lambda is kept, as in pywt
  EXPECT_EQ(hard, (std::vector<double>{-2, -1, 0, 1, 2, 0}));
}

// A slow drift under white noise: the denoised signal is closer to the drift than the input, and
// the drift survives (its low-frequency content is in the approximation, which is kept).
TEST(Denoise, KeepsDriftRemovesWhiteNoise) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal(0.0, 0.05);
  const std::size_t n = 3600;
  std::vector<double> drift(n), x(n);
  for (std::size_t i = 0; i < n; ++i) {
    drift[i] = 0.1 * std::exp(-static_cast<double>(i) / 600.0);
    x[i] = drift[i] + normal(rng);
  }
  for (auto rule : {ThresholdRule::universal, ThresholdRule::level, ThresholdRule::sure,
                    ThresholdRule::bayes}) {
    DenoiseOptions options;
    options.threshold = rule;
    const auto out = denoise(x, options);
    double before = 0, after = 0;
    for (std::size_t i = 0; i < n; ++i) {
      before += (x[i] - drift[i]) * (x[i] - drift[i]);
      after += (out.signal[i] - drift[i]) * (out.signal[i] - drift[i]);
    }
    EXPECT_LT(after, 0.1 * before) << to_string(rule);
    EXPECT_NEAR(out.summary.noise_sigma, 0.05, 0.005) << to_string(rule);
    EXPECT_EQ(out.summary.bands.size(), static_cast<std::size_t>(out.summary.level));
  }
}

TEST(Denoise, TooShortOrTooDeepIsAClearError) {
  DenoiseOptions options;
  options.wavelet = "db4";  // F = 8
  try {
    denoise(std::vector<double>(10, 1.0), options);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "level");
    EXPECT_NE(std::string(e.what()).find("too short to denoise with db4 (at least 14 samples"),
              std::string::npos)
        << e.what();
  }
  options.level = 5;
  try {
    denoise(std::vector<double>(100, 1.0), options);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_NE(
        std::string(e.what()).find("5 is too high for 100 samples with db4: the maximum is 3"),
        std::string::npos)
        << e.what();
  }
  options.level = 0;
  EXPECT_THROW(denoise(std::vector<double>(100, 1.0), options), OptionError);
  options.level.reset();
  std::vector<double> x(100, 1.0);
  x[42] = NAN;
  try {
    denoise(x, options);
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("sample 42 is not a finite number"), std::string::npos);
  }
  EXPECT_THROW(parse_threshold_rule("minimax"), OptionError);
  EXPECT_THROW(parse_shrinkage("garrote"), OptionError);
}

}  // namespace
}  // namespace fogdrift::signal
