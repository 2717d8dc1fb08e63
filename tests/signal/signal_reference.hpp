// The PyWavelets reference written at build time by tests/data/signal/make_signal_reference.py,
// and a digit score: how many significant digits two vectors share.
#pragma once

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <span>
#include <stdexcept>
#include <vector>

namespace fogdrift::test {

inline const nlohmann::json& signal_reference() {
  static const nlohmann::json reference = [] {
    std::ifstream in(FOGDRIFT_SIGNAL_REFERENCE);
    if (!in) throw std::runtime_error("missing " FOGDRIFT_SIGNAL_REFERENCE " (python3-pywt)");
    return nlohmann::json::parse(in);
  }();
  return reference;
}

/// max |a - b| / max(|b|), the error relative to the reference's scale (1 if lengths differ).
inline double relative_error(std::span<const double> a, std::span<const double> b) {
  if (a.size() != b.size()) return 1.0;
  double err = 0.0;
  double scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    err = std::max(err, std::fabs(a[i] - b[i]));
    scale = std::max(scale, std::fabs(b[i]));
  }
  return scale > 0 ? err / scale : err;
}

/// Agreeing significant digits, -log10 of the relative error, capped at 17.
inline double agreeing_digits(double relative) {
  return relative <= 1e-17 ? 17.0 : -std::log10(relative);
}

}  // namespace fogdrift::test
