// The paper experiment's options (paper_option_table.hpp). Defaults are PaperOptions'; validate()
// (paper.hpp) checks the ranges and names the field, "cv.folds" or "calibration.temps_degc", which
// each option lists so that a front end names the error by its own word for the option.
#include "fogdrift/report/paper_option_table.hpp"

#include <string>
#include <vector>

#include "fogdrift/sim/scenarios.hpp"
#include "fogdrift/train/folds.hpp"
#include "fogdrift/train/tune.hpp"

namespace fogdrift::report {
namespace {

OptionTable<PaperOptions> make_paper_table() {
  using O = PaperOptions;
  OptionTable<O> t;
  t.push_back(whole_option<O>(
      {"seeds",
       "--seeds",
       {},
       "",
       between(1, 1000),
       "Independent repetitions of the whole experiment",
       {}},
      [](auto& o) -> auto& { return o.seeds; }));
  t.push_back({{"methods",
                "--methods",
                OptionType::names,
                "",
                method_names(),
                "Methods of Tables 2-3 and the start-up conditions table, in order (train --help "
                "says what each is): the paper's, and any other after them; bp and ssa-svr are "
                "always needed",
                {}},
               [](const O& o) {
                 std::string out;
                 for (const Method& m : o.methods) {
                   if (!out.empty()) out += ',';
                   out += to_string(m);
                 }
                 return out;
               },
               [](O& o, const std::string& text) {
                 o.methods.clear();
                 for (const std::string& name : option_items(text))
                   o.methods.push_back(parse_method(name, "methods"));
               }});
  t.push_back(whole_option<O>(
      {"first_seed", "--first-seed", {}, "", "", "The first seed; the next ones are one apart", {}},
      [](auto& o) -> auto& { return o.first_seed; }));
  t.push_back(whole_option<O>(
      {"population",
       "--population",
       {},
       "",
       between(5, 10000),
       "Optimizer population of the tuned SVRs",
       {}},
      [](auto& o) -> auto& { return o.population; }));
  t.push_back(whole_option<O>(
      {"iterations",
       "--iterations",
       {},
       "",
       between(1, 100000),
       "Optimizer iterations of the tuned SVRs",
       {}},
      [](auto& o) -> auto& { return o.iterations; }));
  t.push_back(choice_option<O>(
      {"fitness",
       "--fitness",
       {},
       "",
       tune::fitness_names(),
       "What the tuned SVRs' candidates are scored by: cv (grouped cross-validation) or train "
       "(the paper's training RMSE)",
       {}},
      [](auto& o) -> auto& { return o.fitness; },
      [](tune::Fitness f) { return tune::to_string(f); },
      [](const std::string& text, const std::string& keyword) {
        return tune::parse_fitness(text, keyword);
      }));
  t.push_back(choice_option<O>(
      {"cv",
       "--cv",
       {},
       "",
       tune::cv_scheme_names(),
       "Folds of the cv fitness: auto, repetition (leave one training repetition out), "
       "recording (k folds of whole recordings, k by {folds}) or temperature (k folds of whole "
       "calibration temperatures, scoring a model where it was not trained)",
       {"cv.scheme"}},
      [](auto& o) -> auto& { return o.cv.scheme; },
      [](tune::CvScheme s) { return tune::to_string(s); },
      [](const std::string& text, const std::string& keyword) {
        return tune::parse_cv_scheme(text, keyword);
      }));
  t.push_back(whole_option<O>(
      {"folds",
       "--folds",
       {},
       "",
       at_least(2).with("at most the temperatures or recordings there are"),
       "k, the folds of {cv} recording or temperature",
       {"cv.folds"}},
      [](auto& o) -> auto& { return o.cv.folds; }));
  t.push_back(number_option<O>(
      tune::epsilon_option_spec(), [](auto& o) -> auto& { return o.epsilon; }));
  t.push_back(on_off_option<O>(
      {"search_epsilon",
       "--search-epsilon",
       {},
       "",
       "",
       "The tuned SVRs also search ε in [0.001, 1] (the paper tunes C "
       "and σ only)",
       {}},
      [](auto& o) -> auto& { return o.search_epsilon; }));
  t.push_back({{"approach",
                "--approach",
                OptionType::choice,
                "",
                sim::approach_names(true),
                "How the Table 3 north-finding start-ups begin (fogdrift simulate northfind "
                "--help)",
                {"northfind.approach"}},
               [](const O& o) { return std::string(to_string(o.northfind.approach)); },
               [](O& o, const std::string& text) {
                 o.northfind.approach = sim::approach_from_string(text, "approach");
               }});
  t.push_back({{"cal_approaches",
                "--cal-approaches",
                OptionType::names,
                "",
                sim::approach_names(false),
                "How each calibration repetition's start-ups begin, cycling (fogdrift simulate "
                "calibration --help): docs/field.md's five-sweep field protocol (for a unit of "
                "unknown physics it recommends seven, adding warm,warm,calibration); the "
                "paper's own is {cal_approaches} calibration and {repetitions} 4",
                {"calibration.approaches"}},
               [](const O& o) { return sim::approaches_to_string(o.calibration.approaches); },
               [](O& o, const std::string& text) {
                 o.calibration.approaches = sim::approaches_from_string(text, "cal_approaches");
               }});
  t.push_back(whole_option<O>(
      {"repetitions",
       "--repetitions",
       {},
       "",
       between(2, 100),
       "Calibration repetitions; the last one is the test repetition",
       {"calibration.repetitions"}},
      [](auto& o) -> auto& { return o.calibration.repetitions; }));
  t.push_back({{"start_ups",
                "--start-ups",
                OptionType::names,
                "",
                sim::approach_names(true) + "; none",
                "Approaches of the start-up conditions table, or none",
                {}},
               [](const O& o) {
                 return o.start_ups.empty() ? std::string("none")
                                            : sim::approaches_to_string(o.start_ups);
               },
               [](O& o, const std::string& text) {
                 o.start_ups = text == "none" ? std::vector<sim::Approach>{}
                                              : sim::approaches_from_string(text, "start_ups");
               }});
  t.push_back(numbers_option<O>(
      {"cal_temps_degc",
       "--cal-temps",
       {},
       "°C",
       between(-70, 100),
       "Calibration chamber temperatures",
       {"calibration.temps_degc"}},
      [](auto& o) -> auto& { return o.calibration.temps_degc; }));
  t.push_back(numbers_option<O>(
      {"nf_temps_degc",
       "--nf-temps",
       {},
       "°C",
       between(-70, 100),
       "North-finding initial temperatures",
       {"northfind.temps_degc"}},
      [](auto& o) -> auto& { return o.northfind.temps_degc; }));
  t.push_back(whole_option<O>(
      {"findings",
       "--findings",
       {},
       "",
       between(1, 1000),
       "North-findings per initial temperature",
       {"northfind.findings"}},
      [](auto& o) -> auto& { return o.northfind.findings; }));
  t.push_back(on_off_option<O>(
      {"studies",
       "--no-studies",
       {},
       "",
       "",
       "The leave-one-temperature-out and fitness studies on the first "
       "seed",
       {}},
      [](auto& o) -> auto& { return o.studies; }));
  return t;
}

}  // namespace

const OptionTable<PaperOptions>& paper_option_table() {
  static const OptionTable<PaperOptions> table = make_paper_table();
  return table;
}

}  // namespace fogdrift::report
