// The causal streaming compensator of the C header (c_parts.hpp, compensator.hpp).
#include "c_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "c_text.hpp"
#include "fogdrift/decimate.hpp"
#include "fogdrift/error.hpp"
#include "fogdrift/signal/differentiate.hpp"

namespace fogdrift::detail {
namespace {

/// The temperature arguments a model reads, e.g. "temp_fog_degc" (docs/logs.md, "Fewer
/// thermometers").
std::string thermometers_read(const CompensationModel& model) {
  const FeatureSpec& spec = model.dataset.features;
  const std::vector<std::string> columns = spec.thermometer_columns();
  std::vector<std::string> read;
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (spec.reads(static_cast<Thermometer>(k))) read.push_back(columns[k]);
  return read.empty() ? std::string("none") : fmt::format("{}", fmt::join(read, ", "));
}

// The header's streaming part: the causal differentiator (taps of every start-up window length,
// a buffer of 2W samples per thermometer), the features in compute_features()'s order and the
// fault policy (stream_faults.hpp), the same steps in the same order as
// StreamingCompensator::update().
constexpr std::string_view kStreamingC =
    R"(/* Streaming: samples every @DATA_DT@ s in, the features computed causally every @DT@ s.
 *   @P@_state s; @P@_reset(&s);   at power-on
 *   drift_@UNIT@ = @P@_update(&s, time_s, @TEMP_ARGS@);
 *   @READING_COMP@ = @P@_compensated_@UNIT@(&s, @READING@);
 *   s.flags: what was wrong with the sample (@U@_FAULT_* bits, 0 for a good sample).
 * Temperature rates: causal Savitzky-Golay derivative over the last @W@ samples (during the
 * first @W@, the samples before power-on taken equal to the first, as if the unit had been at
 * rest); the taps for k + 1 samples start at k(k + 1)/2 in the table.
 * Thermometers this model reads: @READS@; pass anything for the others.@NOTE@
 * Sensor faults (fogdrift docs/compensation.md, "Sensor faults"): a thermometer reading that is
 * not a number, outside [@U@_TEMP_MIN_DEGC, @U@_TEMP_MAX_DEGC], more than @U@_TEMP_JUMP_DEGC
 * from its last good reading continued along its rate, or stuck is continued along its
 * last rate for up to @U@_BRIDGE_S, and so is a time gap; beyond that the drift is held at its
 * last good value until the rate window has refilled, and after @U@_HOLD_S the correction stops
 * (the mean drift). A sample whose time does not advance is skipped; time going back by more
 * than @U@_BRIDGE_S starts again as at power-on. The drift is always a finite number. */
#define @U@_RATE_WINDOW @W@
@GUARD_DEFINE@#ifndef @U@_TEMP_MIN_DEGC
#define @U@_TEMP_MIN_DEGC (@TEMP_MIN@)
#endif
#ifndef @U@_TEMP_MAX_DEGC
#define @U@_TEMP_MAX_DEGC (@TEMP_MAX@)
#endif
#ifndef @U@_@LIMIT@
#define @U@_@LIMIT@ (@GYRO_LIMIT@)
#endif
#ifndef @U@_BRIDGE_S
#define @U@_BRIDGE_S (@BRIDGE@)
#endif
#ifndef @U@_HOLD_S
#define @U@_HOLD_S (@HOLD@)
#endif
#ifndef @U@_STUCK_S
#define @U@_STUCK_S (@STUCK@) /* 0: no stuck check */
#endif
#ifndef @U@_STUCK_DELTA_DEGC
#define @U@_STUCK_DELTA_DEGC (@STUCK_DELTA@)
#endif
#ifndef @U@_TEMP_JUMP_DEGC
#define @U@_TEMP_JUMP_DEGC (@TEMP_JUMP@) /* 0: no jump check */
#endif
@FLAGS@
#define @U@_BLOCK @BLOCK@ /* samples per model sample */
static const double @P@_data_dt_s = @DATA_DT@;
static const double @P@_dt_s = @DT@;
#define @U@_N_THERMOMETERS @NT@ /* @THERMOMETERS@ */
static const int @P@_reads[@U@_N_THERMOMETERS] = {@READ_FLAGS@};
static const @REAL@ @P@_rate_taps[@NTAPS@] = {@TAPS@};
@LAG_TABLES@
typedef struct {
  @REAL@ buffer[@U@_N_THERMOMETERS][2 * @U@_RATE_WINDOW]; /* newest at size - 1 */
  long size;                             /* samples in the buffer */
  long count;                            /* samples since the rate filters started */
  @REAL@ weight;                         /* the guard's weight w, 1 at power-on */
  int guard_started;                     /* the guard has seen a sample */
  double last_time_s;                    /* time of the guard's previous sample */
  @REAL@ novelty;                        /* nu of the last evaluated sample (0 without a guard) */
  unsigned flags;                        /* @U@_FAULT_* bits of the last sample */
  /* the fault policy's state */
  int started;
  double previous_time_s;
  long refill;
  int has_good_drift;
  @REAL@ good_drift_@UNIT@, last_drift_@UNIT@, last_comp_@UNIT@;
  double good_drift_time_s;
  int seen_good[@U@_N_THERMOMETERS], out[@U@_N_THERMOMETERS], tracking[@U@_N_THERMOMETERS];
  @REAL@ good_degc[@U@_N_THERMOMETERS], good_rate[@U@_N_THERMOMETERS];
  @REAL@ pushed_degc[@U@_N_THERMOMETERS];
  double good_time_s[@U@_N_THERMOMETERS];
  @REAL@ unchanged_degc[@U@_N_THERMOMETERS], others_degc[@U@_N_THERMOMETERS][@U@_N_THERMOMETERS];
  double unchanged_since_s[@U@_N_THERMOMETERS];
  /* the block being averaged (@U@_BLOCK > 1) */
  int data_started;
  long sum_count;
  double data_time_s;          /* time of the last data sample */
  double sum[@U@_N_THERMOMETERS]; /* sums of a block in double: up to 2000 samples */
@LAG_STATE@} @P@_state;

static inline void @P@_reset(@P@_state* s) {
  int k;
  s->size = 0;
  s->count = 0;
  s->weight = 1.0;
  s->guard_started = 0;
  s->last_time_s = 0.0;
  s->novelty = 0.0;
  s->flags = 0;
  s->started = 0;
  s->previous_time_s = 0.0;
  s->refill = 0;
  s->has_good_drift = 0;
  s->good_drift_@UNIT@ = s->good_drift_time_s = s->last_drift_@UNIT@ = s->last_comp_@UNIT@ = 0.0;
  s->data_started = 0;
  s->sum_count = 0;
  s->data_time_s = 0.0;
  for (k = 0; k < @U@_N_THERMOMETERS; ++k) {
    s->sum[k] = 0.0;
    s->seen_good[k] = s->out[k] = s->tracking[k] = 0;
    s->good_degc[k] = s->good_time_s[k] = s->good_rate[k] = s->pushed_degc[k] = 0.0;
  }
@LAG_RESET@}
@LAG_FUNCTION@
/* Thermometer k's sample pushed into its rate filter; returns its rate, deg C/s. */
static inline @REAL@ @P@_push_(@P@_state* s, int k, @REAL@ v) {
  const @REAL@* taps;
  const @REAL@* x;
  @REAL@ sum = 0.0;
  long used, j;
  if (k == 0) {
    if (s->size == 2 * @U@_RATE_WINDOW) { /* keep the newest window - 1 at the front */
      int m;
      for (m = 0; m < @U@_N_THERMOMETERS; ++m)
        for (j = 0; j < @U@_RATE_WINDOW - 1; ++j)
          s->buffer[m][j] = s->buffer[m][@U@_RATE_WINDOW + 1 + j];
      s->size = @U@_RATE_WINDOW - 1;
    }
    ++s->size;
    ++s->count;
  }
  s->buffer[k][s->size - 1] = v;
  used = s->count < @U@_RATE_WINDOW ? s->count : @U@_RATE_WINDOW;
  taps = @P@_rate_taps + (used - 1) * used / 2;
  x = s->buffer[k] + (s->size - used);
  /* The taps sum to 0: @RATE_REF_NOTE@ */
  for (j = 0; j < used; ++j) sum += taps[j] * (x[j] - @RATE_REF@);
  return sum / @P@_dt_s;
}

static inline @REAL@ @P@_clamp_degc_(@REAL@ v) {
  return v < @U@_TEMP_MIN_DEGC ? @U@_TEMP_MIN_DEGC : (v > @U@_TEMP_MAX_DEGC ? @U@_TEMP_MAX_DEGC : v);
}

/* A faulty thermometer's stand-in: its last good reading continued along its last rate. The
 * time since that reading is a difference of doubles; the rest is in @REAL@ (in float, double
 * arithmetic would be emulated in software on every sample's jump check). */
static inline @REAL@ @P@_substitute_(const @P@_state* s, int k, double time_s) {
  const @REAL@ elapsed_s = (@REAL@)(time_s - s->good_time_s[k]);
  if (!s->seen_good[k]) return @P@_clamp_degc_(0.0);
  return @P@_clamp_degc_(s->good_degc[k] + s->good_rate[k] * elapsed_s);
}

/* The drift where the model cannot be evaluated: held, then stopped. */
static inline @REAL@ @P@_degraded_(@P@_state* s, double time_s) {
  if (s->has_good_drift && time_s - s->good_drift_time_s <= @U@_HOLD_S) {
    s->flags |= @U@_FAULT_HELD;
    return s->good_drift_@UNIT@;
  }
  s->flags |= @U@_FAULT_STOPPED;
  return @P@_drift_mean_@UNIT@;
}

/* One sample at the model's interval, @P@_dt_s: the fault policy, the rates, the model. */
static inline @REAL@ @P@_step_(@P@_state* s, double time_s,
                                const @REAL@ raw[@U@_N_THERMOMETERS]) {
  @REAL@ temp[@U@_N_THERMOMETERS] = {0.0}, rate[@U@_N_THERMOMETERS] = {0.0}, f[@U@_N_FEATURES];
  int good[@U@_N_THERMOMETERS] = {0}, stuck[@U@_N_THERMOMETERS] = {0};
  int k, j, long_gap = 0, restart_rates, any_out = 0, any_bridged = 0, refilling;
  long missing = 0, m;
  double t = time_s;
  @REAL@ drift;
  if (!isfinite(t)) {
    s->flags |= @U@_FAULT_TIME_BAD;
    t = s->started ? s->previous_time_s + @P@_dt_s : 0.0;
  }
  if (s->started) {
    const double step = t - s->previous_time_s;
    if (step < -@U@_BRIDGE_S) {
      @P@_reset(s);
      s->flags |= @U@_FAULT_RESTART;
    } else if (step < 0.5 * @P@_dt_s) {
      s->flags |= @U@_FAULT_OUT_OF_ORDER;
      return s->last_drift_@UNIT@;
    } else if (step > 1.5 * @P@_dt_s) {
      s->flags |= @U@_FAULT_GAP;
      if (step - @P@_dt_s > @U@_BRIDGE_S)
        long_gap = 1;
      else
        missing = lround(step / @P@_dt_s) - 1;
    }
  }
  for (k = 0; k < @U@_N_THERMOMETERS; ++k) {
    if (!@P@_reads[k]) continue;
    good[k] = isfinite(raw[k]) && raw[k] >= @U@_TEMP_MIN_DEGC && raw[k] <= @U@_TEMP_MAX_DEGC;
    if (!good[k]) {
      s->flags |= @U@_FAULT_TEMP_BAD;
      continue;
    }
    /* A jump, judged within @U@_BRIDGE_S of the last good reading: a longer step is real. */
    if (@U@_TEMP_JUMP_DEGC > 0 && s->seen_good[k] && t - s->good_time_s[k] <= @U@_BRIDGE_S &&
        fabs@F@(raw[k] - @P@_substitute_(s, k, t)) > @U@_TEMP_JUMP_DEGC) {
      good[k] = 0;
      s->flags |= @U@_FAULT_TEMP_JUMP;
    }
  }
  if (@U@_STUCK_S > 0) {
    for (k = 0; k < @U@_N_THERMOMETERS; ++k) {
      if (!good[k]) continue;
      if (!s->tracking[k] || raw[k] != s->unchanged_degc[k]) {
        s->tracking[k] = 1;
        s->unchanged_degc[k] = raw[k];
        s->unchanged_since_s[k] = t;
        for (j = 0; j < @U@_N_THERMOMETERS; ++j) s->others_degc[k][j] = good[j] ? raw[j] : NAN;
        continue;
      }
      for (j = 0; j < @U@_N_THERMOMETERS; ++j) {
        if (j == k || !good[j]) continue;
        if (isnan(s->others_degc[k][j])) s->others_degc[k][j] = raw[j];
        if (t - s->unchanged_since_s[k] >= @U@_STUCK_S &&
            fabs@F@(raw[j] - s->others_degc[k][j]) >= @U@_STUCK_DELTA_DEGC)
          stuck[k] = 1;
      }
    }
    for (k = 0; k < @U@_N_THERMOMETERS; ++k)
      if (stuck[k]) {
        good[k] = 0;
        s->flags |= @U@_FAULT_TEMP_STUCK;
      }
  }
  restart_rates = long_gap;
  for (k = 0; k < @U@_N_THERMOMETERS; ++k) {
    if (!@P@_reads[k]) continue;
    if (good[k]) {
      if (s->out[k]) restart_rates = 1;
      s->out[k] = 0;
      continue;
    }
    if (!s->seen_good[k] || t - s->good_time_s[k] > @U@_BRIDGE_S) s->out[k] = 1;
    if (s->out[k])
      any_out = 1;
    else
      any_bridged = 1;
  }
  if (restart_rates) {
    s->size = 0;
    s->count = 0;
    s->refill = s->has_good_drift ? @U@_RATE_WINDOW - 1 : 0;
    missing = 0;
@LAG_RESTART@  }
  for (k = 0; k < @U@_N_THERMOMETERS; ++k)
    temp[k] = !@P@_reads[k] ? 0.0 : (good[k] ? raw[k] : @P@_substitute_(s, k, t));
  for (m = 1; m <= missing; ++m) {
    const double tm = s->previous_time_s + (double)m * @P@_dt_s;
    for (k = 0; k < @U@_N_THERMOMETERS; ++k) {
      const @REAL@ v = !@P@_reads[k] ? 0.0
                       : good[k] ? s->pushed_degc[k] + (temp[k] - s->pushed_degc[k]) * (@REAL@)m /
                                                           (@REAL@)(missing + 1)
                                 : @P@_substitute_(s, k, tm);
      (void)@P@_push_(s, k, v);
@LAG_PUSH_MISSING@    }
  }
  for (k = 0; k < @U@_N_THERMOMETERS; ++k) {
    rate[k] = @P@_push_(s, k, temp[k]);
@LAG_PUSH@    if (!@P@_reads[k]) continue;
    s->pushed_degc[k] = temp[k];
    if (good[k]) {
      s->seen_good[k] = 1;
      s->good_degc[k] = raw[k];
      s->good_time_s[k] = t;
      s->good_rate[k] = rate[k];
    }
  }
  s->started = 1;
  s->previous_time_s = t;
  refilling = s->refill > 0;
  if (refilling) --s->refill;
  if (any_out || refilling) {
    drift = @P@_degraded_(s, t);
  } else {
@FEATURES@    drift = @P@_predict_@UNIT@(f);
    if (any_bridged) s->flags |= @U@_FAULT_BRIDGED;
@GUARD@    if (isfinite(drift)) {
      s->has_good_drift = 1;
      s->good_drift_@UNIT@ = drift;
      s->good_drift_time_s = t;
    } else {
      drift = @P@_degraded_(s, t);
    }
  }
  (void)rate;
  s->last_drift_@UNIT@ = drift;
  return drift;
}

/* Predicted drift, @UNIT_TEXT@, for the newest sample (every @P@_data_dt_s seconds since power-on):
 * the thermometers averaged over blocks of @U@_BLOCK samples, the first sample a block of its
 * own, and the model run once per block (fogdrift docs/compensation.md, "Any sample rate"). */
static inline @REAL@ @P@_update(@P@_state* s, double time_s, @TEMP_PARAMS@) {
  const @REAL@ raw[@U@_N_THERMOMETERS] = {@TEMP_ARGS@};
  @REAL@ mean[@U@_N_THERMOMETERS];
  double t = time_s, c;
  int first, k;
  s->flags = 0;
  if (@U@_BLOCK == 1) return @P@_step_(s, t, raw);
  if (!isfinite(t)) {
    s->flags |= @U@_FAULT_TIME_BAD;
    t = s->data_started ? s->data_time_s + @P@_data_dt_s : 0.0;
  }
  if (s->data_started) {
    const double gap = t - s->data_time_s;
    if (gap < -@U@_BRIDGE_S) {
      @P@_reset(s);
      s->flags |= @U@_FAULT_RESTART;
    } else if (gap < 0.5 * @P@_data_dt_s) {
      s->flags |= @U@_FAULT_OUT_OF_ORDER;
      return s->last_drift_@UNIT@;
    }
  }
  first = !s->data_started;
  s->data_started = 1;
  s->data_time_s = t;
  for (k = 0; k < @U@_N_THERMOMETERS; ++k) s->sum[k] += raw[k];
  ++s->sum_count;
  if (!first && s->sum_count < @U@_BLOCK) return s->last_drift_@UNIT@;
  c = (double)s->sum_count;
  for (k = 0; k < @U@_N_THERMOMETERS; ++k) {
    mean[k] = (@REAL@)(s->sum[k] / c);
    s->sum[k] = 0.0;
  }
  s->sum_count = 0;
  return @P@_step_(s, t, mean);
}

/* @READING@ minus the last update's drift; the last good value where the @READING_WORD@ is not a
 * number or beyond @U@_@LIMIT@ (then @U@_FAULT_GYRO_BAD is set in s->flags). */
static inline @REAL@ @P@_compensated_@UNIT@(@P@_state* s, @REAL@ @READING@) {
  if (isfinite(@READING@) && fabs@F@(@READING@) <= @U@_@LIMIT@)
    return s->last_comp_@UNIT@ = @READING@ - s->last_drift_@UNIT@;
  s->flags |= @U@_FAULT_GYRO_BAD;
  return s->last_comp_@UNIT@;
}

)";

// The lags of the inputs dT@τ (features.hpp, LaggedRate), emitted only for a model that has them.
constexpr std::string_view kLagStateC =
    R"(  /* the lags of the inputs dT@tau: state, deg C; term, deg C/s; started since power-on */
  @REAL@ lag_degc[@U@_N_LAGS], lag_rate[@U@_N_LAGS];
  int lag_started[@U@_N_LAGS];
)";

