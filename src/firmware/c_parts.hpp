// The parts of the C header beside the scalers and the regressor (c_header.hpp): the novelty
// guard (c_guard.cpp) and the causal streaming compensator (c_streaming.cpp). Each returns C text
// with the header's placeholders (@REAL@, @F@, @UNIT@, ...), which to_c_header fills. Internal
// header.
#pragma once

#include <string>

#include "fogdrift/model/model.hpp"
#include "fogdrift/stream/stream_faults.hpp"

namespace fogdrift::detail {

/// The guard's tables, PREFIX_novelty(features) and PREFIX_target_weight(nu), the same
/// operations in the same order as NoveltyGuard; empty for a model without a guard.
std::string c_guard_part(const CompensationModel& model, const std::string& prefix,
                         const std::string& upper);
/// PREFIX_state, PREFIX_reset, PREFIX_update and PREFIX_compensated_UNIT for samples every
/// `stream_dt_s` s (to_c_header's contract); OptionError as it documents.
std::string c_streaming_part(const CompensationModel& model, const std::string& prefix,
                             const std::string& upper, double stream_dt_s,
                             const FaultPolicy& faults, bool single);

}  // namespace fogdrift::detail
