// The paper experiment's options, described once (option_table.hpp, docs/options.md): the flags
// of `fogdrift paper` and `fogdrift demo` (with the demo's own defaults) come from this table.
// What only decides how the command runs (--out, --force, --instrument, --threads, --json,
// --quiet) the command declares itself.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/report/paper.hpp"

namespace fogdrift::report {

const OptionTable<PaperOptions>& paper_option_table();

}  // namespace fogdrift::report
