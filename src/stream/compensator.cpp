// StreamingCompensator: the streaming step of src/stream/step.h, compiled here as C++ with the
// model's tables and sizes read from the state at run time (docs/architecture.md, "One streaming
// step"). The C headers export-c writes run the same code with them as constants.
#include "fogdrift/stream/compensator.hpp"

#include <math.h>  // NOLINT: step.h's own include, resolved before its namespace opens
#include <cmath>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "fogdrift/features/features.hpp"
#include "fogdrift/model/decimate.hpp"
#include "fogdrift/signal/differentiate.hpp"

namespace fogdrift {

FaultPolicy fault_policy_of(const CompensationModel& model) {
  const FeatureOptions& f = model.dataset.preprocessing;
  if (f.sample_interval_s == 0) return {};  // a model file that does not record it
  return fault_policy_for(f.sample_interval_s, static_cast<double>(signal::window_samples(
                                                   f.rates, f.sample_interval_s)) *
                                                   f.sample_interval_s);
}

namespace detail {
namespace step {

using fds_real = double;

// step_state.h's members under the same names, each array the memory of a StepCore, with the
// model's constants beside them: what a C header fixes at compile time, read here through `s`.
struct fds_state {
  // The model (step.h lists what a header defines).
  int n_thermometers = 0, n_lags = 0;
  long rate_window = 0, block = 0;
  double data_dt_s = 0, dt_s = 0;
  const int* reads = nullptr;
  const double* rate_taps = nullptr;
  const int* lag_thermometer = nullptr;
  const double* lag_gain = nullptr;
  const double* lag_tau_s = nullptr;
  FaultPolicy faults;
  double reading_limit = 0, drift_mean = 0, recover_s = 0;
  bool guarded = false;
  StepCore* core = nullptr;  // the model's features and prediction (features_of, predict_of)
  // The step's state.
  double** buffer = nullptr;
  long size = 0, count = 0;
  double weight = 1;
  int guard_started = 0;
  double last_time_s = 0, novelty = 0;
  unsigned flags = 0;
  int started = 0;
  double previous_time_s = 0;
  long refill = 0;
  int has_good_drift = 0;
  double good_drift = 0, last_drift = 0, last_comp = 0, good_drift_time_s = 0;
  int *seen_good = nullptr, *out = nullptr, *tracking = nullptr;
  double *good_degc = nullptr, *good_rate = nullptr, *pushed_degc = nullptr;
  double *good_time_s = nullptr, *unchanged_degc = nullptr, *unchanged_since_s = nullptr;
  double** others_degc = nullptr;
  int data_started = 0;
  long sum_count = 0;
  double data_time_s = 0;
  double* sum = nullptr;
  double *lag_degc = nullptr, *lag_rate = nullptr;
  int* lag_started = nullptr;
  double *mean = nullptr, *temp = nullptr, *rate = nullptr, *f = nullptr;
  int *good = nullptr, *stuck = nullptr;
};

void features_of(const fds_state* s, const double* temp, const double* rate, double t,
                 const double* lag_rate, double* f) noexcept;
double predict_of(fds_state* s, const double* f) noexcept;
double novelty_of(const fds_state* s) noexcept;
double target_weight_of(const fds_state* s) noexcept;

}  // namespace step

// What the step reads through `s` (step.h's list), as the run-time values above.
#define FDS_N_THERMOMETERS (s->n_thermometers)
#define FDS_RATE_WINDOW (s->rate_window)
#define FDS_BLOCK (s->block)
#define FDS_N_LAGS (s->n_lags)
#define FDS_LAGS 1
#define fds_data_dt_s (s->data_dt_s)
#define fds_dt_s (s->dt_s)
#define fds_reads (s->reads)
#define fds_rate_taps (s->rate_taps)
#define fds_lag_thermometer (s->lag_thermometer)
#define fds_lag_gain (s->lag_gain)
#define fds_lag_tau_s (s->lag_tau_s)
#define FDS_TEMP_MIN_DEGC (s->faults.temp_min_degc)
#define FDS_TEMP_MAX_DEGC (s->faults.temp_max_degc)
#define FDS_READING_LIMIT (s->reading_limit)
#define FDS_BRIDGE_S (s->faults.bridge_s)
#define FDS_HOLD_S (s->faults.hold_s)
#define FDS_STUCK_S (s->faults.stuck_s)
#define FDS_STUCK_DELTA_DEGC (s->faults.stuck_delta_degc)
#define FDS_TEMP_JUMP_DEGC (s->faults.temp_jump_degc)
#define FDS_FAULT_TEMP_BAD fault::temp_bad
#define FDS_FAULT_TEMP_JUMP fault::temp_jump
#define FDS_FAULT_TEMP_STUCK fault::temp_stuck
#define FDS_FAULT_GYRO_BAD fault::gyro_bad
#define FDS_FAULT_TIME_BAD fault::time_bad
#define FDS_FAULT_GAP fault::gap
#define FDS_FAULT_OUT_OF_ORDER fault::out_of_order
#define FDS_FAULT_BRIDGED fault::bridged
#define FDS_FAULT_HELD fault::held
#define FDS_FAULT_STOPPED fault::stopped
#define FDS_FAULT_RESTART fault::restart
#define FDS_FAULT_OFF_INTERVAL fault::off_interval
#define FDS_INTERVAL_TOLERANCE kIntervalTolerance
#define FDS_DRIFT_MEAN (s->drift_mean)
// CompensationModel::predict() has made a drift beyond its limit a NaN already (model.hpp).
#define FDS_DRIFT_LIMIT HUGE_VAL
#define FDS_FABS std::fabs
#define FDS_DIFFERENCE_FROM_NEWEST 0
#define fds_features_(temp, rate, t, lag_rate, f) features_of(s, temp, rate, t, lag_rate, f)
#define fds_predict_(f) predict_of(s, f)
#define FDS_GUARD 1
#define FDS_GUARDED (s->guarded)
#define fds_guard_recover_s (s->recover_s)
// predict_of() has computed ν and the target weight with the drift.
#define fds_novelty_of(f, warming) ((void)(f), (void)(warming), novelty_of(s))
#define fds_target_weight(nu) ((void)(nu), target_weight_of(s))

namespace step {
#include "stream/step.h"
}  // namespace step

#undef FDS_N_THERMOMETERS
#undef FDS_RATE_WINDOW
#undef FDS_BLOCK
#undef FDS_N_LAGS
#undef FDS_LAGS
#undef fds_data_dt_s
#undef fds_dt_s
#undef fds_reads
#undef fds_rate_taps
#undef fds_lag_thermometer
#undef fds_lag_gain
#undef fds_lag_tau_s
#undef FDS_TEMP_MIN_DEGC
#undef FDS_TEMP_MAX_DEGC
#undef FDS_READING_LIMIT
#undef FDS_BRIDGE_S
#undef FDS_HOLD_S
#undef FDS_STUCK_S
#undef FDS_STUCK_DELTA_DEGC
#undef FDS_TEMP_JUMP_DEGC
#undef FDS_FAULT_TEMP_BAD
#undef FDS_FAULT_TEMP_JUMP
#undef FDS_FAULT_TEMP_STUCK
#undef FDS_FAULT_GYRO_BAD
#undef FDS_FAULT_TIME_BAD
#undef FDS_FAULT_GAP
#undef FDS_FAULT_OUT_OF_ORDER
#undef FDS_FAULT_BRIDGED
#undef FDS_FAULT_HELD
#undef FDS_FAULT_STOPPED
#undef FDS_FAULT_RESTART
#undef FDS_FAULT_OFF_INTERVAL
#undef FDS_INTERVAL_TOLERANCE
#undef FDS_DRIFT_MEAN
#undef FDS_DRIFT_LIMIT
#undef FDS_FABS
#undef FDS_DIFFERENCE_FROM_NEWEST
#undef fds_features_
#undef fds_predict_
#undef FDS_GUARD
#undef FDS_GUARDED
#undef fds_guard_recover_s
#undef fds_novelty_of
#undef fds_target_weight

// The memory of one compensator's step and the model's tables, sized once.
struct StepCore {
  const CompensationModel& model;
  std::vector<FeatureColumn> columns;  // the model's inputs (FeatureSpec::columns())
  std::vector<double> work;            // the standardised inputs
  DriftPrediction last;                // at the last sample the model was evaluated on
  std::vector<int> reads, lag_thermometer;
  std::vector<double> taps, lag_gain, lag_tau_s;
  std::vector<double> buffer, others;  // rows of 2W and of one per thermometer
  std::vector<double*> buffer_rows, others_rows;
  std::vector<double> reals;  // every other array of reals, one after another
  std::vector<int> ints;
  std::vector<double> raw;  // one sample's readings
  step::fds_state state;

