// The discrete wavelet transform, one level and multilevel, with the conventions of PyWavelets
// (pywt.dwt/idwt/wavedec/waverec/dwt_max_level), so that a user's PyWavelets script and fogdrift
// give the same coefficients to round-off (tests/signal/dwt_test.cpp checks every wavelet, mode
// and odd and even lengths against python3-pywt).
//
// One level, signal x of length N, filter length F:
//   cA[k] = sum_j dec_lo[j] * x~[2k + 1 - j],  cD[k] likewise with dec_hi,
// where x~ extends x beyond its ends by the Extension. Output length floor((N + F - 1) / 2),
// or ceil(N / 2) for periodization (which first repeats the last sample of an odd-length x and
// then treats the signal as periodic).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fogdrift/signal/wavelet.hpp"

namespace fogdrift::signal {

/// How the signal is continued beyond its ends (PyWavelets' "mode").
enum class Extension {
  symmetric,      ///< half-sample mirror: ... x1 x0 | x0 x1 ... xN-1 | xN-1 xN-2 ... (default)
  periodization,  ///< periodic with the minimal number of coefficients (ceil(N/2) per level)
  zero,           ///< zeros beyond the ends
  periodic,       ///< x repeated with period N
};

std::string_view to_string(Extension extension);
/// Parses "symmetric", "periodization", "zero" or "periodic"; throws OptionError(option, ...).
Extension parse_extension(std::string_view text, std::string_view option = "extension");
/// "symmetric, periodization, zero, periodic".
std::string extension_names();

/// Length of cA (and cD) for a signal of `input_length` samples.
std::size_t dwt_coeff_length(std::size_t input_length, int filter_length, Extension extension);

/// PyWavelets' maximum useful level: floor(log2(N / (F - 1))), 0 if N < F - 1.
int dwt_max_level(std::size_t input_length, int filter_length);

struct DwtLevel {
  std::vector<double> approx;  ///< cA
  std::vector<double> detail;  ///< cD
};

/// One level of the transform (pywt.dwt). Throws OptionError if x is empty.
DwtLevel dwt(std::span<const double> x, const Wavelet& wavelet,
             Extension extension = Extension::symmetric);

/// Inverse of one level (pywt.idwt): cA and cD of equal length n; returns 2n - F + 2 samples,
/// or 2n for periodization. Throws OptionError if the lengths differ or the result is empty.
std::vector<double> idwt(std::span<const double> approx, std::span<const double> detail,
                         const Wavelet& wavelet, Extension extension = Extension::symmetric);

/// Multilevel coefficients in PyWavelets' order: bands[0] = cA_L, bands[1] = cD_L (coarsest),
/// ..., bands[L] = cD_1 (finest).
struct WaveletCoeffs {
  std::vector<std::vector<double>> bands;
  std::size_t input_length = 0;  ///< N of the decomposed signal, so waverec can trim to it
  int level() const { return static_cast<int>(bands.size()) - 1; }
};

/// pywt.wavedec: `level` levels (default dwt_max_level). A level above the maximum is allowed,
/// as in PyWavelets, as long as every stage has at least one sample; callers that want the
/// maximum enforced (the denoiser does) check it themselves. Throws OptionError for a negative
/// level or an empty signal.
WaveletCoeffs wavedec(std::span<const double> x, const Wavelet& wavelet,
                      Extension extension = Extension::symmetric,
                      std::optional<int> level = std::nullopt);

/// pywt.waverec: when an approximation is one sample longer than the next detail band it is
/// trimmed, as PyWavelets does. The result may be one sample longer than the original signal
/// (odd N); see waverec_to_length.
std::vector<double> waverec(const WaveletCoeffs& coeffs, const Wavelet& wavelet,
                            Extension extension = Extension::symmetric);

/// waverec, then trimmed to coeffs.input_length: the exact inverse of wavedec.
std::vector<double> waverec_to_length(const WaveletCoeffs& coeffs, const Wavelet& wavelet,
                                      Extension extension = Extension::symmetric);

}  // namespace fogdrift::signal
