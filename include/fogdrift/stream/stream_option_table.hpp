// `stream`'s options, described once (option_table.hpp, docs/options.md): the guard's switch
// (guard_option.hpp) and the fault policy's options (fault_option_table.hpp), as `fogdrift
// stream`'s flags and the keywords of Python's StreamingCompensator. The fault timings a user
// does not give are fitted to the model (fault_policy_of) by each front end before the table's
// options are applied.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/stream/compensator.hpp"

namespace fogdrift {

const OptionTable<StreamOptions>& stream_option_table();

}  // namespace fogdrift
