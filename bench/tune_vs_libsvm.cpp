// A paper-sized hyperparameter search (SSA, population 20, 50 iterations, `train`'s defaults:
// features T,dT,grad,dT@300, three folds of whole initial temperatures) with fogdrift's tuner,
// with racing (the default), with every fold of every candidate fitted, and with racing but
// without the SVR solver's Newton steps (docs/svr.md), against the same
// search made the usual way: every fold of every candidate fitted cold by LIBSVM, one at a time
// (what a mealpy + scikit-learn / LIBSVM script does, which never stops a candidate early).
//
//   tune_vs_libsvm CAMPAIGN [--runs 3] [--threads 2] [--sample 90]
//
// CAMPAIGN is a calibration campaign folder (e.g. `fogdrift simulate calibration --out cal`);
// the training recordings are used, averaged to 10 s. Each search is run `runs` times (same
// seed, same result; the median wall time is reported). LIBSVM's time is measured on `sample`
// complete candidates spread evenly over the full search's history, each fitted on every fold
// and predicted on the held-out fold, and scaled to that search's candidates × folds; fogdrift's
// engine is timed on the same sample, cold and on one thread, for the per-fit ratio.
#include <svm.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/features/features.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/train/tune.hpp"
#include "libsvm_data.hpp"

namespace {

using namespace fogdrift;
using fogdrift::bench::median;

void quiet(const char*) {}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') {
    std::fprintf(stderr, "usage: tune_vs_libsvm CAMPAIGN [--runs N] [--threads N] [--sample N]\n");
    return 2;
  }
  const std::string campaign_dir = argv[1];
  int runs = 3;
  unsigned threads = 2;
  std::size_t sample = 90;
  for (int i = 2; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--runs")) runs = std::atoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--threads")) threads = static_cast<unsigned>(std::atoi(argv[i + 1]));
    if (!std::strcmp(argv[i], "--sample"))
      sample = static_cast<std::size_t>(std::atoi(argv[i + 1]));
  }
  svm_set_print_string_function(quiet);

  const Campaign campaign = read_campaign(campaign_dir);
  DatasetOptions dataset_options;
  dataset_options.features = recommended_feature_spec({"fog", "acc1", "acc2"});
  const Dataset data = build_dataset(campaign, Role::train, Scenario::calibration, dataset_options);
  ThreadPool pool(threads);
  tune::TuneOptions options;  // SSA, 20 × 50, cv over folds of whole temperatures, racing
  options.pool = &pool;
  tune::TuneOptions every_fold = options;
  every_fold.racing = false;
  tune::TuneOptions no_newton = options;  // the search before the solver's Newton steps
  no_newton.newton = false;

  auto search = [&](const tune::TuneOptions& o, const char* name, std::vector<double>& walls) {
    tune::TuneSummary out;
    for (int r = 0; r < runs; ++r) {
      out = tune::tune_svr(data, o);
      walls.push_back(out.seconds);
      std::fprintf(stderr, "%s run %d: %.1f s, best C %.4g sigma %.4g cv RMSE %.5f, %zu fits\n",
                   name, r + 1, out.seconds, out.best.c, out.best.kernel.sigma(), out.best_fitness,
                   out.fits);
    }
    return out;
  };
  // Interleaved run by run would share the noise better, but each search's runs are the same
  // search, so their spread is the machine's.
  std::vector<double> walls, full_walls, plain_walls;
  const tune::TuneSummary raced = search(options, "racing", walls);
  const tune::TuneSummary s = search(every_fold, "every fold", full_walls);
  const tune::TuneSummary plain = search(no_newton, "racing, no Newton steps", plain_walls);

  // The same folds, fitted cold by each engine on a sample of complete candidates.
  bench::FoldPair folds(data, options.cv);
  const std::size_t n = s.history.size();
  sample = std::min(sample, n);
  double t_lib = 0, t_ours = 0, worst_rel = 0;
  for (std::size_t k = 0; k < sample; ++k) {
    const tune::Candidate& c = s.history[k * n / sample];
    const bench::FoldPair::Scored r = folds.score(c.params, options.cache_mb);
    t_lib += r.libsvm_s;
    t_ours += r.fogdrift_s;
    worst_rel = std::max(worst_rel, std::abs(r.libsvm_loss - c.loss) / c.loss);
  }
  const double per_fit_lib = t_lib / static_cast<double>(sample * folds.folds());
  const double per_fit_ours = t_ours / static_cast<double>(sample * folds.folds());
  const double lib_total = per_fit_lib * static_cast<double>(s.candidates * folds.folds());
  const double wall = median(walls), full_wall = median(full_walls);

  std::printf("| quantity | value |\n|---|---|\n");
  std::printf("| training rows, features, folds | %zu, %zu, %zu |\n", data.rows, data.cols(),
              folds.folds());
  std::printf(
      "| search, racing (default) | SSA, population 20, 50 iterations: %zu evaluations, %zu "
      "distinct candidates, %zu stopped early, %zu fits |\n",
      raced.optimizer.evaluations, raced.candidates, raced.raced, raced.fits);
  std::printf("| best, racing | C = %.4g, σ = %.4g, CV RMSE %.5f (standardised) |\n", raced.best.c,
              raced.best.kernel.sigma(), raced.best_fitness);
  std::printf("| search, every fold (`--no-racing`) | %zu distinct candidates, %zu fits |\n",
              s.candidates, s.fits);
  std::printf("| best, every fold | C = %.4g, σ = %.4g, CV RMSE %.5f (standardised) |\n", s.best.c,
              s.best.kernel.sigma(), s.best_fitness);
  auto print_walls = [&](const char* name, double w, const std::vector<double>& all) {
    std::printf("| %s, %u threads, wall (median of %d) | **%.1f s** (runs:", name, threads, runs,
                w);
    for (double x : all) std::printf(" %.1f", x);
    std::printf(") |\n");
  };
  print_walls("fogdrift search, racing", wall, walls);
  print_walls("fogdrift search, every fold", full_wall, full_walls);
  std::printf("| ratio every fold / racing | %.2f× |\n", full_wall / wall);
  print_walls("fogdrift search, racing, no Newton steps", median(plain_walls), plain_walls);
  std::printf(
      "| best, racing, no Newton steps | C = %.4g, σ = %.4g, CV RMSE %.5f (standardised) |\n",
      plain.best.c, plain.best.kernel.sigma(), plain.best_fitness);
  std::printf("| ratio no Newton steps / racing | %.2f× |\n", median(plain_walls) / wall);
  std::printf("| fogdrift fit + predict, cold, 1 thread, mean of %zu sampled fits | %.1f ms |\n",
              sample * folds.folds(), 1e3 * per_fit_ours);
  std::printf("| LIBSVM fit + predict, cold, 1 thread, same fits | %.1f ms |\n", 1e3 * per_fit_lib);
  std::printf(
      "| LIBSVM equivalent of the search (%zu candidates × %zu folds × mean) | **%.0f s** |\n",
      s.candidates, folds.folds(), lib_total);
  std::printf("| ratio LIBSVM equivalent / fogdrift search, racing | **%.1f×** |\n",
              lib_total / wall);
  std::printf("| ratio LIBSVM equivalent / fogdrift search, every fold | %.1f× |\n",
              lib_total / full_wall);
  std::printf("| per-fit ratio, one thread | %.1f× |\n", per_fit_lib / per_fit_ours);
  std::printf(
      "| worst relative difference of LIBSVM's CV loss from fogdrift's, sampled candidates "
      "| %.1e |\n",
      worst_rel);
  return 0;
}
