// The flags of the options that run a streaming compensator: the fault policy's (FaultPolicy,
// stream_faults.hpp), which `export-c` takes, and `stream`'s, the guard and the fault policy
// (stream_option_table.hpp); each made from its one description.
#pragma once

#include <memory>

#include "fogdrift/model/model.hpp"
#include "fogdrift/stream/compensator.hpp"
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

/// Adds `stream`'s flags to `cmd`: --no-guard and the fault policy's, in the group "Guard and
/// sensor faults".
std::shared_ptr<OptionFlags> add_stream_options(CLI::App* cmd);

/// The options to stream `model` with: its fault policy as fault_policy() makes it, the guard
/// as the flags say. Checked; errors name the flag.
StreamOptions stream_options(const OptionFlags& flags, const CompensationModel& model);

}  // namespace fogdrift::app
