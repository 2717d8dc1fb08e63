// The flags of the options that run a streaming compensator, each made from its one description:
// `export-c`'s (export_option_table.hpp) and `stream`'s (stream_command_option_table.hpp), both
// ending in the fault policy (FaultPolicy, stream_faults.hpp), whose timings are first fitted to
// the model.
#pragma once

#include <memory>

#include "fogdrift/firmware/export_option_table.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/stream/compensator.hpp"
#include "fogdrift/stream/stream_command_option_table.hpp"
#include "fogdrift/stream/stream_faults.hpp"
#include "option_flags.hpp"

namespace fogdrift::app {

/// Adds `export-c`'s flags to `cmd`: --prefix, --stream-rate-hz, --precision, --force-float and
/// the fault policy's, in the group "Header and sensor faults".
std::shared_ptr<OptionFlags> add_export_options(CLI::App* cmd);

/// The options to export `model` with: the fault policy fitted to the model (fault_policy_of:
/// its bridge, hold and stuck timings to its interval and rate window), then the flags given.
/// Checked; errors name the flag.
ExportOptions export_options(const OptionFlags& flags, const CompensationModel& model);

/// Adds `stream`'s flags to `cmd` (stream_command_option_table.hpp): --rate-hz, --strict,
/// --no-guard and the fault policy's, in the group "Rate, guard and sensor faults".
std::shared_ptr<OptionFlags> add_stream_options(CLI::App* cmd);

/// The options to stream `model` with: the fault policy fitted to it as export_options() fits
/// it, then the flags given. Checked; errors name the flag.
StreamCommandOptions stream_options(const OptionFlags& flags, const CompensationModel& model);

}  // namespace fogdrift::app
