// fogdrift.train: a campaign folder to a compensation model, with every option of
// `fogdrift train` under the library's own field names, and a progress callback
// (train_campaign.hpp, docs/python.md).
#include <fmt/format.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <exception>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/model/model_set.hpp"
#include "fogdrift/signal/differentiate.hpp"
#include "fogdrift/train/svr_trainer.hpp"
#include "fogdrift/train/train_campaign.hpp"
#include "fogdrift/train/train_option_table.hpp"
#include "fogdrift/train/train_summary.hpp"
#include "option_keywords.hpp"

namespace py = pybind11;

namespace fogdrift::python {
namespace {

// The keywords only Python has: how the call runs and what it returns, not what the model is,
// each with its default. `progress` is described here and read by hand (a callable has no text).
struct PythonKeyword {
  OptionSpec spec;
  std::string default_text;
};

const std::vector<PythonKeyword>& python_only() {
  const DatasetOptions dataset = DatasetOptions();  // the default target
  static const std::vector<PythonKeyword> keywords = {
      {{"threads",
        "",
        OptionType::whole,
        "",
        "",
        "Threads (0: one per core); results do not depend on it",
        {}},
       "0"},
      {{"target",
        "",
        OptionType::text,
        "",
        "",
        "The column to compensate, gyro_dph or another gyro axis the recordings carry "
        "(gyro_y_dph, ...), an accelerometer (accel_x_g, accel_NAME_g) or a scale-factor "
        "channel (sf_NAME_ppm), each less its reference in the manifest (docs/logs.md, \"Other "
        "targets\"); save_models writes the models of every axis as one file, as `fogdrift "
        "train --targets` does",
        {}},
       dataset.target_column},
      {{"progress",
        "",
        OptionType::text,
        "",
        "",
        "How the search shows its progress: 'auto', a tqdm bar when tqdm is installed, else "
        "a line on standard error every 5 s when it is a terminal; True, a bar or the lines "
        "wherever standard error goes; 'lines'; False or None, nothing; or a callable, called "
        "after each iteration with a dict (iteration, iterations, evaluations, best_rmse, "
        "best_point), returning False to stop the search (docs/python.md, \"Progress\")",
        {}},
       "auto"},
      {{"validate_only",
        "",
        OptionType::on_off,
        "",
        "",
        "Check the options and return None without reading the campaign (train_fleet does, "
        "once, before any unit runs)",
        {}},
       "false"}};
  return keywords;
}

/// The Python-only keyword named `keyword`, or nullptr.
const OptionSpec* python_only_spec(std::string_view keyword) {
  for (const PythonKeyword& k : python_only())
    if (k.spec.keyword == keyword) return &k.spec;
  return nullptr;
}

py::object train(const py::object& campaign, const py::kwargs& kwargs) {
  const OptionTable<CampaignTrainOptions>& table = train_option_table();
  const std::vector<OptionSpec> specs = specs_of(table);
  for (const auto& [key, value] : kwargs) {
    const auto k = key.cast<std::string>();
    const bool known = find_option(table, k) || python_only_spec(k);
    if (!known) {
      std::string all;
      for (const auto& s : specs) all += (all.empty() ? "" : ", ") + s.keyword;
      for (const PythonKeyword& p : python_only()) all += ", " + p.spec.keyword;
      throw py::type_error(fmt::format(
          "train() got an unexpected keyword argument '{}'; its keywords are campaign, {}", k,
          all));
    }
  }
  const auto given = [&](const std::string& k) { return kwargs.contains(k.c_str()); };
  const auto text_of = [&](const OptionSpec& spec) {
    return keyword_text(spec, kwargs[spec.keyword.c_str()], "train");
  };
  CampaignTrainOptions o;
  // The table's options in its order (features after thermometers), errors in keywords.
  in_keywords([&] {
    for (const auto& option : table)
      if (given(option.spec.keyword)) option.set(o, text_of(option.spec));
  });
  if (given("target")) o.dataset.target_column = text_of(*python_only_spec("target"));
  target_of(o.dataset.target_column, "target");
  std::uint64_t threads = 0;
  if (given("threads")) {
    const OptionSpec& spec = *python_only_spec("threads");
    threads = parse_whole_option(spec, text_of(spec));
  }
  const OptionSpec& validate_spec = *python_only_spec("validate_only");
  const bool validate_only =
      given("validate_only") && parse_on_off_option(validate_spec, text_of(validate_spec));
  py::object progress = py::none();
  if (given("progress")) progress = kwargs["progress"];
  if (!progress.is_none() && !PyCallable_Check(progress.ptr()))
    throw py::type_error("train(): progress must be callable or None, not " +
                         py::type::of(progress).attr("__name__").cast<std::string>());
  TrainOptions& t = o.train;
  const std::size_t iterations = t.tune.optimizer.run.iterations;
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
  if (validate_only) {
    in_keywords([&] { validate(t); });
    return py::none();
  }
  // A folder (or its campaign.json), or a campaign held in memory.
  std::optional<std::filesystem::path> path;
  std::optional<HeldCampaign> held;
  if (py::isinstance<py::dict>(campaign)) {
    held = held_campaign(campaign);
  } else if (py::isinstance<py::str>(campaign) || py::hasattr(campaign, "__fspath__")) {
    path = campaign.cast<std::filesystem::path>();
  } else {
    const std::string type = py::str(py::type::of(campaign).attr("__qualname__"));
    throw py::type_error(
        "train(): campaign must be a folder (str or os.PathLike) or a campaign in memory (the "
        "dict fogdrift.simulate returns), not " +
        type +
        (py::isinstance<py::list>(campaign) || py::isinstance<py::tuple>(campaign)
             ? "; for one model per unit's campaign use fogdrift.train_fleet(campaigns)"
             : ""));
  }
  std::optional<CampaignTrainResult> r;
  released_interruptibly([&] {
    ThreadPool pool(static_cast<unsigned>(threads));
    t.tune.pool = &pool;
    in_keywords([&] {
      if (held)
        r.emplace(train_campaign(held->campaign, held->recordings, o));
      else
        r.emplace(train_campaign(read_campaign(*path), o));
    });
  });
  if (callback_error) std::rethrow_exception(callback_error);
  const TrainSummary& s = r->trained.summary;
  // The library's summary (`fogdrift train --json`'s keys), its advice in this function's
  // keywords; then what Python keeps its own way: notes as (keyword, text) pairs, no held_out
  // when there is none, and the box-edge advice among the warnings.
  const OptionWords keywords{
      [](const std::string& field) { return keyword_of(field); },
      [&](const std::string& text) { return in_option_words(text, specs, false); }};
  py::dict summary = from_json(summary_json(*r, keywords).dump()).cast<py::dict>();
  py::list notes;
  for (const auto& n : r->notes) notes.append(py::make_tuple(keyword_of(n.field), n.text));
  summary["notes"] = notes;
  if (!s.held_out) summary["held_out"] = py::none();
  py::list warnings = summary["warnings"];
  // A model that does not beat the baselines is a warning a Python user sees, not only a key.
  if (s.held_out)
    for (const auto& w : s.held_out->warnings) warn(in_option_words(w, specs, false).c_str());
  for (const std::string& w :
       box_edge_warnings(s, t.auto_box_rounds > 0, [&](const std::string& field) {
         return field == "auto_box"         ? std::string("auto_box=True")
                : field == "search_epsilon" ? std::string("search_epsilon=True")
                                            : option_word(specs, field, false);
       })) {
    warnings.append(w);
    warn(w.c_str());
  }
  py::dict out;
  out["model"] = py::cast(std::move(r->trained.model));
  out["summary"] = summary;
  return out;
}

}  // namespace

void bind_train(py::module_& m) {
  m.def("train", &train, py::arg("campaign"),
        "Trains a compensation model on a campaign's training recordings, as `fogdrift train` "
        "does; returns {'model': Model, 'summary': dict}. campaign: a folder (or its "
        "campaign.json), or a campaign in memory: a dict with the manifest's fields and 'data', "
        "one recording per entry (what fogdrift.simulate returns); the same model bytes either "
        "way. Its keywords are `fogdrift train`'s options under their library names "
        "(docs/options.md), then threads, target, progress and validate_only.");
  m.def(
      "train_options",
      [] {
        py::list out =
            describe_options(specs_of(train_option_table()), defaults_of(train_option_table()));
        std::vector<OptionSpec> specs;
        std::vector<std::string> defaults;
        for (const PythonKeyword& k : python_only()) {
          specs.push_back(k.spec);
          defaults.push_back(k.default_text);
        }
        py::list extra = describe_options(specs, defaults);
        for (const auto& d : extra) out.append(d);
        return out;
      },
      "fogdrift.train's keywords, in order: one dict per keyword with its type, default (as "
      "text), unit, doc and the flag of `fogdrift train` that sets it (empty for the keywords "
      "only Python has).");
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
