// What `train` (SSA-SVR with train's defaults: features T,dT,grad,dT@300, three folds of whole
// initial temperatures, SSA 20 × up to 50 with racing, the stall rule and folds of more than
// 5,000 rows thinned, docs/tuning.md) costs as a campaign grows, beside the same
// search made with LIBSVM fits (docs/tuning.md, "What a campaign of your size costs"):
//
//   rows          by more recordings (repetitions of the paper's chamber sweep, 10 s blocks) and
//                 by a finer averaging block (three training repetitions, 60 s … 2 s blocks);
//   thermometers  1, 2 or 3 of the simulated unit's thermometers (3, 7 or 12 inputs);
//   targets       the gyro, then each accelerometer as a further target (train_campaign fits one
//                 search per target).
//
//   train_growth [--threads 2] [--sample 4] [--measure-up-to 12000] [--max-rows 50000]
//                [--libsvm-up-to 50000]
//
// Every point is a campaign of the default simulated instrument (seed 3). At each point the same
// `sample` candidates (complete ones, spread over the history of the base campaign's search) are
// fitted cold on every fold, one thread, by fogdrift's engine and by LIBSVM: the per-fit times
// (the median of three passes up to 12,000 rows, one pass above; so is the floor).
// Points with at most `measure-up-to` training rows also run the whole `train` on `threads`
// threads. Above that `train` is estimated: the measured `train` of the largest smaller campaign
// on the same axis (else the base campaign), scaled by the ratio of fogdrift's per-fit times.
// Measured points carry the estimate too, to show how good it is: since train thins large
// campaigns' folds (docs/tuning.md, "A search on fewer rows") it overshoots, so --measure-up-to
// 50000 measures every point (about 20 minutes on two cores).
// LIBSVM's search is estimated the way tune_vs_libsvm does it: its per-fit time × the base search's
// candidates × folds (a script never stops a candidate). LIBSVM's fits are skipped above
// `libsvm-up-to` rows (at 49,500 rows one takes minutes).
// The floor beside each fit is one kernel pass: every entry of the largest fold's kernel matrix
// computed once (bench::FoldPair::kernel_pass_s: the fits' own training set, one thread, the
// median σ of the sampled candidates), what an exact fit that touched each pair of rows once would
// cost. A fit costs a multiple of it: the solver's iterations, and the rows its cache evicts and
// computes again.
#include <svm.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/features/features.hpp"
#include "fogdrift/model/dataset.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/svr_trainer.hpp"
#include "fogdrift/train/train.hpp"
#include "fogdrift/train/tune.hpp"
#include "libsvm_data.hpp"

namespace {

using namespace fogdrift;

void quiet(const char*) {}

struct Point {
  std::string axis, campaign;
  int repetitions = 4;  // of the chamber sweep; the last is the test repetition
  double block_s = 10;
  std::vector<std::string> thermometers{"fog", "acc1", "acc2"};
  std::vector<std::string> targets{"gyro_dph"};
};

struct Measured {
  std::size_t point = 0;  // index into the points
  std::size_t rows = 0, inputs = 0;
  double fogdrift_fit_ms = 0, libsvm_fit_ms = 0;  // mean per fold fit, cold, one thread
  double kernel_pass_ms = 0;                      // the floor: one pass, largest fold
  std::optional<double> train_s;                  // whole train, every target, measured
  double train_estimate_s = 0;
  double libsvm_search_s = 0;
};

DatasetOptions dataset_options(const Point& p, const std::string& target) {
  DatasetOptions d;
  d.features = recommended_feature_spec(p.thermometers);
  d.preprocessing.block.block_s = p.block_s;
  d.preprocessing.sample_interval_s = 1.0;  // the simulator logs at 1 Hz
  d.target_column = target;
  return d;
}

// The training recordings of a point's campaign (seed 3), simulated once for all its targets.
std::vector<RecordingInput> training_inputs(const Point& p) {
  sim::CalibrationOptions cal;
  cal.repetitions = p.repetitions;
  cal.seed = 3;
  const sim::SimulatedCampaign c = sim::simulate_calibration(sim::Instrument{}, cal);
  return recording_inputs(c.campaign, c.recordings, Role::train);
}

// Campaigns whose fits (and kernel passes) are timed three times, the median; larger ones once.
constexpr std::size_t kThreePassRows = 12000;

// Least-squares slope of log y against log x: the exponent of y ∝ x^a.
double exponent(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) mx += std::log(x[i]), my += std::log(y[i]);
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (std::log(x[i]) - mx) * (std::log(y[i]) - my);
    sxx += (std::log(x[i]) - mx) * (std::log(x[i]) - mx);
  }
  return sxy / sxx;
}

}  // namespace

