// The evaluations' options (eval_option_table.hpp). Defaults are the options structs'; validate()
// (northfind.hpp) checks the segmentation and names each field by its keyword.
#include "fogdrift/eval/eval_option_table.hpp"

#include "fogdrift/model/guard_option.hpp"

namespace fogdrift::eval {
namespace {

OptionTable<EvaluationOptions> make_evaluation() {
  using O = EvaluationOptions;
  OptionTable<O> t;
  t.push_back(guarded_option<O>());
  t.push_back(on_off_option<O>(
      {"allan",
       "--allan",
       {},
       "",
       "",
       "Also the overlapping Allan deviation of every recording's output before and after "
       "compensation: angle random walk, bias instability, rate random walk (a gyro's terms; an "
       "accelerometer or scale-factor target gets none)",
       {}},
      [](auto& o) -> auto& { return o.allan; }));
  return t;
}

OptionTable<FindingOptions> make_finding() {
  using O = FindingOptions;
  OptionTable<O> t;
  t.push_back(guarded_option<O>());
  t.push_back(number_option<O>(
      {"tolerance_deg",
       "--tolerance-deg",
       {},
       "°",
       above(0).below(45),
       "A sample is at a position when table_deg is this close to it",
       {}},
      [](auto& o) -> auto& { return o.segmentation.tolerance_deg; }));
  t.push_back(number_option<O>(
      {"settle_s",
       "--settle-s",
       {},
       "s",
       at_least(0),
       "Samples this soon after the table arrives at a position are "
       "not used",
       {}},
      [](auto& o) -> auto& { return o.segmentation.settle_s; }));
  t.push_back(number_option<O>(
      {"min_dwell_s",
       "--min-dwell-s",
       {},
       "s",
       above(0),
       "A position held for less time than this is not used",
       {}},
      [](auto& o) -> auto& { return o.segmentation.min_dwell_s; }));
  return t;
}

}  // namespace

const OptionTable<EvaluationOptions>& evaluation_option_table() {
  static const OptionTable<EvaluationOptions> table = make_evaluation();
  return table;
}

const OptionTable<FindingOptions>& finding_option_table() {
  static const OptionTable<FindingOptions> table = make_finding();
  return table;
}

}  // namespace fogdrift::eval