constexpr std::string_view kLagFunctionC = R"(
/* Thermometer k's sample into the lags that read it: s += g (T - s), the term (T - s) / tau.
 * A lag starts at its first sample, as at rest. */
static inline void @P@_lags_(@P@_state* s, int k, @REAL@ v) {
  int i;
  for (i = 0; i < @U@_N_LAGS; ++i) {
    if (@P@_lag_thermometer[i] != k) continue;
    if (!s->lag_started[i]) {
      s->lag_degc[i] = v;
      s->lag_started[i] = 1;
    }
    s->lag_degc[i] += @P@_lag_gain[i] * (v - s->lag_degc[i]);
    s->lag_rate[i] = (v - s->lag_degc[i]) / @P@_lag_tau_s[i];
  }
}
)";

constexpr std::string_view kGuardC = R"(#if @U@_GUARD
    {
      const @REAL@ v =
          @P@_target_weight(s->novelty = @P@_novelty_of(f, s->count < @U@_RATE_WINDOW));
      if (!any_bridged) {
        const @REAL@ dt =
            s->guard_started ? (t - s->last_time_s > 0.0 ? t - s->last_time_s : 0.0) : 0.0;
        const @REAL@ up = s->weight + (@P@_guard_recover_s > 0 ? dt / @P@_guard_recover_s : 0.0);
        s->weight = up < v ? up : v;
        s->last_time_s = t;
        s->guard_started = 1;
      }
      drift = s->weight == 0.0 ? @P@_drift_mean_@UNIT@
                               : @P@_drift_mean_@UNIT@ + s->weight * (drift - @P@_drift_mean_@UNIT@);
    }
