// The streaming fault policy's flags (FaultPolicy, stream_faults.hpp), shared by `stream` and
// `export-c`, which both run the policy: made from its one description (fault_option_table.hpp).
#pragma once

#include <memory>

#include "fogdrift/model/model.hpp"
#include "fogdrift/stream/stream_faults.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {

/// Adds the fault policy's flags to `cmd` (--temp-min-degc, …, --temp-jump-degc), in the group
/// "Sensor faults".
std::shared_ptr<OptionFlags> add_fault_options(CLI::App* cmd);

/// The policy to run `model` with: the timings the user did not give (--bridge-s, --hold-s,
/// --stuck-s) fitted to the model's interval and rate window (fault_policy_for) when the model
/// records its interval, the defaults otherwise, then the flags given. Checked; errors name the
/// flag.
FaultPolicy fault_policy(const OptionFlags& flags, const CompensationModel& model);

}  // namespace fogdrift::app
