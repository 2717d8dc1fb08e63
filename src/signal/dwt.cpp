#include "fogdrift/signal/dwt.hpp"

#include <cstdint>
#include <string>

#include "fogdrift/base/enum_names.hpp"
#include "fogdrift/base/error.hpp"

namespace fogdrift::signal {
namespace {

// x~[i] for any integer i, the signal continued by `extension` (not periodization).
double extended(std::span<const double> x, std::int64_t i, Extension extension) {
  const auto n = static_cast<std::int64_t>(x.size());
  if (i >= 0 && i < n) return x[static_cast<std::size_t>(i)];
  switch (extension) {
    case Extension::zero:
      return 0.0;
    case Extension::periodic:
    case Extension::periodization: {
      const std::int64_t p = ((i % n) + n) % n;
      return x[static_cast<std::size_t>(p)];
    }
    case Extension::symmetric: {
      // The mirrored signal x0..xN-1 xN-1..x0 repeats with period 2N.
      const std::int64_t p = ((i % (2 * n)) + 2 * n) % (2 * n);
      return x[static_cast<std::size_t>(p < n ? p : 2 * n - 1 - p)];
    }
  }
  return 0.0;
}

// out[k] = sum_j filter[j] * ext[first + 2k - j] for k < out.size(), where ext[i] = xe[i + pad].
void convolve_down(const std::vector<double>& xe, std::int64_t pad, std::int64_t first,
                   std::span<const double> filter, std::span<double> out) {
  const auto f = static_cast<std::int64_t>(filter.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    const std::int64_t i = first + 2 * static_cast<std::int64_t>(k) + pad;
    double sum = 0.0;
    for (std::int64_t j = 0; j < f; ++j) sum += filter[static_cast<std::size_t>(j)] * xe[i - j];
    out[k] = sum;
  }
}

}  // namespace

namespace {

constexpr std::array<EnumName<Extension>, 4> kExtensionNames = {
    {{Extension::symmetric, "symmetric"},
     {Extension::periodization, "periodization"},
     {Extension::zero, "zero"},
     {Extension::periodic, "periodic"}}};

}  // namespace

std::string_view to_string(Extension extension) {
  return name_in(kExtensionNames, extension);
}

Extension parse_extension(std::string_view text, std::string_view option) {
  return parse_in(kExtensionNames, text, option, "an extension mode");
}

std::string extension_names() {
  return names_in(kExtensionNames);
}

std::size_t dwt_coeff_length(std::size_t input_length, int filter_length, Extension extension) {
  if (extension == Extension::periodization) return (input_length + 1) / 2;
  return (input_length + static_cast<std::size_t>(filter_length) - 1) / 2;
}

int dwt_max_level(std::size_t input_length, int filter_length) {
  if (filter_length < 2) return 0;
  const auto f1 = static_cast<std::size_t>(filter_length - 1);
  if (input_length < f1) return 0;
  std::size_t ratio = input_length / f1;  // floor(log2(N / (F-1))) == floor(log2(floor(N/(F-1))))
  int level = 0;
  while (ratio > 1) {
    ratio >>= 1;
    ++level;
  }
  return level;
}

DwtLevel dwt(std::span<const double> x, const Wavelet& wavelet, Extension extension) {
  if (x.empty()) throw OptionError("signal", "the wavelet transform needs at least one sample");
  const auto f = static_cast<std::int64_t>(wavelet.filter_length());
  const auto n_out = dwt_coeff_length(x.size(), wavelet.filter_length(), extension);
  DwtLevel out{std::vector<double>(n_out), std::vector<double>(n_out)};

  // The extended signal, once, so the convolution is a plain loop: indices lo..hi of x~.
  std::vector<double> even;  // periodization of odd N: the last sample repeated
  std::span<const double> signal = x;
  std::int64_t first = 1;
  if (extension == Extension::periodization) {
    if (x.size() % 2 == 1) {
      even.assign(x.begin(), x.end());
      even.push_back(x.back());
      signal = even;
    }
    first = f / 2;
  }
  const std::int64_t lo = first - (f - 1);
  const std::int64_t hi = first + 2 * (static_cast<std::int64_t>(n_out) - 1);
  std::vector<double> xe(static_cast<std::size_t>(hi - lo + 1));
  for (std::int64_t i = lo; i <= hi; ++i) {
    xe[static_cast<std::size_t>(i - lo)] = extended(signal, i, extension);
  }
  convolve_down(xe, -lo, first, wavelet.dec_lo, out.approx);
  convolve_down(xe, -lo, first, wavelet.dec_hi, out.detail);
  return out;
}

std::vector<double> idwt(std::span<const double> approx, std::span<const double> detail,
                         const Wavelet& wavelet, Extension extension) {
  if (approx.size() != detail.size()) {
    throw OptionError("coefficients", "approximation and detail bands differ in length (" +
                                          std::to_string(approx.size()) + " and " +
                                          std::to_string(detail.size()) + ")");
  }
  const auto f = static_cast<std::int64_t>(wavelet.filter_length());
  const auto n = static_cast<std::int64_t>(approx.size());
  const auto& r = wavelet.rec_lo;
  const auto& s = wavelet.rec_hi;
  if (extension == Extension::periodization) {
    // Upsample, convolve circularly with period 2n, and align by F/2 - 1 samples.
    const std::int64_t m_len = 2 * n;
    if (m_len == 0) throw OptionError("coefficients", "the coefficient bands are empty");
    std::vector<double> x(static_cast<std::size_t>(m_len), 0.0);
    for (std::int64_t k = 0; k < n; ++k) {
      const double a = approx[static_cast<std::size_t>(k)];
      const double d = detail[static_cast<std::size_t>(k)];
      for (std::int64_t j = 0; j < f; ++j) {
        std::int64_t m = (j + 2 * k - f / 2 + 1) % m_len;
        if (m < 0) m += m_len;
        x[static_cast<std::size_t>(m)] +=
            a * r[static_cast<std::size_t>(j)] + d * s[static_cast<std::size_t>(j)];
      }
    }
    return x;
  }
  const std::int64_t len = 2 * n - f + 2;
  if (len < 1) {
    throw OptionError("coefficients", "bands of " + std::to_string(n) +
                                          " coefficients are too short to reconstruct with " +
                                          wavelet.name);
  }
  // x[m] = sum_k cA[k] rec_lo[m + F - 2 - 2k] + cD[k] rec_hi[m + F - 2 - 2k] (the 'valid' part).
  std::vector<double> x(static_cast<std::size_t>(len), 0.0);
  for (std::int64_t m = 0; m < len; ++m) {
    const std::int64_t t = m + f - 2;
    std::int64_t k_lo = (t - (f - 1) + 1) / 2;  // ceil((t - F + 1) / 2) for t - F + 1 >= -1
    if (t - (f - 1) < 0) k_lo = 0;
    const std::int64_t k_hi = std::min(t / 2, n - 1);
    double sum = 0.0;
    for (std::int64_t k = k_lo; k <= k_hi; ++k) {
      const auto j = static_cast<std::size_t>(t - 2 * k);
      sum +=
          approx[static_cast<std::size_t>(k)] * r[j] + detail[static_cast<std::size_t>(k)] * s[j];
    }
    x[static_cast<std::size_t>(m)] = sum;
  }
  return x;
}

WaveletCoeffs wavedec(std::span<const double> x, const Wavelet& wavelet, Extension extension,
                      std::optional<int> level) {
  if (x.empty()) throw OptionError("signal", "the wavelet transform needs at least one sample");
  const int levels = level.value_or(dwt_max_level(x.size(), wavelet.filter_length()));
  if (levels < 0) {
    throw OptionError("level", std::to_string(levels) + " is negative; the minimum level is 0");
  }
  WaveletCoeffs out;
  out.input_length = x.size();
  out.bands.resize(static_cast<std::size_t>(levels) + 1);
  std::vector<double> approx(x.begin(), x.end());
  for (int l = 0; l < levels; ++l) {
    if (approx.empty()) {
      throw OptionError("level", std::to_string(levels) + " levels need more than " +
                                     std::to_string(x.size()) + " samples");
    }
    DwtLevel step = dwt(approx, wavelet, extension);
    out.bands[static_cast<std::size_t>(levels - l)] = std::move(step.detail);
    approx = std::move(step.approx);
  }
  out.bands[0] = std::move(approx);
  return out;
}

std::vector<double> waverec(const WaveletCoeffs& coeffs, const Wavelet& wavelet,
                            Extension extension) {
  if (coeffs.bands.empty()) throw OptionError("coefficients", "no coefficient bands");
  std::vector<double> a = coeffs.bands[0];
  for (std::size_t b = 1; b < coeffs.bands.size(); ++b) {
    const auto& d = coeffs.bands[b];
    if (a.size() == d.size() + 1) a.pop_back();
    a = idwt(a, d, wavelet, extension);
  }
  return a;
}

std::vector<double> waverec_to_length(const WaveletCoeffs& coeffs, const Wavelet& wavelet,
                                      Extension extension) {
  std::vector<double> x = waverec(coeffs, wavelet, extension);
  if (x.size() > coeffs.input_length) x.resize(coeffs.input_length);
  return x;
}

}  // namespace fogdrift::signal
