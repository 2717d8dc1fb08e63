#include "fogdrift/stream/compensator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fogdrift {

FaultPolicy fault_policy_of(const CompensationModel& model) {
  const FeatureOptions& f = model.dataset.preprocessing;
  if (f.sample_interval_s == 0) return {};  // a model file that does not record it
  return fault_policy_for(f.sample_interval_s, static_cast<double>(signal::window_samples(
                                                   f.rates, f.sample_interval_s)) *
                                                   f.sample_interval_s);
}

StreamingCompensator::StreamingCompensator(const CompensationModel& model, double dt_s,
                                           const StreamOptions& options)
    : model_(model),
      k_(decimation_factor(model.dataset.preprocessing, dt_s, "rate")),
      data_dt_s_(streaming_interval_s(model.dataset.preprocessing, dt_s, k_)),
      dt_s_(static_cast<double>(k_) * data_dt_s_),
      faults_(options.faults),
      reading_limit_(target_of(model.dataset.target_column).kind == TargetKind::gyro
                         ? faults_.gyro_limit_dph
                         : std::numeric_limits<double>::infinity()),
      nt_(model.dataset.features.thermometer_count()),
      rates_(nt_, signal::CausalDifferentiator(model.dataset.preprocessing.rates, dt_s_)),
      columns_(model.dataset.features.columns()),
      features_(model.inputs()),
      work_(model.inputs()),
      guarded_(options.guarded && !model.guard.empty()),
      thermometers_(nt_),
      raw_(nt_),
      temp_(nt_),
      rate_(nt_),
      good_(nt_),
      stuck_(nt_),
      block_(nt_) {
  validate(faults_);
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c].lagged()) lags_.push_back({c, LaggedRate(columns_[c].tau_s, dt_s_)});
  for (std::size_t k = 0; k < nt_; ++k) {
    thermometers_[k].read = model.dataset.features.reads(static_cast<Thermometer>(k));
    thermometers_[k].others_degc.assign(nt_, 0.0);
  }
}

void StreamingCompensator::ThermometerState::clear() noexcept {
  seen_good = out = tracking = false;
  good_degc = good_time_s = good_rate = pushed_degc = 0;
  unchanged_degc = unchanged_since_s = 0;
  std::fill(others_degc.begin(), others_degc.end(), 0.0);
}

void StreamingCompensator::reset() noexcept {
  for (auto& r : rates_) r.reset();
  for (Lag& lag : lags_) lag.rate.reset();
  filter_.reset();
  weight_ = 1.0;
  for (ThermometerState& th : thermometers_) th.clear();
  started_ = false;
  refill_ = 0;
  has_good_drift_ = false;
  last_drift_dph_ = last_comp_dph_ = 0;
  block_.clear();
  data_started_ = false;
}

// Which thermometers the model reads give a good reading at this sample: a number inside the
// policy's range, no jump from its last good reading continued along its rate (judged within
// bridge_s of that reading: a step that lasts longer is real), and not stuck
// (stream_faults.hpp). Raises temp_bad, temp_jump and temp_stuck.
void StreamingCompensator::check_thermometers(double time_s, std::uint32_t& flags) noexcept {
  const std::vector<double>& raw = raw_;
  std::vector<char>& good = good_;
  for (std::size_t k = 0; k < nt_; ++k) {
    good[k] = false;
    if (!thermometers_[k].read) continue;
    good[k] =
        std::isfinite(raw[k]) && raw[k] >= faults_.temp_min_degc && raw[k] <= faults_.temp_max_degc;
    if (!good[k]) {
      flags |= fault::temp_bad;
      continue;
    }
    const ThermometerState& th = thermometers_[k];
    if (faults_.temp_jump_degc > 0 && th.seen_good && time_s - th.good_time_s <= faults_.bridge_s &&
        std::abs(raw[k] - substitute(k, time_s)) > faults_.temp_jump_degc) {
      good[k] = false;
      flags |= fault::temp_jump;
    }
  }
  if (faults_.stuck_s <= 0) return;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::fill(stuck_.begin(), stuck_.end(), false);
  for (std::size_t k = 0; k < nt_; ++k) {
    ThermometerState& th = thermometers_[k];
    if (!good[k]) continue;
    if (!th.tracking || raw[k] != th.unchanged_degc) {
      th.tracking = true;
      th.unchanged_degc = raw[k];
      th.unchanged_since_s = time_s;
      for (std::size_t j = 0; j < nt_; ++j) th.others_degc[j] = good[j] ? raw[j] : nan;
      continue;
    }
    for (std::size_t j = 0; j < nt_; ++j) {
      if (j == k || !good[j]) continue;
      if (std::isnan(th.others_degc[j])) th.others_degc[j] = raw[j];  // known from now on
      if (time_s - th.unchanged_since_s >= faults_.stuck_s &&
          std::abs(raw[j] - th.others_degc[j]) >= faults_.stuck_delta_degc)
        stuck_[k] = true;
    }
  }
  for (std::size_t k = 0; k < nt_; ++k)
    if (stuck_[k]) {
      good[k] = false;
      flags |= fault::temp_stuck;
    }
}

