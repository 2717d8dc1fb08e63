#include "fogdrift/signal/wavelet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "fogdrift/base/error.hpp"
#include "signal/signal_reference.hpp"

namespace fogdrift::signal {
namespace {

TEST(Wavelet, FamiliesAndLengths) {
  const auto& names = wavelet_names();
  ASSERT_EQ(names.size(), 20u + 19u + 5u);
  for (const auto& name : names) {
    const Wavelet w = wavelet(name);
    const int expected = w.family == "coif" ? 6 * w.order : 2 * w.order;
    EXPECT_EQ(w.filter_length(), expected) << name;
  }
  EXPECT_EQ(wavelet("haar").name, "db1");
}

// Orthonormality, from the filters alone (PyWavelets' higher-order filters hold ~11 digits, hence
// 1e-10): sum h = sqrt 2, sum h^2 = 1, and h orthogonal to its
// even shifts; the high-pass filter has a zero sum (at least one vanishing moment).
TEST(Wavelet, FiltersAreOrthonormal) {
  for (const auto& name : wavelet_names()) {
    const Wavelet w = wavelet(name);
    const auto& h = w.dec_lo;
    const double sum = std::accumulate(h.begin(), h.end(), 0.0);
    EXPECT_NEAR(sum, std::sqrt(2.0), 1e-10) << name;
    EXPECT_NEAR(std::accumulate(w.dec_hi.begin(), w.dec_hi.end(), 0.0), 0.0, 1e-10) << name;
    for (std::size_t shift = 0; shift < h.size(); shift += 2) {
      double dot = 0.0;
      for (std::size_t k = 0; k + shift < h.size(); ++k) dot += h[k] * h[k + shift];
      EXPECT_NEAR(dot, shift == 0 ? 1.0 : 0.0, 1e-10) << name << " shift " << shift;
    }
  }
}

TEST(Wavelet, UnknownNameIsAnOptionError) {
  try {
    wavelet("db21");
    FAIL() << "no error";
  } catch (const OptionError& e) {
    EXPECT_EQ(e.option(), "wavelet");
    EXPECT_NE(std::string(e.what()).find("db1..db20"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace fogdrift::signal