int main(int argc, char** argv) {
  unsigned threads = 2;
  std::size_t sample = 4, measure_up_to = 12000, max_rows = 50000, libsvm_up_to = 50000;
  for (int i = 1; i + 1 < argc; i += 2) {
    const auto value = static_cast<std::size_t>(std::atol(argv[i + 1]));
    if (!std::strcmp(argv[i], "--threads"))
      threads = static_cast<unsigned>(value);
    else if (!std::strcmp(argv[i], "--sample"))
      sample = value;
    else if (!std::strcmp(argv[i], "--measure-up-to"))
      measure_up_to = value;
    else if (!std::strcmp(argv[i], "--max-rows"))
      max_rows = value;
    else if (!std::strcmp(argv[i], "--libsvm-up-to"))
      libsvm_up_to = value;
    else {
      std::fprintf(stderr,
                   "usage: train_growth [--threads N] [--sample N] [--measure-up-to ROWS] "
                   "[--max-rows ROWS] [--libsvm-up-to ROWS]\n");
      return 2;
    }
  }
  if (argc % 2 == 0 || threads == 0 || sample == 0) {
    std::fprintf(stderr, "train_growth: every option takes one positive whole number\n");
    return 2;
  }
  svm_set_print_string_function(quiet);
  ThreadPool pool(threads);
  TrainOptions options;  // train's defaults: SSA-SVR, its search, temperature folds, held-out
  options.tune.pool = &pool;

  std::vector<Point> points;
  const Point base{"base", "4 repetitions, 10 s blocks"};
  points.push_back(base);
  for (int reps : {2, 7, 13, 26})
    points.push_back({"recordings", std::to_string(reps) + " repetitions, 10 s blocks", reps});
  for (double block : {60.0, 20.0, 5.0, 2.0})
    points.push_back({"block",
                      "4 repetitions, " + std::to_string(static_cast<int>(block)) + " s blocks", 4,
                      block});
  points.push_back({"thermometers", "fog", 4, 10, {"fog"}});
  points.push_back({"thermometers", "fog, acc1", 4, 10, {"fog", "acc1"}});
  points.push_back(
      {"targets", "gyro, accel x", 4, 10, base.thermometers, {"gyro_dph", "accel_x_g"}});
  points.push_back({"targets",
                    "gyro, accel x, accel y",
                    4,
                    10,
                    base.thermometers,
                    {"gyro_dph", "accel_x_g", "accel_y_g"}});

  // The base campaign's search gives the candidates every point is sampled on.
  std::vector<svr::Params> sampled;
  std::size_t base_candidates = 0;
  std::vector<Measured> out;
  struct PerFit {
    double fogdrift_ms = 0, libsvm_ms = 0, kernel_pass_ms = 0;
    std::size_t folds = 0;
  };
  // A campaign and target met on another axis is not trained or sampled again.
  std::map<std::string, double> trained_s;
  std::map<std::string, PerFit> per_fit;
  for (std::size_t pi = 0; pi < points.size(); ++pi) {
    const Point& p = points[pi];
    Measured m;
    m.point = pi;
    double train_s = 0, ours_ms = 0;
    bool measured = true;
    const std::vector<RecordingInput> inputs = training_inputs(p);
    for (const std::string& target : p.targets) {
      const Dataset data = build_dataset(inputs, dataset_options(p, target));
      m.rows = std::max(m.rows, data.rows);
      m.inputs = data.cols();
      // Every other point is sampled on the base search's candidates and scaled from its time.
      if (pi == 0 && data.rows > std::min(max_rows, measure_up_to)) {
        std::fprintf(stderr,
                     "train_growth: --max-rows and --measure-up-to must reach the base campaign "
                     "(%zu rows)\n",
                     data.rows);
        return 2;
      }
      if (data.rows > max_rows) break;
      std::fprintf(stderr, "[%zu/%zu] %s: %s, target %s, %zu rows, %zu inputs\n", pi + 1,
                   points.size(), p.axis.c_str(), p.campaign.c_str(), target.c_str(), data.rows,
                   data.cols());
      std::string key =
          std::to_string(p.repetitions) + "/" + std::to_string(p.block_s) + "/" + target;
      for (const std::string& t : p.thermometers) key += "/" + t;
      if (const auto done = trained_s.find(key); done != trained_s.end()) {
        train_s += done->second;
      } else if (data.rows <= measure_up_to) {
        const TrainResult r = train(data, dataset_options(p, target), options);
        const tune::TuneSummary& search = r.summary.record.get<SvrTrainer::Record>()->tuning;
        train_s += r.summary.seconds;
        trained_s[key] = r.summary.seconds;
        std::fprintf(stderr, "  train: %.1f s (search %.1f s, %zu candidates, %zu fits)\n",
                     r.summary.seconds, search.seconds, search.candidates, search.fits);
        if (pi == 0) {
          std::vector<const tune::Candidate*> complete;
          for (const auto& c : search.history)
            if (c.complete) complete.push_back(&c);
          sample = std::min(sample, complete.size());
          for (std::size_t k = 0; k < sample; ++k)
            sampled.push_back(complete[k * complete.size() / sample]->params);
          base_candidates = search.candidates;
        }
      } else {
        measured = false;
      }
      if (!per_fit.count(key)) {
        // Fits on up to kThreePassRows rows are timed three times (the median), larger once.
        bench::FoldPair folds(data, options.tune.cv);
        const int passes = data.rows <= kThreePassRows ? 3 : 1;
        std::vector<double> ours_runs, lib_runs;
        for (int run = 0; run < passes; ++run) {
          double ours = 0, lib = 0;
          for (const svr::Params& params : sampled) {
            const bench::FoldPair::Scored sc =
                folds.score(params, options.tune.cache_mb, data.rows <= libsvm_up_to);
            ours += sc.fogdrift_s;
            lib += sc.libsvm_s;
          }
          ours_runs.push_back(ours);
          lib_runs.push_back(lib);
        }
        const double ours = bench::median(ours_runs), lib = bench::median(lib_runs);
        const double fits = static_cast<double>(sampled.size() * folds.folds());
        std::vector<double> sigmas;
        for (const svr::Params& params : sampled) sigmas.push_back(params.kernel.sigma());
        const svr::Kernel kernel = svr::Kernel::rbf_sigma(bench::median(sigmas));
        std::vector<double> pass_runs;
        for (int run = 0; run < passes; ++run) pass_runs.push_back(folds.kernel_pass_s(kernel));
        const double pass_ms = 1e3 * bench::median(pass_runs);
        per_fit[key] = {1e3 * ours / fits, 1e3 * lib / fits, pass_ms, folds.folds()};
        std::fprintf(stderr,
                     "  per fit: fogdrift %.1f ms, LIBSVM %.1f ms; one kernel pass %.1f ms\n",
                     1e3 * ours / fits, 1e3 * lib / fits, pass_ms);
      }
      const PerFit& f = per_fit[key];
      ours_ms += f.fogdrift_ms;
      m.libsvm_search_s += 1e-3 * f.libsvm_ms * static_cast<double>(base_candidates * f.folds);
      // The columns show the mean fit over the targets.
      const double n = static_cast<double>(p.targets.size());
      m.fogdrift_fit_ms += f.fogdrift_ms / n;
      m.libsvm_fit_ms += f.libsvm_ms / n;
      m.kernel_pass_ms += f.kernel_pass_ms / n;
    }
    if (m.rows > max_rows) {
      std::fprintf(stderr, "[%zu/%zu] %s: %s skipped, %zu rows (--max-rows %zu)\n", pi + 1,
                   points.size(), p.axis.c_str(), p.campaign.c_str(), m.rows, max_rows);
      continue;
    }
    if (measured) m.train_s = train_s;
    // Scaled from the measured campaign of this axis (or the base) with the most rows below
    // this one's: the search's fit count and racing change with size, so the nearest is best.
    const Measured* ref = out.empty() ? &m : &out.front();
    for (const Measured& o : out)
      if (points[o.point].axis == p.axis && o.train_s && o.rows < m.rows && o.rows > ref->rows)
        ref = &o;
    m.train_estimate_s = *ref->train_s * ours_ms / ref->fogdrift_fit_ms;
    out.push_back(m);
  }

  std::printf(
      "| axis | campaign | training rows | inputs | one kernel pass, ms (floor) | fogdrift fit, "
      "ms | fit / kernel pass | LIBSVM fit, ms | per-fit ratio | `train` measured, s | `train` "
      "estimated, s | LIBSVM search estimated, s | LIBSVM / `train` "
      "|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  // A figure LIBSVM was not run for (above --libsvm-up-to) is a dash.
  const auto cell = [](double v, const char* format) {
    char text[32] = "—";
    if (std::isfinite(v)) std::snprintf(text, sizeof text, format, v);
    return std::string(text);
  };
  std::vector<double> rows, ours, lib_rows, lib;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const Measured& m = out[i];
    const Point& p = points[m.point];
    const double train_s = m.train_s.value_or(m.train_estimate_s);
    const std::string measured = m.train_s ? cell(*m.train_s, "%.1f") : "—";
    std::printf("| %s | %s | %zu | %zu | %.1f | %.1f | %.1f× | %s | %s | %s | %.0f | %s | %s |\n",
                p.axis.c_str(), p.campaign.c_str(), m.rows, m.inputs, m.kernel_pass_ms,
                m.fogdrift_fit_ms, m.fogdrift_fit_ms / m.kernel_pass_ms,
                cell(m.libsvm_fit_ms, "%.1f").c_str(),
                cell(m.libsvm_fit_ms / m.fogdrift_fit_ms, "%.1f×").c_str(), measured.c_str(),
                m.train_estimate_s, cell(m.libsvm_search_s, "%.0f").c_str(),
                cell(m.libsvm_search_s / train_s, "%.1f×").c_str());
    if (p.axis == "base" || p.axis == "recordings" || p.axis == "block") {
      rows.push_back(static_cast<double>(m.rows));
      ours.push_back(m.fogdrift_fit_ms);
      if (std::isfinite(m.libsvm_fit_ms)) {
        lib_rows.push_back(static_cast<double>(m.rows));
        lib.push_back(m.libsvm_fit_ms);
      }
    }
  }
  std::printf(
      "\nPer-fit time against training rows (both row axes, least squares in log–log): fogdrift "
      "∝ rows^%.2f",
      exponent(rows, ours));
  if (lib.size() >= 2)
    std::printf(", LIBSVM ∝ rows^%.2f (up to %zu rows)", exponent(lib_rows, lib), libsvm_up_to);
  std::printf(
      ". %zu candidates × every fold sampled per point; the base search evaluated %zu distinct "
      "candidates; %u threads for `train`.\n",
      sampled.size(), base_candidates, threads);
  return 0;
}
