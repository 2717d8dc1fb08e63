// fogdrift train: fit a compensation model on a campaign's training recordings (docs/method.md §2).
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_util.hpp"
#include "commands.hpp"
#include "fogdrift/base/csv.hpp"
#include "fogdrift/base/error.hpp"
#include "fogdrift/base/run_files.hpp"
#include "fogdrift/base/thread_pool.hpp"
#include "fogdrift/io/campaign.hpp"
#include "fogdrift/model/model_set.hpp"
#include "fogdrift/train/svr_trainer.hpp"
#include "fogdrift/train/train_campaign.hpp"
#include "fogdrift/train/train_option_table.hpp"
#include "fogdrift/train/train_summary.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {
namespace {

struct TrainArgs {
  std::string campaign;
  std::string output;
  unsigned threads = 0;
  std::string targets = "gyro_dph";
  bool json = false;
  bool quiet = false;
  /// The options that decide the model (train_option_table.hpp), and what they were set to.
  std::shared_ptr<OptionFlags> flags;
  CampaignTrainOptions options;
};

// "C = 8.62, sigma = 6.03: 0.18098; …": candidates of a search and their losses.
std::string candidate_list(const std::vector<tune::Candidate>& candidates) {
  std::string out;
  for (const tune::Candidate& c : candidates)
    out += fmt::format("{}C = {:.4g}, sigma = {:.3g}: {:.5f}", out.empty() ? "" : "; ", c.params.c,
                       c.params.kernel.sigma(), c.loss);
  return out;
}

/// How sure train is, its advice in flags.
std::vector<std::string> held_out_warnings(const TrainArgs& a, const HeldOutReport& h) {
  std::vector<std::string> out;
  for (const auto& w : h.warnings) out.push_back(a.flags->words(w));
  return out;
}

/// The choices made for the user, each with the flag that would change it.
std::vector<std::string> notes_of(const TrainArgs& a, const CampaignTrainResult& trained) {
  std::vector<std::string> notes;
  for (const CampaignNote& n : trained.notes)
    notes.push_back(fmt::format("{} ({})", n.text, flag_for(n.field, a.flags->flag_table())));
  return notes;
}

/// A best value on the edge of its box: the box, not the data, may have stopped the search.
std::vector<std::string> edge_notes_of(const TrainArgs& a, const TrainSummary& s) {
  return box_edge_warnings(s, a.options.train.auto_box_rounds > 0, [&](const std::string& field) {
    return flag_for(field, a.flags->flag_table());
  });
}

/// `fogdrift train --json`'s summary of one model: the library's, its options named by flag.
nlohmann::ordered_json summary_json(const TrainArgs& a, const CampaignTrainResult& trained) {
  nlohmann::ordered_json j;
  j["model"] = a.output;
  const OptionWords flags{
      [&](const std::string& field) { return flag_for(field, a.flags->flag_table()); },
      [&](const std::string& text) { return a.flags->words(text); }};
  j.update(fogdrift::summary_json(trained, flags));
  return j;
}

/// The text summary of one model; `heading` prefixes its first line (the axis of a model set).
void print_summary(const TrainArgs& a, const CampaignTrainResult& trained,
                   const std::string& heading) {
  const TrainSummary& s = trained.trained.summary;
  const Dataset& data = trained.data;
  const Provenance& p = trained.trained.model.provenance;
  const std::vector<std::string> notes = notes_of(a, trained);
  const std::vector<std::string> edge_notes = edge_notes_of(a, s);
  {
    std::string hyper;
    for (const auto& [k, v] : s.hyperparameters)
      hyper += fmt::format("{}{} = {:.6g}", hyper.empty() ? "" : ", ", k, v);
    std::cout << fmt::format("{}{}: {} on {} rows of {} training recordings ({} features)\n",
                             heading, a.campaign, to_string(s.method), s.rows, data.groups.size(),
                             data.cols());
    std::cout << fmt::format("  {}\n", hyper);
    std::cout << fmt::format("  {} RMSE {:.5f} (standardised drift){}\n", s.fitness,
                             s.fitness_value, p.cv.empty() ? "" : ", " + p.cv);
    // A searched SVR's record (svr_trainer.hpp): its search, rows and boxes.
    const SvrTrainer::Record* svr = s.record.get<SvrTrainer::Record>();
    if (svr && !svr->tuning.optimizer.log.empty())
      std::cout << fmt::format(
          "  search: {}; {} distinct candidates ({} stopped early by "
          "racing), {} SVR fits\n",
          svr->tuning.optimizer.brief_report(), svr->tuning.candidates, svr->tuning.raced,
          svr->tuning.fits);
    if (svr && svr->tuning.near_repeats > 0)
      std::cout << fmt::format(
          "  {} candidates within {:g} decade of one fitted took its loss "
          "(--candidate-resolution)\n",
          svr->tuning.near_repeats, a.options.train.tune.candidate_resolution);
    if (svr && svr->tuning.capped_fits > 0)
      std::cout << fmt::format(
          "  {} fits stopped unfinished at {} SMO iterations a row (--smo-iterations-per-row); "
          "{}\n",
          svr->tuning.capped_fits, a.options.train.tune.smo_iterations_per_row,
          svr->tuning.stride > 1 ? std::string("the rescored candidates are fitted to the end")
          : svr->tuning.finished.empty()
              ? std::string("none would have been the answer")
              : "fitted to the end as they would have been the answer: " +
                    candidate_list(svr->tuning.finished));
    if (svr && svr->tuning.optimizer.status == opt::Status::converged)
      std::cout << fmt::format(
          "  stopped learning: less than {:g} % better over its last {} iterations "
          "(--stall-iterations, --stall-tolerance)\n",
          100 * a.options.train.tune.optimizer.run.stall_tolerance,
          a.options.train.tune.optimizer.run.stall_iterations);
    if (svr && svr->tuning.stride > 1)
      std::cout << fmt::format(
          "  searched on one training row in {} (C x {}), the best {} rescored on all rows: {} "
          "(--search-rows)\n",
          svr->tuning.stride, svr->tuning.stride, svr->tuning.rescored.size(),
          candidate_list(svr->tuning.rescored));
    const tune::TuneOptions& tuned = a.options.train.tune;
    if (svr && svr->tuning.stride == 1 && tuned.search_rows > 0 &&
        svr->tuning.largest_fold_rows > 0 && svr->tuning.largest_fold_rows < tuned.thin_from_rows)
      // A --search-rows the user set must not look applied when the folds are too small for it.
      std::cout << fmt::format(
          "  searched on every training row: the largest fold holds {} rows, fewer than "
          "--thin-from-rows {} (from there folds are thinned to about --search-rows {})\n",
          svr->tuning.largest_fold_rows, tuned.thin_from_rows, tuned.search_rows);
    if (svr && svr->boxes.size() > 1) {
      const auto& b = svr->boxes.back();
      std::cout << fmt::format(
          "  auto-box: {} searches, last box C [{:.6g}, {:.6g}], sigma "
          "[{:.6g}, {:.6g}]\n",
          svr->boxes.size(), b.c_min, b.c_max, b.sigma_min, b.sigma_max);
    }
    if (s.held_out) {
      const HeldOutReport& h = *s.held_out;
      std::cout << fmt::format(
          "  expected to remove {:.0f} % of the drift on held-out rows, {:.0f} % of its variation "
          "within a start-up: {}\n",
          100.0 * h.expected_share, 100.0 * h.expected_startup_share, h.folds);
      std::string base;
      for (const Baseline& b : h.baselines) base += fmt::format(", {} {:.4f}", b.name, b.rmse);
      std::cout << fmt::format("  held-out RMSE (standardised): model {:.4f}{}\n", h.model_rmse,
                               base);
    } else if (!s.held_out_missing.empty()) {
      std::cout << fmt::format("  expected share: n/a ({})\n", s.held_out_missing);
    }
    for (const auto& n : notes) std::cout << "  note: " << n << "\n";
    if (s.held_out)
      for (const auto& w : held_out_warnings(a, *s.held_out))
        std::cout << "  warning: " << w << "\n";
    for (const auto& n : edge_notes) std::cout << "  warning: " << n << "\n";
    for (const auto& w : data.warnings) std::cout << "  warning: " << w << "\n";
  }
}

void run(TrainArgs& a) {
  CampaignTrainOptions& campaign_options = a.options;
  a.flags->apply(train_option_table(), campaign_options);
  TrainOptions& options = campaign_options.train;
  ThreadPool pool(a.threads);
  options.tune.pool = &pool;

  const bool show_progress = !a.quiet && !a.json && stderr_is_terminal();
  // The method as trained (svr with --search ssa is ssa-svr); a method and a search that
  // contradict, and any other impossible option, are refused here, before the campaign is read.
  std::string label;
  try {
    validate(options);
    label = to_string(resolved(options).method);
  } catch (const OptionError& e) {
    throw a.flags->named(e);
  }
  const auto start = std::chrono::steady_clock::now();
  if (show_progress) {
    options.tune.optimizer.run.progress = [&](const opt::IterationRecord& r) {
      const double s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::cerr << fmt::format(
                       "\r{}: iteration {}/{}, best {} RMSE {:.5f}, {} evaluations, {:.0f} s ",
                       label, r.iteration, options.tune.optimizer.run.iterations,
                       tune::to_string(options.tune.fitness), r.best_fitness, r.evaluations, s)
                << std::flush;
      return true;
    };
  }

  const Campaign campaign = read_campaign(a.campaign);
  check_output_not_input(a.output, "--output");
  // One model per target column, each with its own search and guard (docs/logs.md, "Every
  // axis"), written as one file.
  const std::vector<std::string> targets = split_list(a.targets);
  check_targets(targets, "--targets");
  std::vector<CampaignTrainResult> results;
  for (const std::string& target : targets) {
    campaign_options.dataset.target_column = target;
    if (show_progress && targets.size() > 1) std::cerr << target << ": ";
    try {
      results.push_back(train_campaign(campaign, campaign_options));
    } catch (const OptionError& e) {
      if (show_progress) std::cerr << "\n";
      throw a.flags->named(e);
    }
    if (show_progress) std::cerr << "\n";
  }
  if (results.size() == 1) {
    save(results.front().trained.model, a.output);
  } else {
    ModelSet set;
    for (const auto& r : results) set.models.push_back(r.trained.model);
    save(set, a.output);
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (a.json && results.size() == 1) {
    std::cout << summary_json(a, results.front()).dump(2) << "\n";
  } else if (a.json) {
    nlohmann::ordered_json j;
    j["model"] = a.output;
    j["targets"] = targets;
    j["axes"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < results.size(); ++i) {
      nlohmann::ordered_json one;
      one["target"] = targets[i];
      const nlohmann::ordered_json summary = summary_json(a, results[i]);
      for (const auto& [k, v] : summary.items())
        if (k != "model") one[k] = v;
      j["axes"].push_back(one);
    }
    j["seconds"] = seconds;
    std::cout << j.dump(2) << "\n";
  } else if (!a.quiet) {
    for (std::size_t i = 0; i < results.size(); ++i)
      print_summary(a, results[i], results.size() > 1 ? targets[i] + ": " : "");
    std::cout << fmt::format("  wrote {}{} in {:.1f} s\n", a.output,
                             results.size() > 1 ? fmt::format(" ({} axes)", results.size()) : "",
                             seconds);
  }
}

}  // namespace

void add_train(CLI::App& app) {
  auto args = std::make_shared<TrainArgs>();
  auto* cmd = app.add_subcommand(
      "train",
      "Train a compensation model on the calibration recordings whose role is \"train\" and write\n"
      "it as JSON (features, scalers, regressor, provenance with SHA-256 of every data file).\n\n"
      "Methods: " +
          method_names() +
          " (--method below says what each is).\n"
          "A method is a regressor and a search: --method svr --search pso is pso-svr.\n"
          "Fitness of a candidate (C, σ): 'cv' (default) is the RMSE over grouped folds that "
          "never\n"
          "split a recording: with --cv auto, three folds of whole calibration temperatures (a "
          "model\n"
          "scored where it was not trained, as a start-up at a new temperature asks), or with "
          "fewer\n"
          "than three temperatures, leave one repetition out; 'train' is the paper's training "
          "RMSE,\n"
          "which favours over-fitting. C and σ are searched in log10 space, ε is 0.05 "
          "(docs/tuning.md).\n"
          "The model records the region of feature space it was trained on; compensate, stream,\n"
          "evaluate, northfind and export-c reduce its correction outside it (docs/field.md).\n"
          "Calibrate under the start-up conditions the instrument will meet: docs/field.md gives "
          "the\n"
          "protocol (fogdrift simulate calibration --repetitions 7 --approach\n"
          "calibration,soaked,warm,ramping,warm,warm,calibration).\n"
          "Examples:\n"
          "  fogdrift simulate calibration --out cal && fogdrift train cal -o model.json\n"
          "  fogdrift train cal --method pso-svr --population 30 --iterations 40 --seed 2 -o "
          "pso.json\n"
          "  fogdrift train cal --method bp --hidden 12 -o bp.json --json");
  cmd->add_option("campaign", args->campaign, "Campaign folder (or its campaign.json)")->required();
  cmd->add_option("-o,--output", args->output, "Model file to write (JSON, atomically)")
      ->required();
  args->flags = std::make_shared<OptionFlags>(cmd, specs_of(train_option_table()),
                                              defaults_of(train_option_table()));
  cmd->add_option("--threads", args->threads,
                  "Threads (0: one per core); results do not depend on it")
      ->capture_default_str();
  cmd->add_option("--targets", args->targets,
                  "The columns to compensate, comma-separated: gyro_dph and further gyro axes the "
                  "recordings carry (gyro_y_dph, ... from fogdrift import), accelerometers "
                  "(accel_x_g, accel_NAME_g: their bias), scale-factor channels (sf_NAME_ppm); "
                  "several give one model file with a model per axis, each with its own search "
                  "and guard (docs/logs.md, \"Other targets\")")
      ->capture_default_str();
  cmd->add_flag("--json", args->json, "Print the training summary as JSON");
  cmd->add_flag("-q,--quiet", args->quiet, "Print nothing on success");
  cmd->callback([args] { run(*args); });
}

}  // namespace fogdrift::app
