// fogdrift's ε-SVR engine against LIBSVM, in one process on the same data (issue: SVR engine).
//
//   svr_vs_libsvm [--sizes 2000,6000] [--repeats 3] [--sweep-n 6000] [--no-sweep] [--no-threads]
//                 [--libsvm-path] [--no-conjugate] [--no-newton]
//   svr_vs_libsvm --write-data N FILE   (the data as a LIBSVM file, for whole commands)
//
// Data: tests/svr/datasets.hpp startup_like(N), d = 9, standardised features and target.
// Grid: C ∈ {1, 10, 100}, σ ∈ {0.5, 1, 2} (γ = 1/(2σ²)), ε = 0.1, tolerance 1e-3, shrinking on,
// a 200 MB kernel cache for both. Times are medians over the repeats (wall clock, one thread).
// Prints Markdown tables for bench/RESULTS.md.
#include <svm.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/svr/libsvm_format.hpp"
#include "fogdrift/svr/svr.hpp"
#include "libsvm_data.hpp"
#include "svr/datasets.hpp"

namespace {

using fogdrift::bench::Clock;
using fogdrift::bench::median;
using fogdrift::bench::seconds_since;
using fogdrift::svr::Data;

// LIBSVM reports the objective only through its print hook; keep the last one.
double g_libsvm_obj = 0;
void capture_libsvm(const char* s) {
  const char* p = std::strstr(s, "obj = ");
  if (p) g_libsvm_obj = std::strtod(p + 6, nullptr);
}

using fogdrift::bench::LibsvmData;

struct LibsvmFit {
  double seconds, obj;
  int n_sv;
};

LibsvmFit libsvm_fit(LibsvmData& data, double c, double gamma) {
  svm_parameter p{};
  p.svm_type = EPSILON_SVR;
  p.kernel_type = RBF;
  p.gamma = gamma;
  p.cache_size = 200;
  p.eps = 1e-3;
  p.C = c;
  p.p = 0.1;
  p.shrinking = 1;
  const auto t = Clock::now();
  svm_model* m = svm_train(&data.prob, &p);
  const double s = seconds_since(t);
  LibsvmFit out{s, g_libsvm_obj, m->l};
  svm_free_and_destroy_model(&m);
  return out;
}

bool g_libsvm_path = false;  // --libsvm-path: fogdrift's solver that follows LIBSVM's path
bool g_conjugate = true;     // --no-conjugate: the pair solver without conjugate steps
bool g_newton = true;        // --no-newton: the pair solver without free-set Newton steps

fogdrift::svr::Params params_for(double c, double sigma) {
  fogdrift::svr::Params p;
  p.libsvm_path = g_libsvm_path;
  p.conjugate = g_conjugate;
  p.newton = g_newton;
  p.kernel = fogdrift::svr::Kernel::rbf_sigma(sigma);
  p.c = c;
  p.epsilon = 0.1;
  p.tolerance = 1e-3;
  p.cache_mb = 200;
  return p;
}

std::vector<std::size_t> parse_sizes(const char* s) {
  std::vector<std::size_t> out;
  for (const char* p = s; *p;) {
    out.push_back(std::strtoul(p, const_cast<char**>(&p), 10));
    if (*p == ',') ++p;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::size_t> sizes{2000, 6000};
  int repeats = 3;
  std::size_t sweep_n = 6000;
  bool sweep = true, threads = true;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--sizes" && i + 1 < argc)
      sizes = parse_sizes(argv[++i]);
    else if (a == "--repeats" && i + 1 < argc)
      repeats = std::atoi(argv[++i]);
    else if (a == "--sweep-n" && i + 1 < argc)
      sweep_n = std::strtoul(argv[++i], nullptr, 10);
    else if (a == "--no-sweep")
      sweep = false;
    else if (a == "--no-threads")
      threads = false;
    else if (a == "--libsvm-path")
      g_libsvm_path = true;
    else if (a == "--no-conjugate")
      g_conjugate = false;
    else if (a == "--no-newton")
      g_newton = false;
    else if (a == "--write-data" && i + 2 < argc) {
      // The bench's data as a LIBSVM file, for whole-command timings
      // (bench/svr_command_vs_svm_train.sh).
      const std::size_t n = std::strtoul(argv[++i], nullptr, 10);
      fogdrift::svr::write_libsvm_data(fogdrift::svr::testing::startup_like(n), argv[++i]);
      return 0;
    } else {
      std::fprintf(
          stderr,
          "usage: %s [--sizes N,N] [--repeats R] [--sweep-n N] [--no-sweep] "
          "[--no-threads] [--libsvm-path] [--no-conjugate] [--no-newton] | --write-data N FILE\n",
          argv[0]);
      return 2;
    }
  }
  svm_set_print_string_function(capture_libsvm);
  const double cs[] = {1, 10, 100};
  const double sigmas[] = {0.5, 1, 2};

  std::printf("### Cold fits, one thread (median of %d)\n\n", repeats);
  std::printf(
      "fogdrift s: the median of the repeats, each reusing the memory of the fits before it "
      "through one\nWorkspace (as in a search); first fit s: once more with no workspace, "
      "paying every page fault.\n\n");
  std::printf(
      "| N | C | σ | LIBSVM s | fogdrift s | speed-up | first fit s | speed-up | obj LIBSVM | "
      "obj fogdrift | rel. diff | nSV LIBSVM | nSV fogdrift |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t n : sizes) {
    const Data data = fogdrift::svr::testing::startup_like(n);
    LibsvmData ldata(data);
    const fogdrift::svr::TrainingSet set(data);
    fogdrift::svr::Workspace workspace;  // what a search's fits reuse (docs/svr.md, "Memory")
    std::vector<double> ratios, first_ratios;
    for (double c : cs) {
      for (double sigma : sigmas) {
        const double gamma = 1.0 / (2 * sigma * sigma);
        std::vector<double> tl, tf;
        LibsvmFit lf{};
        fogdrift::svr::FitResult ff;
        for (int r = 0; r < repeats; ++r) {
          lf = libsvm_fit(ldata, c, gamma);
          tl.push_back(lf.seconds);
          const auto t = Clock::now();
          ff = fogdrift::svr::fit(set, params_for(c, sigma), nullptr, &workspace);
          tf.push_back(seconds_since(t));
        }
        const auto t = Clock::now();  // with no memory kept from earlier fits
        fogdrift::svr::fit(set, params_for(c, sigma));
        const double first = seconds_since(t);
        const double ml = median(tl), mf = median(tf);
        ratios.push_back(ml / mf);
        first_ratios.push_back(ml / first);
        const double obj = ff.summary.solver.objective;
        std::printf(
            "| %zu | %g | %g | %.3f | %.3f | %.1f× | %.3f | %.1f× | %.6f | %.6f | %.1e | %d | %zu "
            "|\n",
            n, c, sigma, ml, mf, ml / mf, first, ml / first, lf.obj, obj,
            std::fabs(obj - lf.obj) / std::max(1e-300, std::fabs(lf.obj)), lf.n_sv,
            ff.summary.n_sv);
        std::fflush(stdout);
      }
    }
    std::printf("| %zu | | | | | **median %.1f×** | | **median %.1f×** | | | | | |\n", n,
                median(ratios), median(first_ratios));
  }

  if (sweep) {
    const Data data = fogdrift::svr::testing::startup_like(sweep_n);
    LibsvmData ldata(data);
    const fogdrift::svr::TrainingSet set(data);
    std::vector<double> c_values;
    for (int k = 0; k < 20; ++k) c_values.push_back(0.1 * std::pow(1000.0, k / 19.0));
    const double sigma = 1.0;
    double libsvm_total = 0;
    std::vector<double> lobj;
    for (double c : c_values) {
      const auto f = libsvm_fit(ldata, c, 1.0 / (2 * sigma * sigma));
      libsvm_total += f.seconds;
      lobj.push_back(f.obj);
    }
    std::vector<double> tf;
    std::vector<fogdrift::svr::FitResult> path;
    for (int r = 0; r < repeats; ++r) {
      const auto t = Clock::now();
      path = fogdrift::svr::fit_c_path(set, params_for(1, sigma), c_values);
      tf.push_back(seconds_since(t));
    }
    double worst = 0;
    for (std::size_t k = 0; k < c_values.size(); ++k)
      worst = std::max(worst,
                       std::fabs(path[k].summary.solver.objective - lobj[k]) / std::fabs(lobj[k]));
    std::printf(
        "\n### Warm-started sweep: 20 values of C from 0.1 to 100 (log-spaced), σ = 1, "
        "N = %zu\n\n",
        sweep_n);
    std::printf(
        "| 20 cold LIBSVM fits s | fogdrift warm path s (median of %d) | speed-up | "
        "worst rel. obj diff |\n|---|---|---|---|\n",
        repeats);
    std::printf("| %.2f | %.3f | %.1f× | %.1e |\n", libsvm_total, median(tf),
                libsvm_total / median(tf), worst);
    std::fflush(stdout);
  }

  if (threads) {
    const Data data = fogdrift::svr::testing::startup_like(sweep_n);
    const fogdrift::svr::TrainingSet set(data);
    std::vector<fogdrift::svr::Params> grid;
    for (double c : cs)
      for (double sigma : sigmas) grid.push_back(params_for(c, sigma));
    std::printf("\n### Nine-candidate batch (the C × σ grid), N = %zu, fit_batch\n\n", sweep_n);
    std::printf("| threads | seconds (median of %d) | speed-up over 1 thread |\n|---|---|---|\n",
                repeats);
    double one = 0;
    for (unsigned th : {1u, 2u}) {
      fogdrift::ThreadPool pool(th);
      std::vector<double> t;
      for (int r = 0; r < repeats; ++r) {
        const auto t0 = Clock::now();
        auto res = fogdrift::svr::fit_batch(set, grid, pool);
        t.push_back(seconds_since(t0));
      }
      if (th == 1) one = median(t);
      std::printf("| %u | %.3f | %.2f× |\n", th, median(t), one / median(t));
    }
  }
  return 0;
}