  StepCore(const CompensationModel& m, double dt_s, const StreamOptions& options);
  StepCore(const StepCore&) = delete;
  StepCore& operator=(const StepCore&) = delete;
};

StepCore::StepCore(const CompensationModel& m, double dt_s, const StreamOptions& options)
    : model(m), columns(m.dataset.features.columns()), work(m.inputs()) {
  step::fds_state& s = state;
  const FeatureOptions& pre = m.dataset.preprocessing;
  // The data's interval as the model's interval / k (decimate.hpp), and the model's.
  const std::size_t k = decimation_factor(pre, dt_s, "rate");
  s.block = static_cast<long>(k);
  s.data_dt_s = streaming_interval_s(pre, dt_s, k);
  s.dt_s = static_cast<double>(k) * s.data_dt_s;
  const signal::CausalDifferentiator rates(pre.rates, s.dt_s);
  validate(options.faults);
  s.faults = options.faults;
  const std::size_t nt = m.dataset.features.thermometer_count();
  const std::size_t w = rates.window();
  s.n_thermometers = static_cast<int>(nt);
  s.rate_window = static_cast<long>(w);
  for (std::size_t j = 1; j <= w; ++j)
    taps.insert(taps.end(), rates.taps(j).begin(), rates.taps(j).end());
  for (std::size_t t = 0; t < nt; ++t)
    reads.push_back(m.dataset.features.reads(static_cast<Thermometer>(t)) ? 1 : 0);
  for (const FeatureColumn& c : columns)
    if (c.lagged()) {
      lag_thermometer.push_back(static_cast<int>(c.a));
      lag_gain.push_back(LaggedRate(c.tau_s, s.dt_s).gain());
      lag_tau_s.push_back(c.tau_s);
    }
  const std::size_t nl = lag_gain.size();
  s.n_lags = static_cast<int>(nl);
  s.reads = reads.data();
  s.rate_taps = taps.data();
  s.lag_thermometer = lag_thermometer.data();
  s.lag_gain = lag_gain.data();
  s.lag_tau_s = lag_tau_s.data();
  // A gyro's readings beyond the limit are faults; another target's only when not a number
  // (stream_faults.hpp).
  s.reading_limit = target_of(m.dataset.target_column).kind == TargetKind::gyro
                        ? s.faults.gyro_limit_dph
                        : std::numeric_limits<double>::infinity();
  s.drift_mean = m.guarded_dph(0.0, 0.0);
  s.guarded = options.guarded && !m.guard.empty();
  s.recover_s = m.guard.settings.recover_s;
  s.core = this;

  buffer.assign(nt * 2 * w, 0.0);
  others.assign(nt * nt, 0.0);
  for (std::size_t t = 0; t < nt; ++t) {
    buffer_rows.push_back(buffer.data() + t * 2 * w);
    others_rows.push_back(others.data() + t * nt);
  }
  s.buffer = buffer_rows.data();
  s.others_degc = others_rows.data();
  // The arrays of reals: 10 per thermometer, 2 per lag, 1 per input.
  reals.assign(10 * nt + 2 * nl + columns.size(), 0.0);
  double* r = reals.data();
  const auto take = [&r](std::size_t n) { return std::exchange(r, r + n); };
  s.good_degc = take(nt), s.good_rate = take(nt), s.pushed_degc = take(nt);
  s.good_time_s = take(nt), s.unchanged_degc = take(nt), s.unchanged_since_s = take(nt);
  s.sum = take(nt), s.mean = take(nt), s.temp = take(nt), s.rate = take(nt);
  s.lag_degc = take(nl), s.lag_rate = take(nl);
  s.f = take(columns.size());
  raw.assign(nt, 0.0);
  ints.assign(5 * nt + nl, 0);
  int* i = ints.data();
  const auto take_int = [&i](std::size_t n) { return std::exchange(i, i + n); };
  s.seen_good = take_int(nt), s.out = take_int(nt), s.tracking = take_int(nt);
  s.good = take_int(nt), s.stuck = take_int(nt);
  s.lag_started = take_int(nl);
  step::fds_reset(&s);
}

namespace step {

// The model's inputs, as compute_features() forms them: each column's value, a lagged rate from
// its lag's term (the lags in the order of their columns).
void features_of(const fds_state* s, const double* temp, const double* rate, double t,
                 const double* lag_rate, double* f) noexcept {
  const std::vector<FeatureColumn>& columns = s->core->columns;
  const auto n = static_cast<std::size_t>(s->n_thermometers);
  const std::span<const double> temps(temp, n), rates(rate, n);
  std::size_t lag = 0;
  for (std::size_t c = 0; c < columns.size(); ++c)
    f[c] = columns[c].lagged() ? lag_rate[lag++] : columns[c].value(temps, rates, t);
}

// The drift, with ν and the guard's target weight kept for the step's guard: while the rate
// window fills, novelty leaves the rates out (guard.hpp, "Warm-up").
double predict_of(fds_state* s, const double* f) noexcept {
  StepCore& core = *s->core;
  const bool warming = s->count < s->rate_window;
  core.last =
      core.model.predict(std::span<const double>(f, core.columns.size()), core.work, warming);
  return core.last.drift_dph;
}

double novelty_of(const fds_state* s) noexcept {
  return s->core->last.novelty;
}
double target_weight_of(const fds_state* s) noexcept {
  return s->core->last.target_weight;
}

}  // namespace step
}  // namespace detail

StreamingCompensator::StreamingCompensator(const CompensationModel& model, double dt_s,
                                           const StreamOptions& options)
    : core_(std::make_unique<detail::StepCore>(model, dt_s, options)) {}

StreamingCompensator::~StreamingCompensator() = default;
StreamingCompensator::StreamingCompensator(StreamingCompensator&&) noexcept = default;
StreamingCompensator& StreamingCompensator::operator=(StreamingCompensator&&) noexcept = default;

void StreamingCompensator::reset() noexcept {
  detail::step::fds_reset(&core_->state);
}

double StreamingCompensator::novelty() const noexcept {
  return core_->last.novelty;
}
double StreamingCompensator::weight() const noexcept {
  return core_->state.weight;
}

StreamOutput StreamingCompensator::update(const Sample& x) noexcept {
  detail::StepCore& core = *core_;
  std::vector<double>& raw = core.raw;
  raw[0] = x.temp_fog_degc, raw[1] = x.temp_acc1_degc, raw[2] = x.temp_acc2_degc;
  // A further thermometer the sample does not hold is a reading that is not a number, a fault as
  // any other (stream_faults.hpp).
  for (std::size_t k = 3; k < raw.size(); ++k)
    raw[k] = k - 3 < x.further_degc.size() ? x.further_degc[k - 3]
                                           : std::numeric_limits<double>::quiet_NaN();
  StreamOutput out;
  out.drift_dph = detail::step::fds_update_(&core.state, x.time_s, raw.data());
  out.gyro_comp_dph = detail::step::fds_compensated_(&core.state, x.gyro_dph);
  out.flags = core.state.flags;
  return out;
}

}  // namespace fogdrift
