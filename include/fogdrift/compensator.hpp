// Compensation one sample at a time, causally, as an instrument's processor runs it
// (docs/method.md §4: a model in the field runs causally, one sample at a time).
//
// Each update takes the logger's sample (time, gyro, three temperatures), differentiates the
// temperatures with the causal Savitzky–Golay filter of the model's window and degree
// (signal::CausalDifferentiator), forms the model's features exactly as compute_features() does
// at the sample rate, and returns the predicted drift. Nothing is allocated per sample.
//
// With a model trained on causal features (`fogdrift train --differentiator causal`) the
// result equals the batch path, CompensationModel::predict_dph(Recording), sample for sample.
// A model trained on centred (offline) features can be streamed too, but its rate features then
// differ from those it was trained on (a causal fit lags or is noisier); docs/compensation.md
// measures what that costs.
#pragma once

#include <array>
#include <vector>

#include "fogdrift/model.hpp"
#include "fogdrift/signal/differentiate.hpp"

namespace fogdrift {

struct Sample {
  double time_s = 0;
  double gyro_dph = 0;
  double temp_fog_degc = 0;
  double temp_acc1_degc = 0;
  double temp_acc2_degc = 0;
};

class StreamingCompensator {
 public:
  /// `dt_s` is the logger's sample interval (the differentiator's taps depend on it).
  StreamingCompensator(const CompensationModel& model, double dt_s, bool guarded = true);

  /// The predicted drift at this sample, °/h, guarded unless the constructor said otherwise
  /// (guard.hpp); compensated output = s.gyro_dph − drift.
  double update(const Sample& s) noexcept;
  /// Starts again, as at power-on.
  void reset() noexcept;
  /// ν and w of the last update (NaN and 1 without a guard in the model).
  double novelty() const noexcept { return last_.novelty; }
  double weight() const noexcept { return weight_; }

 private:
  const CompensationModel& model_;
  std::array<signal::CausalDifferentiator, 3> rates_;
  std::vector<FeatureColumn> columns_;  // the model's inputs (FeatureSpec::columns())
  std::vector<double> features_, work_;
  bool guarded_;
  GuardFilter filter_;
  DriftPrediction last_;
  double weight_ = 1.0;
};

}  // namespace fogdrift
