#include "fogdrift/train/train.hpp"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>

#include "fogdrift/base/error.hpp"
#include "fogdrift/base/version.hpp"
#include "fogdrift/regress/poly.hpp"
#include "fogdrift/train/trainers.hpp"

namespace fogdrift {
namespace {

// A polynomial of degree 1 in one input: the straight line held_out.hpp compares models with.
bool is_a_line_in_one_input(const CompensationModel& m) {
  const Poly* poly = m.regressor.get_if<Poly>();
  return poly != nullptr && poly->degree <= 1 && poly->inputs == 1;
}

}  // namespace

TrainOptions resolved(const TrainOptions& options) {
  TrainOptions r = options;
  const Method& m = options.method;
  Search requested = m.search;
  if (options.search != Search::own) {
    if (m.search != Search::own && options.search != m.search) {
      const std::string method = to_string(m), search(to_string(options.search));
      throw OptionError(
          "search", fmt::format("'{}' contradicts {{method}} {}, which is {} searched by {}; "
                                "give {{method}} {} with {{search}} {}",
                                search, method, m.trainer, to_string(m.search), m.trainer, search));
    }
    requested = options.search;
  }
  r.method.search = trainer(m.trainer).search(requested, options);
  r.search = Search::own;
  if (is_optimizer(r.method.search)) r.tune.optimizer.algorithm = optimizer_of(r.method.search);
  return r;
}

void validate(const TrainOptions& given) {
  const TrainOptions options = resolved(given);
  trainer(options.method.trainer).validate(options);
}

TrainResult train(const Dataset& data, const DatasetOptions& dataset, const TrainOptions& given) {
  const auto start = std::chrono::steady_clock::now();
  const TrainOptions options = resolved(given);
  const TrainerEntry& method = trainer(options.method.trainer);
  method.validate(options);
  if (data.rows == 0) throw OptionError("data", "there are no training rows");

  // Scalers of all training rows, for the final fit of every method.
  std::vector<std::size_t> rows(data.rows);
  std::iota(rows.begin(), rows.end(), 0);
  const tune::ScaledSplit full = tune::scale_split(data, rows, {});
  Trained t = method.train({data, full, options});

  TrainResult out;
  TrainSummary& s = out.summary;
  s = std::move(t.summary);
  s.method = options.method;
  s.rows = data.rows;
  CompensationModel& m = out.model;
  m.dataset = dataset;
  m.feature_names = data.feature_names;
  m.x_scaler = t.x_scaler.value_or(full.x_scaler);
  m.y_scaler = t.y_scaler.value_or(full.y_scaler);
  m.regressor = std::move(t.regressor);
  Provenance& p = m.provenance;
  p.method = to_string(options.method);
  p.search = t.search;
  p.seed = options.tune.optimizer.run.seed;
  p.population = t.population;
  p.iterations = t.iterations;
  p.cv = t.cv;
  p.training_rows = data.rows;
  p.fogdrift_version = kVersion;

  // The guard's region: every training row, standardised as the regressor sees it, its unit
  // set by the spacing of the calibration temperatures (guard.hpp).
  std::vector<double> z = data.x;
  m.x_scaler.apply(z);
  std::vector<double> temps;
  for (const GroupInfo& g : data.groups) temps.push_back(g.initial_temp_degc);
  std::vector<std::size_t> labels(data.rows), conditions(data.rows);
  for (std::size_t i = 0; i < data.rows; ++i) {
    conditions[i] = static_cast<std::size_t>(data.groups[data.group[i]].repetition);
    std::size_t k = 0;
    while (temps[k] != temps[data.group[i]]) ++k;  // the first group of the same temperature
    labels[i] = k;
  }
  m.guard = NoveltyGuard::fit(z, data.cols(), labels, conditions, options.guard);
  m.guard.set_warmup_inputs(m.dataset.features.rate_inputs());
  m.baselines = fit_training_baselines(data);
  if (options.held_out && !t.held_folds.empty())
    s.held_out =
        held_out_report(data, t.held_folds, t.held_predict, t.held_description,
                        startup_warning_share(m.dataset.denoise_target), is_a_line_in_one_input(m));
  p.fitness = s.fitness;
  p.fitness_value = s.fitness_value;
  p.hyperparameters = s.hyperparameters;
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace fogdrift
