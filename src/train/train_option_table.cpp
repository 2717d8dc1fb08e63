// `fogdrift train`'s options, described once (train_option_table.hpp). Defaults are read from a
// default CampaignTrainOptions, never written here; ranges are checked where the library
// validates the options (validate(TrainOptions), the dataset's and the differentiator's checks).
#include "fogdrift/train/train_option_table.hpp"

#include <fmt/format.h>

#include "fogdrift/features/features.hpp"
#include "fogdrift/signal/differentiate.hpp"
#include "fogdrift/train/trainers.hpp"

namespace fogdrift {
namespace {

using O = CampaignTrainOptions;

OptionTable<O> make_train_table() {
  OptionTable<O> t;
  t.push_back(
      {{"method",
        "--method",
        OptionType::choice,
        "",
        method_names(),
        "The regressor and how it is trained: " + method_docs(),
        {}},
       [](const O& o) { return to_string(o.train.method); },
       [](O& o, const std::string& text) { o.train.method = parse_method(text, "method"); }});
  t.push_back(
      {{"search",
        "--search",
        OptionType::choice,
        "",
        search_names(),
        "How the regressor's hyperparameters are searched, over the folds of {cv} with "
        "{population} and {iterations}: ssa (sparrow search), pso (particle swarm), gwo "
        "(grey wolf); none; auto, the method's own (ssa for ssa-svr, none for svr; {method} "
        "says each one's). {method} svr with {search} ssa is ssa-svr",
        {}},
       [](const O& o) { return std::string(to_string(o.train.search)); },
       [](O& o, const std::string& text) { o.train.search = parse_search(text, "search"); }});
  t.push_back({{"fitness",
                "--fitness",
                OptionType::choice,
                "",
                tune::fitness_names(),
                "What a tuned SVR's candidate (C, σ) is scored by: cv, the RMSE over grouped "
                "folds that never split a recording; train, the paper's training RMSE, which "
                "favours over-fitting",
                {}},
               [](const O& o) { return tune::to_string(o.train.tune.fitness); },
               [](O& o, const std::string& text) {
                 o.train.tune.fitness = tune::parse_fitness(text, "fitness");
               }});
  t.push_back({{"cv",
                "--cv",
                OptionType::choice,
                "",
                tune::cv_scheme_names(),
                "Folds: auto (temperature with at least three temperatures, else repetition), "
                "repetition (leave one out), recording (k folds of whole recordings) or "
                "temperature (k folds of whole initial temperatures: the fitness of a model at "
                "temperatures it never saw). bp, which is not refitted after early stopping, "
                "stops on a third of the recordings unless repetition or recording is asked",
                {}},
               [](const O& o) { return tune::to_string(o.train.tune.cv.scheme); },
               [](O& o, const std::string& text) {
                 o.train.tune.cv.scheme = tune::parse_cv_scheme(text, "cv");
               }});
  t.push_back(whole_option<O>(
      {"folds", "--folds", {}, "", at_least(2), "k of {cv} recording or temperature", {}},
      [](auto& o) -> auto& { return o.train.tune.cv.folds; }));
  t.push_back({{"thermometers",
                "--thermometers",
                OptionType::names,
                "",
                "fog, acc1, acc2, NAME",
                "The thermometers the features read, e.g. fog,acc1,acc2,case: the auto features "
                "over them, or what a term of {features} without its own list reads. NAME is a "
                "further column temp_NAME_degc; the model then needs its reading wherever it runs "
                "(stream, export-c). auto: those of fog, acc1, acc2 every training recording has",
                {}},
               [](const O& o) {
                 return o.thermometers.empty() ? std::string("auto")
                                               : fmt::format("{}", fmt::join(o.thermometers, ","));
               },
               [](O& o, const std::string& text) {
                 o.thermometers =
                     text == "auto" ? std::vector<std::string>{} : parse_thermometers(text);
               }});
  t.push_back({{"features",
                "--features",
                OptionType::text,
                "",
                "",
                "Feature spec: terms T, dT, grad, dgrad, t, TdT, dT@SECONDS (the rate through a "
                "lag of that time constant), each optionally with its thermometers, e.g. "
                "'T,dT(fog),grad'; auto: the paper's T,dT,grad and the rates through a 300 s lag, "
                "T,dT,grad,dT@300, over the thermometers every training recording has "
                "(T(fog),dT(fog),dT@300(fog) with one; docs/field.md)",
                {}},
               [](const O& o) {
                 return o.auto_features ? std::string("auto") : o.dataset.features.to_string();
               },
               [](O& o, const std::string& text) {
                 o.auto_features = text == "auto";
                 if (!o.auto_features)
                   o.dataset.features = FeatureSpec::parse(text, o.thermometers);
               }});
  t.push_back({{"differentiator",
                "--differentiator",
                OptionType::choice,
                "",
                signal::causality_names(),
                "Temperature rates: centred (offline, no delay) or causal (what the instrument can "
                "run sample by sample; train with it for a streaming compensator)",
                {"causality"}},
               [](const O& o) {
                 return std::string(signal::to_string(o.dataset.preprocessing.rates.causality));
               },
               [](O& o, const std::string& text) {
                 o.dataset.preprocessing.rates.causality =
                     signal::parse_causality(text, "differentiator");
               }});
  t.push_back(seconds_or_auto_option<O>(
      {"block_s",
       "--block-s",
       {},
       "",
       above(0).with("a whole number of samples"),
       "Averaging block of the modelling rows; auto: 10 s, or the nearest whole number of samples "
       "for a log that 10 s does not divide (one sample for logs slower than 0.1 Hz)",
       {}},
      [](auto& o) -> auto& { return o.block_s; }));
  t.push_back(seconds_or_auto_option<O>(
      {"rate_window_s",
       "--rate-window-s",
       {},
       "",
       above(0).with("at least 5 samples"),
       "Window of the temperature-rate differentiator; auto: 121 s centred, 61 s causal, at least "
       "5 samples, and (centred) no longer than the shortest recording",
       {"window_s"}},
      [](auto& o) -> auto& { return o.rate_window_s; }));
  t.push_back({{"rate_degree",
                "--rate-degree",
                OptionType::whole_or_auto,
                "",
                between(1, 4),
                "Degree of the polynomial the differentiator fits; auto: 2 centred, 1 causal. For "
                "causal rates 1 is the least noisy and lags by half the window, 2 does not lag a "
                "steady curvature and is about four times noisier (docs/signal.md)",
                {"poly_order"}},
               [](const O& o) {
                 return o.rate_degree ? std::to_string(*o.rate_degree) : std::string("auto");
               },
               [](O& o, const std::string& text) {
                 const OptionSpec spec{
                     "rate_degree", "", OptionType::whole_or_auto, "", "", "", {}};
                 const auto v = parse_whole_or_auto_option(spec, text);
                 if (v && (*v < 1 || *v > 4))
                   throw OptionError("rate_degree", fmt::format("{} is outside 1 … 4", *v));
                 o.rate_degree = v ? std::optional<int>(static_cast<int>(*v)) : std::nullopt;
               }});
  t.push_back(on_off_option<O>(
      {"denoise",
       "--denoise",
       {},
       "",
       "",
       "Train on the wavelet-denoised gyro (the paper's target) instead of its block means: "
       "the denoiser smooths the first minutes of a start-up, which a north-finding needs "
       "(docs/field.md)",
       {}},
      [](auto& o) -> auto& { return o.dataset.denoise_target; }));
  t.push_back(whole_option<O>(
      {"population",
       "--population",
       {},
       "",
       at_least(2).with("ssa-svr ≥ 5"),
       "Individuals of the search's optimizer",
       {}},
      [](auto& o) -> auto& { return o.train.tune.optimizer.run.population; }));
  t.push_back(whole_option<O>(
      {"iterations",
       "--iterations",
       {},
       "",
       at_least(1),
       "Iterations of the search after its initial population",
       {}},
      [](auto& o) -> auto& { return o.train.tune.optimizer.run.iterations; }));
  t.push_back(whole_option<O>(
      {"stall_iterations",
       "--stall-iterations",
       {},
       "",
       at_least(0).with("0 runs every iteration"),
       "Stop the search early once its best fitness has improved by less than "
       "{stall_tolerance} over this many iterations: the search ends when it stops learning, "
       "and what it returns is what the full run had found by then (docs/tuning.md)",
       {}},
      [](auto& o) -> auto& { return o.train.tune.optimizer.run.stall_iterations; }));
  t.push_back(number_option<O>(
      {"stall_tolerance",
       "--stall-tolerance",
       {},
       "",
       at_least(0).below(1),
       "The relative improvement of the best fitness that counts as learning for "
       "{stall_iterations} (0.001: a tenth of a percent)",
       {}},
      [](auto& o) -> auto& { return o.train.tune.optimizer.run.stall_tolerance; }));
  t.push_back(whole_option<O>(
      {"search_rows",
       "--search-rows",
       {},
       "",
       at_least(0).with("0 fits every row"),
       "The fewest training rows of a fold the search may thin: a fold with k times as many "
       "is searched on every k-th row (C × k, every held-out row scored), and the best 3 "
       "candidates are scored again on all rows. A fit costs the square of its rows "
       "(docs/tuning.md)",
       {}},
      [](auto& o) -> auto& { return o.train.tune.search_rows; }));
  t.push_back(whole_option<O>(
      {"thin_from_rows",
       "--thin-from-rows",
       {},
       "",
       at_least(0).with("0 lets {search_rows} alone decide"),
       "The fewest training rows a fold must hold for the search to thin it ({search_rows}): "
       "a smaller campaign is searched on every row, where thinning saves little and costs "
       "the search the most (docs/tuning.md)",
       {}},
      [](auto& o) -> auto& { return o.train.tune.thin_from_rows; }));
  t.push_back(whole_option<O>(
      {"smo_iterations_per_row",
       "--smo-iterations-per-row",
       {},
       "",
       between(0, static_cast<double>(tune::kMaxSmoIterationsPerRow)).with("0 sets no cap"),
       "The SMO iterations each of the search's fits may take, per training row of the largest "
       "fold: a fit stopped there is unfinished, its loss steers the search but never bounds "
       "racing, and a candidate that would be the answer is fitted to the end first "
       "(docs/tuning.md). Spares the slow fits of the over-fitting corner",
       {}},
      [](auto& o) -> auto& { return o.train.tune.smo_iterations_per_row; }));
  t.push_back(number_option<O>(
      {"candidate_resolution",
       "--candidate-resolution",
       {},
       "",
       between(0, tune::kMaxCandidateResolution).with("0 fits every distinct candidate"),
       "Decades of C and σ (and ε) within which two of the search's candidates are one: the "
       "later takes the loss of the one fitted, and the answer is always a fitted candidate. A "
       "candidate's loss is known only to its fits' tolerance, which moves it by about as much as "
       "such a step does; the default halves some searches and moved no population study's "
       "shares one way (docs/tuning.md)",
       {}},
      [](auto& o) -> auto& { return o.train.tune.candidate_resolution; }));
  t.push_back(whole_option<O>(
      {"seed", "--seed", {}, "", "", "Seed of the search (and of bp's weights)", {}},
      [](auto& o) -> auto& { return o.train.tune.optimizer.run.seed; }));
  t.push_back(number_option<O>(
      {"c_min", "--c-min", {}, "", above(0), "Smallest C searched", {}},
      [](auto& o) -> auto& { return o.train.tune.space.c_min; }));
  t.push_back(number_option<O>(
      {"c_max", "--c-max", {}, "", "> {c_min}", "Largest C searched", {}},
      [](auto& o) -> auto& { return o.train.tune.space.c_max; }));
  t.push_back(number_option<O>(
      {"sigma_min",
       "--sigma-min",
       {},
       "",
       above(0),
       "Smallest σ searched, in standardised feature units",
       {}},
      [](auto& o) -> auto& { return o.train.tune.space.sigma_min; }));
  t.push_back(number_option<O>(
      {"sigma_max", "--sigma-max", {}, "", "> {sigma_min}", "Largest σ searched", {}},
      [](auto& o) -> auto& { return o.train.tune.space.sigma_max; }));
  t.push_back(number_option<O>(
      tune::epsilon_option_spec(), [](auto& o) -> auto& { return o.train.tune.space.epsilon; }));
  t.push_back(on_off_option<O>(
      {"search_epsilon",
       "--search-epsilon",
       {},
       "",
       "",
       "Also search ε, in [{epsilon_min}, {epsilon_max}]",
       {}},
      [](auto& o) -> auto& { return o.train.tune.space.search_epsilon; }));
  t.push_back(number_option<O>(
      {"epsilon_min",
       "--epsilon-min",
       {},
       "",
       above(0),
       "Smallest ε searched with {search_epsilon}",
       {}},
      [](auto& o) -> auto& { return o.train.tune.space.epsilon_min; }));
  t.push_back(number_option<O>(
      {"epsilon_max",
       "--epsilon-max",
       {},
       "",
       "> {epsilon_min}",
       "Largest ε searched with {search_epsilon}",
       {}},
      [](auto& o) -> auto& { return o.train.tune.space.epsilon_max; }));
  t.push_back(
      {{"auto_box",
        "--auto-box",
        OptionType::on_off,
        "",
        "",
        fmt::format("When the best C, σ or ε lies on an edge of its box, widen the box a "
                    "decade there and search again (at most {} times); train warns of "
                    "such edges either way",
                    TrainOptions::kAutoBoxRounds),
        {}},
       [](const O& o) { return std::string(o.train.auto_box_rounds > 0 ? "true" : "false"); },
       [](O& o, const std::string& text) {
         const OptionSpec spec{"auto_box", "", OptionType::on_off, "", "", "", {}};
         o.train.auto_box_rounds =
             parse_on_off_option(spec, text) ? TrainOptions::kAutoBoxRounds : 0;
       }});
  t.push_back(on_off_option<O>(
      {"racing",
       "--no-racing",
       {},
       "",
       "",
       "Stop a search's candidate once its held-out errors on the folds fitted so "
       "far exceed the best candidate's: the same best among the candidates "
       "visited in about half the fits; turned off, every fold of every candidate "
       "is fitted (docs/tuning.md)",
       {}},
      [](auto& o) -> auto& { return o.train.tune.racing; }));
  t.push_back(number_option<O>(
      {"cache_mb",
       "--cache-mb",
       {},
       "MB",
       at_least(0),
       "Kernel-row cache of each SVR fit (one fit per thread): less memory, slower "
       "fits",
       {}},
      [](auto& o) -> auto& { return o.train.tune.cache_mb; }));
  // Each trainer's own options, in the registry's order (trainers.hpp).
  for (const TrainerEntry& trainer : trainer_entries())
    for (Option<O>& o : lifted<O>(
             trainer.options(), [](auto& c) -> auto& { return c.train; }))
      t.push_back(std::move(o));
  return t;
}

}  // namespace

const OptionTable<CampaignTrainOptions>& train_option_table() {
  static const OptionTable<CampaignTrainOptions> table = make_train_table();
  return table;
}

}  // namespace fogdrift
