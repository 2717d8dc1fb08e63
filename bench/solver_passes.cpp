// The pair solver's passes over its active samples (docs/svr.md, "Where the speed comes from"),
// ns a sample, for every instruction set this processor has, on arrays of N = 3,000 samples (a
// fold of the paper's campaign): select_low with the diagonal read from memory and without it
// (the RBF kernel's), the conjugate step's update and the ordinary one. The median of seven
// passes of 200 million samples each; the peer is the portable table, in the same run.
//
//   build/bench/solver_passes            # about 20 s
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "fogdrift/base/random.hpp"
#include "svr/loops.hpp"

namespace {

using fogdrift::svr::detail::Isa;
using fogdrift::svr::detail::Loops;

struct Arrays {
  std::vector<double> f, up, low, qd, kd;
  std::vector<float> k_i, k_j;
};

Arrays make_arrays(std::size_t n) {
  fogdrift::Rng rng(7);
  Arrays a;
  a.f.resize(n);
  a.up.resize(n);
  a.low.resize(n);
  a.qd.assign(n, 1.0);
  a.kd.resize(n);
  a.k_i.resize(n);
  a.k_j.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    a.f[k] = rng.uniform(-1, 1);
    a.up[k] = k % 3 == 0 ? 0.05 : -0.05;
    a.low[k] = k % 5 == 0 ? -0.05 : 0.05;
    a.k_i[k] = static_cast<float>(std::exp(-rng.uniform(0, 3)));
    a.k_j[k] = static_cast<float>(std::exp(-rng.uniform(0, 3)));
    a.kd[k] = rng.uniform(-1e-3, 1e-3);
  }
  return a;
}

// Median ns a sample of `pass` over n samples, seven passes of about 2·10⁸ samples each.
double ns_per_sample(std::size_t n, const std::function<double()>& pass) {
  const std::size_t repeats = 200'000'000 / n;
  std::vector<double> times;
  double sink = 0;
  for (int p = 0; p < 7; ++p) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t r = 0; r < repeats; ++r) sink += pass();
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    times.push_back(s * 1e9 / static_cast<double>(repeats * n));
  }
  if (sink == 0.125) std::printf(" ");  // keeps the passes' results alive
  std::nth_element(times.begin(), times.begin() + 3, times.end());
  return times[3];
}

}  // namespace

int main() {
  constexpr std::size_t kN = 3000;
  Arrays a = make_arrays(kN);
  const Isa isas[] = {Isa::portable, Isa::avx2, Isa::avx512};
  double portable[4] = {};
  std::printf(
      "| instruction set | select_low, diagonal read | select_low, uniform diagonal | "
      "conjugate update | update | speed-up on select_low (uniform) |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (const Isa isa : isas) {
    const Loops* table = fogdrift::svr::detail::loops_for(isa);
    if (table == nullptr) continue;
    const Loops& l = *table;
    const double t[4] = {
        ns_per_sample(kN,
                      [&] {
                        return static_cast<double>(l.select_low(a.f.data(), a.low.data(),
                                                                a.k_i.data(), a.qd.data(), 1.0, 0.3,
                                                                1e-12, kN)
                                                       .index);
                      }),
        ns_per_sample(kN,
                      [&] {
                        return static_cast<double>(l.select_low(a.f.data(), a.low.data(),
                                                                a.k_i.data(), nullptr, 1.0, 0.3,
                                                                1e-12, kN)
                                                       .index);
                      }),
        // Steps small enough that f stays in range over every pass.
        ns_per_sample(kN,
                      [&] {
                        return static_cast<double>(l.conjugate_update_and_select_up(
                                                        a.f.data(), a.up.data(), a.k_i.data(),
                                                        a.k_j.data(), a.kd.data(), 1e-9, 1e-12, kN)
                                                       .index);
                      }),
        ns_per_sample(kN, [&] {
          return static_cast<double>(l.update_and_select_up(a.f.data(), a.up.data(), a.k_i.data(),
                                                            a.k_j.data(), 1e-12, -1e-12, kN)
                                         .index);
        })};
    if (isa == Isa::portable) std::copy(t, t + 4, portable);
    std::printf("| %s | %.3f | %.3f | %.3f | %.3f | %.2f× |\n",
                std::string(fogdrift::svr::detail::isa_name(isa)).c_str(), t[0], t[1], t[2], t[3],
                portable[1] / t[1]);
  }
  return 0;
}
