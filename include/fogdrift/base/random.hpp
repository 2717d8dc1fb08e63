// Deterministic random numbers, identical on every platform and standard library.
//
// std::normal_distribution and friends are implementation-defined, so the same seed would give
// different campaigns with libstdc++ and libc++. fogdrift draws from xoshiro256** (Blackman &
// Vigna 2018) seeded through splitmix64, and makes Gaussians by the Box–Muller transform, all
// specified here. Independent streams (one per recording, one per particle, ...) come from
// derive_seed(), so results never depend on the order in which threads consume numbers.
#pragma once

#include <array>
#include <cstdint>

namespace fogdrift {

/// splitmix64 finaliser: a well-mixed 64-bit function of `x`.
std::uint64_t mix64(std::uint64_t x);

/// Seed of the independent stream `stream` below `seed` (e.g. recording index below the run seed).
inline std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  return mix64(seed ^ mix64(stream + 0x9E3779B97F4A7C15ULL));
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed);

  std::uint64_t next_u64();
  /// Uniform in [0, 1), 53 random bits.
  double uniform();
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  /// Standard normal N(0, 1) (Box–Muller; the second value of each pair is kept for the next call).
  double normal();
  /// N(mean, sd²).
  double normal(double mean, double sd) { return mean + sd * normal(); }

 private:
  std::array<std::uint64_t, 4> s_{};
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace fogdrift
