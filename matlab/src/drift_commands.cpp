// fogdrift.simulate, fogdrift.train, fogdrift.evaluate, fogdrift.denoise and fogdrift.options:
// the drift workflow with the command line's options, named as Python names them
// (docs/matlab.md, docs/options.md).
#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <optional>

#include "commands.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/base/text_file.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/eval/eval_option_table.hpp"
#include "fogdrift/eval/evaluation.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/io/target.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/opt/summary.hpp"
#include "fogdrift/report/option_descriptions.hpp"
#include "fogdrift/signal/denoise.hpp"
#include "fogdrift/signal/denoise_option_table.hpp"
#include "fogdrift/sim/instrument.hpp"
#include "fogdrift/sim/scenario_option_table.hpp"
#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/svr_trainer.hpp"
#include "fogdrift/train/train_campaign.hpp"
#include "fogdrift/train/train_option_table.hpp"
#include "fogdrift/train/train_summary.hpp"

namespace fogdrift::matlab {
namespace {

using Pairs = std::vector<std::pair<std::string, const mxArray*>>;

/// The pair named `name` among `rest`, or nullptr.
const mxArray* take(const Pairs& rest, const std::string& name) {
  for (const auto& p : rest)
    if (p.first == name) return p.second;
  return nullptr;
}

/// OptionError for any of `rest` not among `own`.
void only(const Args& args, const Pairs& rest, const std::vector<std::string>& own,
          const std::vector<OptionSpec>& specs) {
  for (const auto& p : rest)
    if (std::find(own.begin(), own.end(), p.first) == own.end())
      unknown_option(args.function, p.first, own, specs);
}

bool on_off(const mxArray* v, const std::string& name) {
  OptionSpec spec;
  spec.keyword = name;
  spec.type = OptionType::on_off;
  return option_text(spec, v) == "true";
}

template <class O, class Simulate>
sim::SimulatedCampaign run_scenario(const Args& args, const Pairs& pairs,
                                    const OptionTable<O>& table, O o, Simulate simulate,
                                    const sim::Instrument& unit, std::uint64_t seed) {
  const std::vector<OptionSpec> specs = specs_of(table);
  only(args, in_keywords_of(specs, [&] { return apply_options(table, o, pairs); }),
       {"out", "seed", "instrument", "replace"}, specs);
  o.seed = seed;
  return in_keywords_of(specs, [&] { return simulate(unit, o); });
}

}  // namespace

void simulate(const Args& args, Results& out) {
  const std::string scenario = text_of(args.at(0, "scenario"), "scenario");
  const Pairs pairs = name_values(args, 1);
  std::uint64_t seed = 1;
  std::optional<std::filesystem::path> folder;
  bool replace = false;
  sim::Instrument unit;
  std::vector<std::filesystem::path> read;  // the instrument file, which out must not replace
  for (const auto& [name, value] : pairs) {
    if (name == "seed") {
      OptionSpec spec;
      spec.keyword = "seed";
      spec.type = OptionType::whole;
      seed = parse_whole_option(spec, option_text(spec, value));
    } else if (name == "out") {
      folder = text_of(value, "out");
    } else if (name == "replace") {
      replace = on_off(value, "replace");
    } else if (name == "instrument") {
      const std::string file = text_of(value, "instrument");
      unit = sim::instrument_from_json(read_text_file(file), file);
      read.push_back(file);
    }
  }
  sim::SimulatedCampaign c;
  if (scenario == "calibration")
    c = run_scenario(args, pairs, sim::calibration_option_table(), sim::CalibrationOptions{},
                     sim::simulate_calibration, unit, seed);
  else if (scenario == "northfind")
    c = run_scenario(args, pairs, sim::northfind_option_table(), sim::NorthfindOptions{},
                     sim::simulate_northfind, unit, seed);
  else if (scenario == "stable")
    c = run_scenario(args, pairs, sim::northfind_option_table(), sim::stable_defaults(),
                     sim::simulate_stable, unit, seed);
  else
    throw OptionError("scenario", fmt::format("must be 'calibration', 'northfind' or 'stable' "
                                              "(got '{}')",
                                              scenario));
  if (folder) {
    check_output_not_among(*folder, read, "out");
    sim::write_campaign(*folder, c, replace);
  }
  out.values.push_back(to_mx(nlohmann::ordered_json::parse(manifest_json(c.campaign))));
}

void train(const Args& args, Results& out) {
  const std::string campaign = text_of(args.at(0, "campaign"), "campaign");
  const OptionTable<CampaignTrainOptions>& table = train_option_table();
  const std::vector<OptionSpec> specs = specs_of(table);
  CampaignTrainOptions o;
  const Pairs rest =
      in_keywords_of(specs, [&] { return apply_options(table, o, name_values(args, 1)); });
  only(args, rest, {"threads", "target", "out", "progress"}, specs);
  std::uint64_t threads = 0;
  if (const mxArray* v = take(rest, "threads")) {
    OptionSpec spec;
    spec.keyword = "threads";
    spec.type = OptionType::whole;
    threads = parse_whole_option(spec, option_text(spec, v));
  }
  if (const mxArray* v = take(rest, "target")) o.dataset.target_column = text_of(v, "target");
  target_of(o.dataset.target_column, "target");
  std::optional<std::filesystem::path> path;
  if (const mxArray* v = take(rest, "out")) path = text_of(v, "out");
  in_keywords_of(specs, [&] { validate(o.train); });
  const Campaign c = read_campaign(campaign);
  if (path) {
    std::vector<std::filesystem::path> inputs = {c.dir / "campaign.json"};
    for (const CampaignEntry& e : c.recordings) inputs.push_back(c.path_of(e));
    check_output_not_among(*path, inputs, "out");
  }
  ThreadPool pool(static_cast<unsigned>(threads));
  o.train.tune.pool = &pool;
  // A line every 5 s of a search, unless 'progress' is false (the host shows what it prints
  // when the call returns or, in Octave's command window, as it goes).
  const bool progress = !take(rest, "progress") || on_off(take(rest, "progress"), "progress");
  const auto start = std::chrono::steady_clock::now();
  double last_s = 0;
  const std::size_t iterations = o.train.tune.optimizer.run.iterations;
  if (progress)
    o.train.tune.optimizer.run.progress = [&](const opt::IterationRecord& it) {
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (s - last_s >= 5 || it.iteration == iterations) {
        last_s = s;
        mexPrintf("%s: iteration %zu/%zu, best RMSE %.5f, %zu evaluations, %.0f s\n",
                  args.function.c_str(), static_cast<std::size_t>(it.iteration), iterations,
                  it.best_fitness, static_cast<std::size_t>(it.evaluations), s);
        mexEvalString("drawnow;");
      }
      return true;
    };
  const CampaignTrainResult r = in_keywords_of(specs, [&] { return train_campaign(c, o); });
  if (path) save(r.trained.model, *path);
  const OptionWords keywords{
      [&](const std::string& field) { return option_word(specs, field, false); },
      [&](const std::string& text) { return in_option_words(text, specs, false); }};
  const nlohmann::ordered_json summary = summary_json(r, keywords);
  if (summary["held_out"].contains("warnings"))
    for (const auto& w : summary["held_out"]["warnings"]) out.warnings.push_back(w);
  // A best value on its box's edge, the advice in name-value pairs, as Python and the CLI say it.
  for (const std::string& w : box_edge_warnings(
           r.trained.summary, o.train.auto_box_rounds > 0, [&](const std::string& field) {
             return field == "auto_box"         ? std::string("'auto_box', true")
                    : field == "search_epsilon" ? std::string("'search_epsilon', true")
                                                : "'" + option_word(specs, field, false) + "'";
           }))
    out.warnings.push_back(w);
  out.values.push_back(text(to_json(r.trained.model)));
  out.values.push_back(to_mx(summary));
}

void evaluate(const Args& args, Results& out) {
  const std::string model_text = text_of(args.at(0, "model"), "model");
  const std::string campaign = text_of(args.at(1, "campaign"), "campaign");
  const auto& table = eval::evaluation_option_table();
  const std::vector<OptionSpec> specs = specs_of(table);
  eval::EvaluationOptions o;
  only(args, in_keywords_of(specs, [&] { return apply_options(table, o, name_values(args, 2)); }),
       {}, specs);
  const CompensationModel m = compensation_model_from_json(model_text, "model", {});
  const eval::Evaluation e =
      in_keywords_of(specs, [&] { return eval::evaluate(m, read_campaign(campaign), o); });
  const std::string verdict = eval::verdict(e);
  if (verdict != "beats its baselines")
    out.warnings.push_back(
        fmt::format("the model {} on {} (see the baselines field)", verdict, campaign));
  out.values.push_back(to_mx(nlohmann::ordered_json::parse(eval::to_json(e, "model", campaign))));
}

void denoise(const Args& args, Results& out) {
  const std::vector<double> x = vector_of(args.at(0, "signal"), "signal");
  const auto& table = signal::denoise_option_table();
  const std::vector<OptionSpec> specs = specs_of(table);
  signal::DenoiseOptions o;
  only(args, in_keywords_of(specs, [&] { return apply_options(table, o, name_values(args, 1)); }),
       {}, specs);
  const signal::DenoiseResult r = in_keywords_of(specs, [&] { return signal::denoise(x, o); });
  nlohmann::ordered_json s;
  s["level"] = r.summary.level;
  s["noise_sigma"] = r.summary.noise_sigma;
  s["bands"] = nlohmann::ordered_json::array();
  for (const auto& b : r.summary.bands)
    s["bands"].push_back(
        {{"level", b.level}, {"size", b.size}, {"threshold", b.threshold}, {"kept", b.kept}});
  MxPtr y = column(r.signal);
  if (mxGetM(args.values[0]) == 1) mxSetN(y.get(), r.signal.size()), mxSetM(y.get(), 1);
  out.values.push_back(std::move(y));
  out.values.push_back(to_mx(s));
}

void options(const Args& args, Results& out) {
  const std::string which = text_of(args.at(0, "function"), "function");
  out.values.push_back(to_mx(report::options_json(report::option_descriptions(which, "function"))));
}

}  // namespace fogdrift::matlab
