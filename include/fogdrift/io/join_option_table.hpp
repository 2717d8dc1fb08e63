// `fogdrift join`'s options, described once (option_table.hpp, docs/options.md): what to bring in,
// how to align the two clocks and how far to interpolate. What only decides how the command
// runs (the two files, the output, --quiet) it declares itself.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/io/join.hpp"

namespace fogdrift {

/// In the order they are applied: offset_range_s after offset_from, whose searches it widens.
const OptionTable<JoinOptions>& join_option_table();

}  // namespace fogdrift