// Thermometer k's value for one sample into the lags that read it.
void StreamingCompensator::push_lags(std::size_t k, double temp_degc) noexcept {
  for (Lag& lag : lags_)
    if (static_cast<std::size_t>(columns_[lag.column].a) == k) lag.value = lag.rate.push(temp_degc);
}

// The sample's further thermometers into raw_[3…]; one the sample does not hold is a reading
// that is not a number, a fault as any other (stream_faults.hpp).
void StreamingCompensator::further_into_raw(const Sample& s) noexcept {
  for (std::size_t k = 3; k < nt_; ++k)
    raw_[k] = k - 3 < s.further_degc.size() ? s.further_degc[k - 3]
                                            : std::numeric_limits<double>::quiet_NaN();
}

// A faulty thermometer's stand-in: its last good reading continued along its last good rate,
// kept inside the policy's range.
double StreamingCompensator::substitute(std::size_t k, double time_s) const noexcept {
  const ThermometerState& th = thermometers_[k];
  if (!th.seen_good) return std::clamp(0.0, faults_.temp_min_degc, faults_.temp_max_degc);
  const double v = th.good_degc + th.good_rate * (time_s - th.good_time_s);
  return std::clamp(v, faults_.temp_min_degc, faults_.temp_max_degc);
}

// The drift where the model cannot be evaluated: the last good drift for up to hold_s after it,
// then the model's mean drift (the correction stopped, as the guard at weight 0).
double StreamingCompensator::degraded(double time_s, std::uint32_t& flags) const noexcept {
  if (has_good_drift_ && time_s - good_drift_time_s_ <= faults_.hold_s) {
    flags |= fault::held;
    return good_drift_dph_;
  }
  flags |= fault::stopped;
  return model_.guarded_dph(0.0, 0.0);
}

StreamOutput StreamingCompensator::finish(const Sample& s, double drift_dph,
                                          std::uint32_t flags) noexcept {
  StreamOutput out{drift_dph, last_comp_dph_, flags};
  if (std::isfinite(s.gyro_dph) && std::abs(s.gyro_dph) <= reading_limit_)
    out.gyro_comp_dph = last_comp_dph_ = s.gyro_dph - drift_dph;
  else
    out.flags |= fault::gyro_bad;
  return out;
}

StreamOutput StreamingCompensator::update(const Sample& s) noexcept {
  if (k_ == 1) return step(s, 0);
  // Blocks of k_ samples (decimate.hpp); time is checked here at the data's interval as step()
  // checks it at the model's.
  std::uint32_t flags = 0;
  double t = s.time_s;
  if (!std::isfinite(t)) {
    flags |= fault::time_bad;
    t = data_started_ ? data_time_s_ + data_dt_s_ : 0.0;
  }
  if (data_started_) {
    const double gap = t - data_time_s_;
    if (gap < -faults_.bridge_s) {
      reset();
      flags |= fault::restart;
    } else if (gap < 0.5 * data_dt_s_) {
      return finish(s, last_drift_dph_, flags | fault::out_of_order);
    } else if (gap <= 1.5 * data_dt_s_ && off_interval(gap, data_dt_s_)) {
      flags |= fault::off_interval;
    }
  }
  const bool first = !data_started_;
  data_started_ = true;
  data_time_s_ = t;
  raw_[0] = s.temp_fog_degc, raw_[1] = s.temp_acc1_degc, raw_[2] = s.temp_acc2_degc;
  further_into_raw(s);
  block_.add(raw_, 0.0);
  if (!first && block_.count < k_) return finish(s, last_drift_dph_, flags);
  const auto c = static_cast<double>(block_.count);
  for (std::size_t k = 0; k < nt_; ++k) temp_[k] = block_.temp[k] / c;
  const Sample mean{t,        s.gyro_dph, temp_[0],
                    temp_[1], temp_[2],   std::span<const double>(temp_).subspan(3)};
  block_.clear();
  return step(mean, flags);
}