#endif
)";

}  // namespace

std::string c_streaming_part(const CompensationModel& model, const std::string& prefix,
                             const std::string& upper, double data_dt_s, const FaultPolicy& faults,
                             bool single) {
  if (!std::isfinite(data_dt_s)) throw OptionError("stream_dt_s", "must be a finite interval");
  validate(faults);
  const std::size_t block =
      decimation_factor(model.dataset.preprocessing, data_dt_s, "stream_dt_s");
  const double dt_s = static_cast<double>(block) * data_dt_s;  // the model's interval
  signal::CausalDifferentiator diff(model.dataset.preprocessing.rates, dt_s);
  const std::size_t w = diff.window();
  std::vector<double> taps;
  for (std::size_t k = 1; k <= w; ++k) {
    const auto& t = diff.taps(k);
    taps.insert(taps.end(), t.begin(), t.end());
  }
  std::string flags;
  for (std::size_t k = 0; k < fault::count; ++k) {
    std::string name(fault::names()[k]);
    for (char& c : name) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    flags += fmt::format("#define {}_FAULT_{} {}u\n", upper, name, 1u << k);
  }
  // Feature assignments: FeatureColumn::value() written out in C, a lagged rate (dT@τ) from its
  // lag's state (features.hpp, LaggedRate).
  std::string features;
  const std::vector<FeatureColumn> columns = model.dataset.features.columns();
  std::vector<double> lag_gain, lag_tau_s;
  std::vector<int> lag_thermometer;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    if (columns[c].lagged()) {
      features += fmt::format("    f[{}] = s->lag_rate[{}];\n", c, lag_gain.size());
      lag_gain.push_back(LaggedRate(columns[c].tau_s, dt_s).gain());
      lag_tau_s.push_back(columns[c].tau_s);
      lag_thermometer.push_back(static_cast<int>(columns[c].a));
      continue;
    }
    const auto a = static_cast<std::size_t>(columns[c].a);
    const auto b = static_cast<std::size_t>(columns[c].b);
    std::string value;
    switch (columns[c].term) {
      case FeatureTerm::temp:
        value = fmt::format("temp[{}]", a);
        break;
      case FeatureTerm::rate:
        value = fmt::format("rate[{}]", a);
        break;
      case FeatureTerm::gradient:
        value = fmt::format("temp[{}] - temp[{}]", a, b);
        break;
      case FeatureTerm::gradient_rate:
        value = fmt::format("rate[{}] - rate[{}]", a, b);
        break;
      case FeatureTerm::time:
        value = "t";
        break;
      case FeatureTerm::temp_rate_product:
        value = fmt::format("temp[{}] * rate[{}]", a, a);
        break;
      case FeatureTerm::lagged_rate:
        break;  // above
    }
    features += fmt::format("    f[{}] = {};\n", c, value);
  }
  // One argument per thermometer of the spec, the further ones after fog, acc1, acc2.
  const FeatureSpec& spec = model.dataset.features;
  const std::vector<std::string> temp_columns = spec.thermometer_columns();
  std::string read_flags, params, names;
  for (std::size_t k = 0; k < temp_columns.size(); ++k) {
    const auto th = static_cast<Thermometer>(k);
    const char* sep = k ? ", " : "";
    read_flags += fmt::format("{}{}", sep, spec.reads(th) ? 1 : 0);
    params += fmt::format("{}@REAL@ {}", sep, temp_columns[k]);
    names += fmt::format("{}{}", sep, spec.thermometer_name(th));
  }
  const std::string args = fmt::format("{}", fmt::join(temp_columns, ", "));
  const bool guarded = !model.guard.empty();
  const bool gyro = target_of(model.dataset.target_column).kind == TargetKind::gyro;
  return fill_template(
      std::string(kStreamingC),
      {{"@GUARD@", guarded ? std::string(kGuardC) : std::string()},
       {"@GUARD_DEFINE@", guarded ? fmt::format("#ifndef {0}_GUARD\n#define {0}_GUARD 1 /* 0: full "
                                                "correction always */\n#endif\n",
                                                upper)
                                  : std::string()},
       {"@NOTE@",
        model.dataset.preprocessing.rates.causality == signal::Causality::causal
            ? ""
            : "\n * NOTE: this model was trained with centred rates; streaming applies causal "
              "ones, which\n * lag. Train with --differentiator causal for firmware."},
       {"@FEATURES@", features},
       {"@LAG_STATE@", lag_gain.empty() ? "" : std::string(kLagStateC)},
       {"@LAG_RESET@",
        lag_gain.empty() ? "" : "  for (k = 0; k < @U@_N_LAGS; ++k) s->lag_started[k] = 0;\n"},
       {"@LAG_RESTART@",
        lag_gain.empty() ? "" : "    for (k = 0; k < @U@_N_LAGS; ++k) s->lag_started[k] = 0;\n"},
       {"@LAG_FUNCTION@", lag_gain.empty() ? "" : std::string(kLagFunctionC)},
       {"@LAG_PUSH_MISSING@", lag_gain.empty() ? "" : "      @P@_lags_(s, k, v);\n"},
       {"@LAG_PUSH@", lag_gain.empty() ? "" : "    @P@_lags_(s, k, temp[k]);\n"},
       {"@LAG_TABLES@",
        lag_gain.empty()
            ? std::string()
            : fmt::format("#define @U@_N_LAGS {} /* inputs dT@tau: rates through a lag */\n"
                          "static const int @P@_lag_thermometer[@U@_N_LAGS] = {{{}}};\n"
                          "static const @REAL@ @P@_lag_gain[@U@_N_LAGS] = {{{}}};\n"
                          "static const @REAL@ @P@_lag_tau_s[@U@_N_LAGS] = {{{}}};\n",
                          lag_gain.size(), fmt::join(lag_thermometer, ", "), c_array(lag_gain),
                          c_array(lag_tau_s))},
       {"@FLAGS@", flags},
       {"@READS@", thermometers_read(model)},
       {"@READ_FLAGS@", read_flags},
       {"@NT@", std::to_string(spec.thermometer_count())},
       {"@THERMOMETERS@", names},
       {"@TEMP_PARAMS@", params},
       {"@TEMP_ARGS@", args},
       {"@TAPS@", c_array(taps)},
       {"@NTAPS@", std::to_string(taps.size())},
       {"@TEMP_MIN@", c_number(faults.temp_min_degc)},
       {"@TEMP_MAX@", c_number(faults.temp_max_degc)},
       // A gyro's readings beyond the limit are faults; another target's only when not a number
       // (stream_faults.hpp), unless the firmware defines a limit of its own.
       {"@GYRO_LIMIT@", gyro ? c_number(faults.gyro_limit_dph) : std::string("HUGE_VAL")},
       {"@BRIDGE@", c_number(faults.bridge_s)},
       {"@HOLD@", c_number(faults.hold_s)},
       {"@STUCK@", c_number(faults.stuck_s)},
       {"@STUCK_DELTA@", c_number(faults.stuck_delta_degc)},
       {"@TEMP_JUMP@", c_number(faults.temp_jump_degc)},
       // In float, differences from the newest sample keep the rate's rounding that of the change
       // in temperature over the window, not of the temperature itself.
       {"@RATE_REF@", single ? "x[used - 1]" : "0.0"},
       {"@RATE_REF_NOTE@", single ? "in float, samples less the newest lose less to rounding."
                                  : "in double, the samples as they are (fogdrift's own sums)."},
       {"@DATA_DT@", c_number(data_dt_s)},
       {"@BLOCK@", std::to_string(block)},
       {"@DT@", c_number(dt_s)},
       {"@W@", std::to_string(w)},
       // Last: the values above may contain the prefix's own placeholders.
       {"@P@", prefix},
       {"@U@", upper}});
}

}  // namespace fogdrift::detail
