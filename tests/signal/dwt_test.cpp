#include "fogdrift/signal/dwt.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>

#include "fogdrift/base/error.hpp"
#include "signal/signal_reference.hpp"

namespace fogdrift::signal {
namespace {

using test::agreeing_digits;
using test::relative_error;
using test::signal_reference;

// Every wavelet, every mode, odd and even lengths, one level and the maximum level: wavedec's
// bands and waverec's output agree with PyWavelets to 1e-10 of the band's scale.
TEST(Dwt, MatchesPyWaveletsForEveryWaveletModeAndLength) {
  const auto& cases = signal_reference().at("dwt");
  ASSERT_GT(cases.size(), 1000u);
  double worst = 0.0;
  std::map<std::string, double> worst_by_mode;
  for (const auto& c : cases) {
    const Wavelet w = wavelet(c.at("wavelet").get<std::string>());
    const Extension mode = parse_extension(c.at("mode").get<std::string>());
    const auto x = c.at("x").get<std::vector<double>>();
    const int level = c.at("level").get<int>();
    const std::string where = c.at("wavelet").get<std::string>() + " " +
                              c.at("mode").get<std::string>() + " N=" + std::to_string(x.size()) +
                              " level=" + std::to_string(level);
    ASSERT_EQ(dwt_max_level(x.size(), w.filter_length()), c.at("max_level").get<int>()) << where;
    const WaveletCoeffs coeffs = wavedec(x, w, mode, level);
    const auto& ref_bands = c.at("coeffs");
    ASSERT_EQ(coeffs.bands.size(), ref_bands.size()) << where;
    for (std::size_t b = 0; b < ref_bands.size(); ++b) {
      const auto ref = ref_bands[b].get<std::vector<double>>();
      ASSERT_EQ(coeffs.bands[b].size(), ref.size()) << where << " band " << b;
      const double err = relative_error(coeffs.bands[b], ref);
      ASSERT_LE(err, 1e-10) << where << " band " << b;
      worst = std::max(worst, err);
      worst_by_mode[c.at("mode")] = std::max(worst_by_mode[c.at("mode")], err);
    }
    const auto ref_rec = c.at("waverec").get<std::vector<double>>();
    const auto rec = waverec(coeffs, w, mode);
    ASSERT_EQ(rec.size(), ref_rec.size()) << where;
    const double err = relative_error(rec, ref_rec);
    ASSERT_LE(err, 1e-10) << where << " waverec";
    worst = std::max(worst, err);
  }
  std::cout << "[ digits ] wavedec/waverec vs PyWavelets "
            << signal_reference().at("pywt_version").get<std::string>() << ": " << cases.size()
            << " cases, worst " << agreeing_digits(worst) << " digits\n";
  for (const auto& [mode, err] : worst_by_mode) {
    std::cout << "[ digits ]   " << mode << ": " << agreeing_digits(err) << "\n";
  }
}

// Perfect reconstruction (orthogonal wavelets): waverec_to_length(wavedec(x)) == x to round-off.
TEST(Dwt, ReconstructsExactlyForEveryMode) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  for (const char* name : {"db1", "db4", "sym8", "coif5", "db20"}) {
    const Wavelet w = wavelet(name);
    for (auto mode :
         {Extension::symmetric, Extension::periodization, Extension::zero, Extension::periodic}) {
      for (std::size_t n : {1u, 2u, 3u, 10u, 99u, 1000u}) {
        std::vector<double> x(n);
        for (auto& v : x) v = normal(rng);
        const int level = std::max(1, dwt_max_level(n, w.filter_length()));
        const auto back = waverec_to_length(wavedec(x, w, mode, level), w, mode);
        ASSERT_LE(relative_error(back, x), 1e-12) << name << " " << to_string(mode) << " " << n;
      }
    }
  }
}

TEST(Dwt, MaxLevelRule) {
  EXPECT_EQ(dwt_max_level(1000, 2), 9);  // floor(log2(1000))
  EXPECT_EQ(dwt_max_level(1000, 8), 7);  // floor(log2(1000 / 7))
  EXPECT_EQ(dwt_max_level(6, 8), 0);     // shorter than F - 1
  EXPECT_EQ(dwt_max_level(7, 8), 0);
  EXPECT_EQ(dwt_max_level(14, 8), 1);
  EXPECT_EQ(dwt_coeff_length(33, 8, Extension::symmetric), 20u);
  EXPECT_EQ(dwt_coeff_length(33, 8, Extension::periodization), 17u);
}

TEST(Dwt, BadArguments) {
  const Wavelet w = wavelet("db2");
  EXPECT_THROW(dwt(std::vector<double>{}, w), OptionError);
  EXPECT_THROW(wavedec(std::vector<double>{1, 2, 3}, w, Extension::symmetric, -1), OptionError);
  EXPECT_THROW(idwt(std::vector<double>{1, 2}, std::vector<double>{1}, w), OptionError);
  EXPECT_THROW(idwt(std::vector<double>{1}, std::vector<double>{1}, wavelet("db4")), OptionError);
  try {
    parse_extension("reflect", "extension");
    FAIL();
  } catch (const OptionError& e) {
    EXPECT_NE(std::string(e.what()).find("symmetric, periodization, zero, periodic"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace fogdrift::signal
