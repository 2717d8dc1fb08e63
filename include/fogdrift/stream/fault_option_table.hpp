// The streaming fault policy's options, described once (option_table.hpp, docs/options.md):
// `fogdrift stream`'s and `fogdrift export-c`'s flags and the keywords of Python's
// StreamingCompensator come from this table. The timings a user does not give are fitted to
// the model (fault_policy_for, stream_faults.hpp) by each front end.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/stream/stream_faults.hpp"

namespace fogdrift {

const OptionTable<FaultPolicy>& fault_option_table();

}  // namespace fogdrift
