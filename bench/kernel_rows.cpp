// RBF kernel rows in the two arithmetics the engine has (docs/svr.md, "The kernel in float"):
// LIBSVM's, in double and rounded to float (the LIBSVM path's), against the float kernel every
// other fit computes, on the same training set in the same run. Prints ns a kernel entry, the
// median of seven passes over the same rows, and the ratio.
//
//   build/bench/kernel_rows            # about 10 s
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "fogdrift/base/random.hpp"
#include "fogdrift/svr/kernel.hpp"
#include "fogdrift/svr/svr.hpp"

namespace {

using fogdrift::svr::Kernel;
using fogdrift::svr::KernelArithmetic;
using fogdrift::svr::TrainingSet;

// Median ns an entry of `rows` rows computed in `arithmetic`, over seven passes.
double ns_per_entry(const TrainingSet& set, const Kernel& kernel, KernelArithmetic arithmetic,
                    std::size_t rows) {
  std::vector<float> out(set.size());
  std::vector<double> passes;
  for (int pass = 0; pass < 7; ++pass) {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t r = 0; r < rows; ++r)
      set.kernel_row(kernel, (r * 7919) % set.size(), out.data(), arithmetic);
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    passes.push_back(s * 1e9 / static_cast<double>(rows * set.size()));
  }
  std::nth_element(passes.begin(), passes.begin() + 3, passes.end());
  return passes[3];
}

}  // namespace

int main() {
  std::printf(
      "| samples | features | LIBSVM's arithmetic, ns an entry | float, ns an entry | ratio |\n");
  std::printf("|---|---|---|---|---|\n");
  for (const std::size_t n : {1000, 4320, 12000}) {
    for (const std::size_t d : {3, 12, 24}) {
      fogdrift::Rng rng(n + d);
      fogdrift::svr::Data data;
      data.rows = n;
      data.cols = d;
      for (std::size_t i = 0; i < n * d; ++i) data.x.push_back(rng.normal());
      for (std::size_t i = 0; i < n; ++i) data.y.push_back(rng.normal());
      // No distance matrix: every row from the features, as a search's folds compute them.
      const TrainingSet set(data, TrainingSet::Options{0, 24, nullptr});
      const Kernel kernel = Kernel::rbf_sigma(2.0);
      const std::size_t rows = std::max<std::size_t>(50, 4'000'000 / (n * d));
      const double libsvm = ns_per_entry(set, kernel, KernelArithmetic::libsvm, rows);
      const double single = ns_per_entry(set, kernel, KernelArithmetic::single, rows);
      std::printf("| %zu | %zu | %.3f | %.3f | %.2f× |\n", n, d, libsvm, single, libsvm / single);
    }
  }
}
