// The evaluations' options, described once (option_table.hpp, docs/options.md): `fogdrift
// evaluate`'s and `fogdrift northfind`'s flags and the keywords of Python's fogdrift.evaluate,
// fogdrift.northfind and fogdrift.find_north come from these tables. What names the data (the
// model, the campaign or recordings, what the gyro sensed) each front end declares itself.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/eval/evaluation.hpp"
#include "fogdrift/eval/findings.hpp"

namespace fogdrift::eval {

/// `evaluate`'s options: the guard, the Allan terms.
const OptionTable<EvaluationOptions>& evaluation_option_table();
/// `northfind`'s (and find_north's) options: the guard, how the positions are found.
const OptionTable<FindingOptions>& finding_option_table();

}  // namespace fogdrift::eval
