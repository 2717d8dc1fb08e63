// The streaming fault policy's flags (FaultPolicy, stream_faults.hpp), shared by `stream` and
// `export-c`, which both run the policy: one place binds them to the struct's fields.
#pragma once

#include <CLI/CLI.hpp>

#include "cli_util.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/model/stream_faults.hpp"

namespace fogdrift::app {

/// Adds --temp-min-degc, --temp-max-degc, --gyro-limit-dph, --bridge-s, --hold-s, --stuck-s and
/// --stuck-delta-degc to `cmd`, bound to `policy`'s fields (defaults shown from the struct).
void add_fault_options(CLI::App* cmd, FaultPolicy& policy);

/// The timings the user did not give (--bridge-s, --hold-s, --stuck-s) from the model's interval
/// and rate window (fault_policy_for), for a model that records its interval.
void fault_timings_from_model(const CLI::App& cmd, const CompensationModel& model,
                              FaultPolicy& policy);

/// faults.* field → flag, for with_flags().
const FlagTable& fault_flags();

}  // namespace fogdrift::app
