// Compensation one sample at a time, causally, as an instrument's processor runs it
// (docs/method.md §4: a model in the field runs causally, one sample at a time).
//
// Each update takes the logger's sample (time, gyro, its temperatures), differentiates the
// temperatures with the causal Savitzky–Golay filter of the model's window and degree
// (signal::CausalDifferentiator), forms the model's features exactly as compute_features() does
// at the sample rate, and returns the predicted drift. Nothing is allocated per sample.
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
#include <span>
#include <vector>

#include "fogdrift/model/decimate.hpp"
#include "fogdrift/model/model.hpp"
#include "fogdrift/signal/differentiate.hpp"
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

class StreamingCompensator {
 public:
  /// `dt_s` is the logger's sample interval. Throws OptionError for an invalid FaultPolicy, and
  /// (naming "rate") for an interval the model cannot run at (decimation_factor). A sample's
  /// further_degc holds the model's further thermometers (model.dataset.features.further); one
  /// it lacks is a faulty reading (temp_bad).
  StreamingCompensator(const CompensationModel& model, double dt_s,
                       const StreamOptions& options = {});

  /// The drift and compensated gyro at this sample, guarded unless the options said otherwise.
  StreamOutput update(const Sample& s) noexcept;
  /// Starts again, as at power-on.
  void reset() noexcept;
  /// ν and w of the last sample the model was evaluated on (NaN and 1 without a guard).
  double novelty() const noexcept { return last_.novelty; }
  double weight() const noexcept { return weight_; }

 private:
  // What the fault policy keeps of one thermometer the model reads.
  struct ThermometerState {
    bool read = false;
    bool seen_good = false;  // a good reading since power-on
    bool out = false;        // its outage has lasted longer than bridge_s
    double good_degc = 0, good_time_s = 0, good_rate = 0;  // the last good reading
    double pushed_degc = 0;  // the last value given to its differentiator
    // The stuck check: the reading, since when it has not changed, and the other thermometers'
    // readings then (NaN: not known).
    bool tracking = false;
    double unchanged_degc = 0, unchanged_since_s = 0;
    std::vector<double> others_degc;  // one per thermometer, sized once
    void clear() noexcept;            // as at power-on, keeping `read` and the memory
  };

  const CompensationModel& model_;
  std::size_t k_;     // data samples per model sample (decimate.hpp)
  double data_dt_s_;  // the logger's interval
  double dt_s_;       // the model's: k_ · data_dt_s_
  FaultPolicy faults_;
  double reading_limit_;  // gyro_limit_dph for a gyro target, ∞ for another (stream_faults.hpp)
  std::size_t nt_;        // thermometers numbered in the model's spec
  std::vector<signal::CausalDifferentiator> rates_;
  std::vector<FeatureColumn> columns_;  // the model's inputs (FeatureSpec::columns())
  // The lagged rates (dT@τ) among them: the input each fills and its lag.
  struct Lag {
    std::size_t column;
    LaggedRate rate;
    double value = 0;  // its term at the last sample pushed, °C/s
  };
  std::vector<Lag> lags_;
  std::vector<double> features_, work_;
  bool guarded_;
  GuardFilter filter_;
  DriftPrediction last_;
  double weight_ = 1.0;
  // Fault policy state (see stream_faults.hpp).
  std::vector<ThermometerState> thermometers_;
  // One sample's thermometers: raw, good and stuck, and the values and rates the model reads.
  std::vector<double> raw_, temp_, rate_;
  std::vector<char> good_, stuck_;
  bool started_ = false;
  double previous_time_s_ = 0;
  std::size_t refill_ = 0;  // samples until the rate filters have a full window again
  bool has_good_drift_ = false;
  double good_drift_dph_ = 0, good_drift_time_s_ = 0;
  double last_drift_dph_ = 0, last_comp_dph_ = 0;
  // The block being filled (k_ > 1), and the time of the last data sample taken.
  BlockSum block_;
  bool data_started_ = false;
  double data_time_s_ = 0;

  // One sample at the model's interval: the fault policy, the rates, the model and the guard.
  StreamOutput step(const Sample& s, std::uint32_t flags) noexcept;
  void check_thermometers(double time_s, std::uint32_t& flags) noexcept;
  void further_into_raw(const Sample& s) noexcept;
  void push_lags(std::size_t k, double temp_degc) noexcept;
  double substitute(std::size_t k, double time_s) const noexcept;
  double degraded(double time_s, std::uint32_t& flags) const noexcept;
  StreamOutput finish(const Sample& s, double drift_dph, std::uint32_t flags) noexcept;
};

}  // namespace fogdrift
