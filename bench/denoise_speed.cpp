// Wall time of signal::denoise on one long gyro-like signal (white noise on a slow drift);
// prints the median of --repeats runs in milliseconds. Driven by bench/denoise_vs_pywavelets.sh,
// which times the same pipeline in PyWavelets in the same run.
//
//   build/bench/denoise_speed N WAVELET RULE [--repeats R]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "fogdrift/base/random.hpp"
#include "fogdrift/signal/denoise.hpp"

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: denoise_speed N WAVELET RULE [--repeats R]\n");
    return 2;
  }
  const std::size_t n = std::stoull(argv[1]);
  fogdrift::signal::DenoiseOptions options;
  options.wavelet = argv[2];
  options.threshold = fogdrift::signal::parse_threshold_rule(argv[3]);
  int repeats = 7;
  for (int i = 4; i + 1 < argc; ++i) {
    if (std::strcmp(argv[i], "--repeats") == 0) repeats = std::stoi(argv[i + 1]);
  }
  fogdrift::Rng rng(1);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = 0.05 * std::exp(-double(i) / (0.2 * double(n))) + 0.03 * rng.normal();
  }
  std::vector<double> ms;
  double checksum = 0;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const auto out = fogdrift::signal::denoise(x, options);
    const auto t1 = std::chrono::steady_clock::now();
    checksum += out.signal[n / 2];
    ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  std::sort(ms.begin(), ms.end());
  std::printf("%.3f %.17g\n", ms[ms.size() / 2], checksum);
  return 0;
}