StreamOutput StreamingCompensator::step(const Sample& s, std::uint32_t flags) noexcept {
  double t = s.time_s;
  if (!std::isfinite(t)) {
    flags |= fault::time_bad;
    t = started_ ? previous_time_s_ + dt_s_ : 0.0;
  }
  // Time: a restart, a sample that does not advance, or a gap before this sample.
  std::size_t missing = 0;
  bool long_gap = false;
  if (started_) {
    const double step = t - previous_time_s_;
    if (step < -faults_.bridge_s) {
      reset();
      flags |= fault::restart;
    } else if (step < 0.5 * dt_s_) {
      return finish(s, last_drift_dph_, flags | fault::out_of_order);
    } else if (step > 1.5 * dt_s_) {
      flags |= fault::gap;
      if (step - dt_s_ > faults_.bridge_s)
        long_gap = true;
      else
        missing = static_cast<std::size_t>(std::lround(step / dt_s_)) - 1;
    } else if (off_interval(step, dt_s_)) {
      flags |= fault::off_interval;
    }
  }
  // raw_ from the sample first: step() may be given the block means held in temp_.
  further_into_raw(s);
  raw_[0] = s.temp_fog_degc, raw_[1] = s.temp_acc1_degc, raw_[2] = s.temp_acc2_degc;
  check_thermometers(t, flags);
  const std::vector<double>& raw = raw_;
  const std::vector<char>& good = good_;
  // Outages: bridged up to bridge_s, out beyond; a thermometer back from being out, or a gap
  // too long to bridge, starts the rate filters again.
  bool restart_rates = long_gap, any_out = false, any_bridged = false;
  for (std::size_t k = 0; k < nt_; ++k) {
    ThermometerState& th = thermometers_[k];
    if (!th.read) continue;
    if (good[k]) {
      restart_rates |= th.out;
      th.out = false;
      continue;
    }
    if (!th.seen_good || t - th.good_time_s > faults_.bridge_s) th.out = true;
    (th.out ? any_out : any_bridged) = true;
  }
  if (restart_rates) {
    // The lags start again with the rates, as at rest (features.hpp, LaggedRate).
    for (auto& r : rates_) r.reset();
    for (Lag& lag : lags_) lag.rate.reset();
    // At power-on (no drift given yet) the short windows are those the model was trained with.
    refill_ = has_good_drift_ ? rates_[0].window() - 1 : 0;
    missing = 0;
  }
  std::vector<double>&temp = temp_, &rate = rate_;
  std::fill(temp.begin(), temp.end(), 0.0);
  std::fill(rate.begin(), rate.end(), 0.0);
  for (std::size_t k = 0; k < nt_; ++k) {
    ThermometerState& th = thermometers_[k];
    if (!th.read) continue;
    temp[k] = good[k] ? raw[k] : substitute(k, t);
    // The missing samples of a bridged gap, on the interval: interpolated towards this sample.
    for (std::size_t m = 1; m <= missing; ++m) {
      const double tm = previous_time_s_ + static_cast<double>(m) * dt_s_;
      const double v = good[k]
                           ? th.pushed_degc + (temp[k] - th.pushed_degc) * static_cast<double>(m) /
                                                  static_cast<double>(missing + 1)
                           : substitute(k, tm);
      rates_[k].push(v);
      push_lags(k, v);
    }
    rate[k] = rates_[k].push(temp[k]);
    push_lags(k, temp[k]);
    th.pushed_degc = temp[k];
    if (good[k]) {
      th.seen_good = true;
      th.good_degc = raw[k];
      th.good_time_s = t;
      th.good_rate = rate[k];
    }
  }
  started_ = true;
  previous_time_s_ = t;
  const bool refilling = refill_ > 0;
  if (refilling) --refill_;

  double drift = 0;
  if (any_out || refilling) {
    drift = degraded(t, flags);
  } else {
    for (std::size_t c = 0; c < columns_.size(); ++c)
      features_[c] = columns_[c].value(temp, rate, t);
    for (const Lag& lag : lags_) features_[lag.column] = lag.value;
    // While the rate window fills, novelty leaves the rates out (guard.hpp, "Warm-up").
    bool warming = false;
    for (std::size_t k = 0; k < nt_; ++k) warming |= thermometers_[k].read && !rates_[k].settled();
    last_ = model_.predict(features_, work_, warming);
    drift = last_.drift_dph;
    if (any_bridged) flags |= fault::bridged;
    if (guarded_) {
      // Substituted temperatures say nothing about novelty: the weight waits for real ones.
      if (!any_bridged)
        weight_ = filter_.update(t, last_.target_weight, model_.guard.settings.recover_s);
      drift = model_.guarded_dph(drift, weight_);
    }
    if (std::isfinite(drift)) {
      has_good_drift_ = true;
      good_drift_dph_ = drift;
      good_drift_time_s_ = t;
    } else {
      drift = degraded(t, flags);
    }
  }
  last_drift_dph_ = drift;
  return finish(s, drift, flags);
}

}  // namespace fogdrift
