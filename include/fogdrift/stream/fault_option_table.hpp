// The streaming fault policy's options, described once (option_table.hpp, docs/options.md):
// the last part of `stream`'s table (stream_option_table.hpp: `fogdrift stream`'s flags, Python's
// StreamingCompensator's keywords) and of `export-c`'s (export_option_table.hpp). The timings a
// user does not give are fitted to the model (fault_policy_for, stream_faults.hpp) by each front
// end.
#pragma once

#include "fogdrift/base/option_table.hpp"
#include "fogdrift/stream/stream_faults.hpp"

namespace fogdrift {

const OptionTable<FaultPolicy>& fault_option_table();

}  // namespace fogdrift
