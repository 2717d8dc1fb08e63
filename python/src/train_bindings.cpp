// fogdrift.train: a campaign folder to a compensation model, with every option of
// `fogdrift train` under the library's own field names, and a progress callback
// (train_campaign.hpp, docs/python.md).
#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <exception>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "fogdrift/campaign.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/model_set.hpp"
#include "fogdrift/signal/differentiate.hpp"
#include "fogdrift/thread_pool.hpp"
#include "fogdrift/train_campaign.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

const TrainOptions kTrain;
const opt::RunOptions kRun;
const tune::SearchSpace kSpace;

py::object train(const py::object& campaign, const std::string& method, const std::string& fitness,
                 const std::string& cv, std::size_t folds, const std::string& features,
                 const py::object& thermometers, const std::string& differentiator,
                 const py::object& block_s, const py::object& rate_window_s,
                 const py::object& rate_degree, std::size_t population, std::size_t iterations,
                 std::uint64_t seed, int threads, double c_min, double c_max, double sigma_min,
                 double sigma_max, double epsilon, bool search_epsilon, bool auto_box, bool racing,
                 bool denoise, std::size_t hidden, std::size_t max_degree, std::size_t gp_points,
                 const std::string& gp_fit, const std::string& gp_kernel,
                 const py::object& progress, const std::string& target, bool validate_only) {
  CampaignTrainOptions o;
  target_of(target, "target");
  o.dataset.target_column = target;
  TrainOptions& t = o.train;
  t.method = parse_method(method, "method");
  t.tune.fitness = tune::parse_fitness(fitness, "fitness");
  t.tune.cv.scheme = tune::parse_cv_scheme(cv, "cv");
  t.tune.cv.folds = folds;
  // "auto", a list of names, or one comma-separated string of them (train --thermometers).
  std::vector<std::string> listed;
  if (py::isinstance<py::str>(thermometers)) {
    if (thermometers.cast<std::string>() != "auto")
      listed = parse_thermometers(thermometers.cast<std::string>());
  } else {
    std::string joined;
    for (const py::handle& name : thermometers) {
      if (!py::isinstance<py::str>(name))
        throw py::type_error("thermometers: 'auto' or a list of names such as ['fog', 'case']");
      joined += (joined.empty() ? "" : ",") + name.cast<std::string>();
    }
    listed = parse_thermometers(joined);
  }
  o.auto_features = features == "auto";
  o.thermometers = listed;
  if (!o.auto_features) o.dataset.features = FeatureSpec::parse(features, listed);
  o.dataset.preprocessing.rates.causality = signal::parse_causality(differentiator);
  o.block_s = seconds_or_auto(block_s, "block_s");
  o.rate_window_s = seconds_or_auto(rate_window_s, "rate_window_s");
  if (!(py::isinstance<py::str>(rate_degree) && rate_degree.cast<std::string>() == "auto")) {
    if (!py::isinstance<py::int_>(rate_degree) || rate_degree.cast<long>() < 1 ||
        rate_degree.cast<long>() > 4)
      throw OptionError("rate_degree", "must be 'auto' or a whole degree 1..4 (got " +
                                           py::repr(rate_degree).cast<std::string>() + ")");
    o.rate_degree = rate_degree.cast<int>();
  }
  o.dataset.denoise_target = denoise;
  t.tune.optimizer.run.population = population;
  t.tune.optimizer.run.iterations = iterations;
  t.tune.optimizer.run.seed = seed;
  t.tune.space.c_min = c_min;
  t.tune.space.c_max = c_max;
  t.tune.space.sigma_min = sigma_min;
  t.tune.space.sigma_max = sigma_max;
  t.tune.space.epsilon = epsilon;
  t.tune.space.search_epsilon = search_epsilon;
  t.auto_box_rounds = auto_box ? TrainOptions::kAutoBoxRounds : 0;
  t.tune.racing = racing;
  t.mlp.hidden = hidden;
  t.poly_max_degree = max_degree;
  t.gp.max_points = gp_points;
  t.gp.selection = parse_gp_selection(gp_fit, "gp_fit");
  if (gp_kernel != "rbf" && gp_kernel != "ard")
    throw OptionError("gp_kernel", fmt::format("'{}' is not rbf or ard", gp_kernel));
  t.gp.ard = gp_kernel == "ard";
  // The callback runs on the training thread with the GIL taken; an exception in it stops the
  // search and is raised when train returns.
  std::exception_ptr callback_error;
  if (!progress.is_none())
    t.tune.optimizer.run.progress = [&](const opt::IterationRecord& r) {
      py::gil_scoped_acquire gil;
      try {
        py::dict d;
        d["iteration"] = r.iteration;
        d["iterations"] = iterations;
        d["evaluations"] = r.evaluations;
        d["best_rmse"] = r.best_fitness;
        d["best_point"] = r.best_point;
        const py::object go_on = progress(d);
        return go_on.is_none() || go_on.cast<bool>();
      } catch (...) {
        callback_error = std::current_exception();
        return false;
      }
    };
  // What can be checked without the data (train_fleet: once, before any unit runs).
  if (threads < 0)
    throw OptionError("threads", fmt::format("{} is not a number of threads: 0 (every core) or "
                                             "more",
                                             threads));
  if (validate_only) {
    in_keywords([&] { validate(t); });
    return py::none();
  }
  // A folder (or its campaign.json), or a campaign held in memory.
  std::optional<std::filesystem::path> path;
  std::optional<HeldCampaign> held;
  if (py::isinstance<py::dict>(campaign))
    held = held_campaign(campaign);
  else
    path = campaign.cast<std::filesystem::path>();
  std::optional<CampaignTrainResult> r;
  {
    py::gil_scoped_release release;
    ThreadPool pool(static_cast<unsigned>(threads));
    t.tune.pool = &pool;
    in_keywords([&] {
      if (held)
        r.emplace(train_campaign(held->campaign, held->recordings, o));
      else
        r.emplace(train_campaign(read_campaign(*path), o));
    });
  }
  if (callback_error) std::rethrow_exception(callback_error);
  const TrainSummary& s = r->trained.summary;
  py::dict summary;
  summary["method"] = to_string(s.method);
  summary["fitness"] = s.fitness;
  summary["fitness_rmse"] = s.fitness_value;
  py::dict hyper;
  for (const auto& [k, v] : s.hyperparameters) hyper[py::str(k)] = v;
  summary["hyperparameters"] = hyper;
  summary["training_rows"] = s.rows;
  summary["recordings"] = r->data.groups.size();
  summary["features"] = r->data.feature_names;
  summary["block_s"] = r->dataset.preprocessing.block.block_s;
  summary["rate_window_s"] = r->dataset.preprocessing.rates.window_s;
  summary["rate_degree"] = r->dataset.preprocessing.rates.poly_order;
  // The method's own record, under `fogdrift train --json`'s keys.
  if (s.method == Method::bp) {
    py::dict bp;
    bp["epochs"] = s.mlp.epochs;
    bp["best_epoch"] = s.mlp.best_epoch;
    bp["early_stopped"] = s.mlp.status == MlpStatus::early_stopped;
    bp["train_rmse"] = s.mlp.train_rmse;
    summary["bp"] = bp;
  }
  if (s.method == Method::poly) summary["poly_cv_rmse_by_degree"] = s.poly_cv_rmse;
  if (s.method == Method::gp) {
    py::dict gp;
    gp["points"] = s.gp.points;
    gp["log_likelihood"] = s.gp.log_likelihood;
    gp["iterations"] = s.gp.iterations;
    gp["evaluations"] = s.gp.evaluations;
    gp["fold_fits"] = s.gp.fold_fits;
    gp["raced"] = s.gp.raced;
    gp["converged"] = s.gp.converged;
    summary["gp"] = gp;
  }
  py::list notes;
  for (const auto& n : r->notes) notes.append(py::make_tuple(keyword_of(n.field), n.text));
  summary["notes"] = notes;
  std::vector<std::string> warnings = r->data.warnings;
  if (s.held_out) {
    const HeldOutReport& h = *s.held_out;
    py::list base;
    for (const Baseline& b : h.baselines) {
      py::dict d;
      d["name"] = b.name;
      d["rmse"] = b.rmse;
      base.append(d);
    }
    py::dict held;
    held["folds"] = h.folds;
    held["model_rmse"] = h.model_rmse;
    held["expected_share"] = h.expected_share;
    held["expected_startup_share"] = h.expected_startup_share;
    held["baselines"] = base;
    summary["held_out"] = held;
    warnings.insert(warnings.end(), h.warnings.begin(), h.warnings.end());
    // A model that does not beat the baselines is a warning a Python user sees, not only a key.
    for (const std::string& w : h.warnings) warn(w.c_str());
  } else {
    summary["held_out"] = py::none();
  }
  // What `fogdrift train --json` reports of the search, under the same keys.
  summary["cv"] = r->trained.model.provenance.cv;
  py::list edges;
  for (const auto& e : s.box_edges) {
    py::dict d;
    d["parameter"] = e.parameter;
    d["edge"] = e.upper ? "upper" : "lower";
    d["value"] = e.value;
    d["box"] = py::make_tuple(e.low, e.high);
    d["improvement"] = e.improvement;
    edges.append(d);
  }
  summary["box_edges"] = edges;
  py::list boxes;
  for (const auto& b : s.boxes) {
    py::dict d;
    d["c"] = py::make_tuple(b.c_min, b.c_max);
    d["sigma"] = py::make_tuple(b.sigma_min, b.sigma_max);
    boxes.append(d);
  }
  summary["boxes_searched"] = boxes;
  if (s.method == Method::ssa_svr || s.method == Method::pso_svr || s.method == Method::gwo_svr) {
    const auto& tr = s.tuning;
    py::dict search;
    search["optimizer"] = opt::to_string(tr.optimizer.algorithm);
    search["population"] = population;
    search["iterations"] = tr.optimizer.iterations;
    search["evaluations"] = tr.optimizer.evaluations;
    search["candidates"] = tr.candidates;
    search["fits"] = tr.fits;
    search["raced"] = tr.raced;
    search["initial_best_rmse"] = tr.optimizer.initial_best_fitness;
    search["seconds"] = tr.seconds;
    summary["search"] = search;
  } else {
    summary["search"] = py::none();
  }
  // The box-edge warning the command line prints, in this function's keywords, as a warning.
  for (const std::string& w : box_edge_warnings(s, auto_box, [](const std::string& field) {
         return field == "auto_box"         ? std::string("auto_box=True")
                : field == "search_epsilon" ? std::string("search_epsilon=True")
                                            : field;
       })) {
    warnings.push_back(w);
    warn(w.c_str());
  }
  summary["warnings"] = warnings;
  summary["fits"] = s.tuning.fits;
  summary["seconds"] = s.seconds;
  py::dict out;
  out["model"] = py::cast(std::move(r->trained.model));
  out["summary"] = summary;
  return out;
}

}  // namespace

