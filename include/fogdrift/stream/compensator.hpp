// Compensation one sample at a time, causally, as an instrument's processor runs it
// (docs/method.md §4: a model in the field runs causally, one sample at a time).
//
// Each update takes the logger's sample (time, gyro, its temperatures), differentiates the
// temperatures with the causal Savitzky–Golay filter of the model's window and degree
// (signal::CausalDifferentiator), forms the model's features exactly as compute_features() does
// at the sample rate, and returns the predicted drift. Nothing is allocated per sample.
//
// The step is written once, in C (src/stream/step.h; docs/architecture.md, "One streaming
// step"): this class runs it with the model's tables sized at run time, and every C header
// `export-c --stream-rate-hz` writes embeds the same code with the tables as constants. A fault
// rule is changed in that one file.
//
// With a model trained on causal features (`fogdrift train --differentiator causal`) the
// result equals the batch path, CompensationModel::predict_dph(Recording), sample for sample.
// A model trained on centred (offline) features can be streamed too, but its rate features then
// differ from those it was trained on (a causal fit lags or is noisier); docs/compensation.md
// measures what that costs.
//
// Data faster than the model's interval (a 1 Hz model on a 100 Hz logger) are averaged in blocks
// of k samples and the model runs once per block (decimate.hpp): the cost per sample does not
// grow with the rate, and the result equals the batch path's on the same data.
//
// Faulty samples (a thermometer or gyro that is not a number, out of range or stuck, a time gap,
// time that does not advance or goes back) are handled by the policy of stream_faults.hpp: the
// output is always finite, each affected sample is flagged, and without faults nothing changes.
#pragma once

#include <cstdint>
#include <memory>
#include <span>

#include "fogdrift/model/model.hpp"
#include "fogdrift/stream/stream_faults.hpp"

namespace fogdrift {

struct Sample {
  double time_s = 0;
  double gyro_dph = 0;
  double temp_fog_degc = 0;
  double temp_acc1_degc = 0;
  double temp_acc2_degc = 0;
  /// The further thermometers of the model's spec (FeatureSpec::further), in that order; the
  /// caller's memory, read during update() only (docs/logs.md, "More thermometers").
  std::span<const double> further_degc = {};
};

/// The fault policy a model runs with unless told otherwise: the bridge, hold and stuck timings
/// fitted to the model's sample interval and rate window (fault_policy_for), for a model file
/// that records its interval; the defaults otherwise. `fogdrift stream`, `export-c` and Python's
/// StreamingCompensator start from it and set what the user gives.
FaultPolicy fault_policy_of(const CompensationModel& model);

/// The highest logger rate a streaming compensator is run at (`stream --rate-hz`, `export-c
/// --stream-rate-hz`), Hz.
inline constexpr double kMaxStreamRateHz = 10000;

struct StreamOptions {
  /// Reduce the correction where the inputs are novel to the model (guard.hpp); ignored for a
  /// model without a guard.
  bool guarded = true;
  FaultPolicy faults;
};

struct StreamOutput {
  double drift_dph = 0;      ///< predicted drift, °/h; always finite
  double gyro_comp_dph = 0;  ///< gyro − drift; the last good value where the gyro is faulty
  std::uint32_t flags = 0;   ///< fault:: flags of this sample, 0 for a good one
};

namespace detail {
struct StepCore;
}

/// The one streaming step (src/stream/step.h, C99 compiled here with run-time tables, and
/// embedded in every C header export-c writes), wrapped for the library.
class StreamingCompensator {
 public:
  /// `dt_s` is the logger's sample interval. Throws OptionError for an invalid FaultPolicy, and
  /// (naming "rate") for an interval the model cannot run at (decimation_factor). A sample's
  /// further_degc holds the model's further thermometers (model.dataset.features.further); one
  /// it lacks is a faulty reading (temp_bad).
  StreamingCompensator(const CompensationModel& model, double dt_s,
                       const StreamOptions& options = {});
  ~StreamingCompensator();
  StreamingCompensator(StreamingCompensator&&) noexcept;
  StreamingCompensator& operator=(StreamingCompensator&&) noexcept;

  /// The drift and compensated gyro at this sample, guarded unless the options said otherwise.
  StreamOutput update(const Sample& s) noexcept;
  /// Starts again, as at power-on.
  void reset() noexcept;
  /// ν and w of the last sample the model was evaluated on (NaN and 1 without a guard).
  double novelty() const noexcept;
  double weight() const noexcept;

 private:
  // The step's state and the model's tables, sized at run time (compensator.cpp).
  std::unique_ptr<detail::StepCore> core_;
};

}  // namespace fogdrift