void bind_train(py::module_& m) {
  m.def(
      "train", &train, py::arg("campaign"), py::kw_only(),
      py::arg("method") = to_string(kTrain.method),
      py::arg("fitness") = std::string(tune::to_string(kTrain.tune.fitness)),
      py::arg("cv") = std::string(tune::to_string(kTrain.tune.cv.scheme)),
      py::arg("folds") = kTrain.tune.cv.folds, py::arg("features") = "auto",
      py::arg("thermometers") = "auto",
      py::arg("differentiator") = std::string(signal::to_string(FeatureOptions{}.rates.causality)),
      py::arg("block_s") = "auto", py::arg("rate_window_s") = "auto",
      py::arg("rate_degree") = "auto", py::arg("population") = kRun.population,
      py::arg("iterations") = kRun.iterations, py::arg("seed") = kRun.seed, py::arg("threads") = 0,
      py::arg("c_min") = kSpace.c_min, py::arg("c_max") = kSpace.c_max,
      py::arg("sigma_min") = kSpace.sigma_min, py::arg("sigma_max") = kSpace.sigma_max,
      py::arg("epsilon") = kSpace.epsilon, py::arg("search_epsilon") = false,
      py::arg("auto_box") = false, py::arg("racing") = kTrain.tune.racing,
      py::arg("denoise") = true, py::arg("hidden") = kTrain.mlp.hidden,
      py::arg("max_degree") = kTrain.poly_max_degree, py::arg("gp_points") = kTrain.gp.max_points,
      py::arg("gp_fit") = std::string(to_string(kTrain.gp.selection)),
      py::arg("gp_kernel") = kTrain.gp.ard ? "ard" : "rbf", py::arg("progress") = py::none(),
      py::arg("target") = "gyro_dph", py::arg("validate_only") = false,
      "Trains a compensation model on a campaign's training recordings, as `fogdrift train` "
      "does; returns {'model': Model, 'summary': dict}. campaign: a folder (or its "
      "campaign.json), or a campaign in memory: a dict with the manifest's fields and 'data', "
      "one recording per entry (what fogdrift.simulate returns); the same model bytes either "
      "way. thermometers: the thermometers the features read, e.g. ['fog', 'acc1', 'acc2', "
      "'case'] for a further column temp_case_degc (docs/logs.md, \"More thermometers\"); "
      "'auto': those of fog, acc1, acc2 every recording has. target: the column to "
      "compensate, gyro_dph or another gyro axis the recordings carry (gyro_y_dph, ...), an "
      "accelerometer (accel_x_g, accel_NAME_g) or a scale-factor channel (sf_NAME_ppm), each "
      "less its reference in the manifest (docs/logs.md, \"Other targets\"); save_models writes "
      "the models of every axis as one file, as "
      "`fogdrift train --targets` does. racing: stop a search's candidate once its folds so far "
      "cannot beat the best (False fits every fold, as `train --no-racing`; docs/tuning.md, "
      "\"Speed\"). method='gp': a Gaussian process (docs/gp.md); gp_points, gp_fit ('cv' or "
      "'likelihood') and gp_kernel ('rbf' or 'ard') as `train --gp-points/--gp-fit/--gp-kernel`. "
      "validate_only: check the options and return None "
      "without reading the campaign (train_fleet does, once, before any unit runs).");
  m.def(
      "save_models",
      [](const std::filesystem::path& path, const std::vector<CompensationModel>& models) {
        ModelSet set;
        set.models = models;
        save(set, path);
      },
      py::arg("path"), py::arg("models"),
      "Writes the models of several axes (each trained with its own target) as one model "
      "file, atomically, as `fogdrift train --targets` writes it; Model.load(path, target=...) "
      "reads one back.");
}

}  // namespace fogdrift::python
