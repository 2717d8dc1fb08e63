/* fogdrift's per-sample streaming step in C99: the causal temperature rates, the fault policy, the
 * novelty guard's weight and the model, one sample at a time (fogdrift docs/compensation.md,
 * docs/firmware.md, docs/architecture.md "One streaming step").
 *
 * This is the one implementation of the step. fogdrift's library compiles it as C++ with
 * run-time tables for StreamingCompensator (src/stream/compensator.cpp), which `fogdrift stream`
 * and Python's StreamingCompensator run; every C header fogdrift writes (export-c
 * --stream-rate-hz) embeds it at build time after its state (step_state.h), with fds_ and FDS_
 * renamed to the header's prefix (unit_, UNIT_). It compiles and is tested on its own as C99
 * (tests/stream/step_test.c), against a model the includer defines first:
 *
 *   typedef double fds_real;          the arithmetic type (float for a 32-bit FPU)
 *   fds_state                          the state: step_state.h's, or the library's
 *   FDS_N_THERMOMETERS, FDS_N_FEATURES, FDS_RATE_WINDOW (W), FDS_BLOCK (samples a model sample
 *     averages), FDS_N_LAGS (0: no input dT@tau)
 *   fds_data_dt_s, fds_dt_s            the data's and the model's sample intervals, s (double)
 *   fds_reads[N_THERMOMETERS]          1 for a thermometer the model reads
 *   fds_rate_taps[W (W + 1) / 2]       the causal differentiator's taps for 1 ... W samples,
 *                                      those for k + 1 samples from k (k + 1) / 2, each set
 *                                      summing to 0
 *   fds_lag_thermometer, fds_lag_gain, fds_lag_tau_s [FDS_N_LAGS]    with lags
 *   FDS_TEMP_MIN_DEGC, FDS_TEMP_MAX_DEGC, FDS_READING_LIMIT, FDS_BRIDGE_S, FDS_HOLD_S,
 *     FDS_STUCK_S, FDS_STUCK_DELTA_DEGC, FDS_TEMP_JUMP_DEGC     the fault policy
 *   FDS_FAULT_TEMP_BAD, ... FDS_FAULT_OFF_INTERVAL              its flags' bits
 *   FDS_INTERVAL_TOLERANCE             a step within this share of an interval is one
 *   FDS_DRIFT_MEAN                     the drift where the model cannot run
 *   FDS_DRIFT_LIMIT                    the farthest a drift may lie from it
 *   FDS_FABS(x)                        fabs or fabsf
 *   FDS_DIFFERENCE_FROM_NEWEST         1: rates from the samples less the newest (float)
 *   fds_features_(temp, rate, t, lag_rate, f)   the model's inputs
 *   fds_predict_(f)                    the drift for one row of inputs
 *   FDS_GUARD, fds_novelty_of(f, warming), fds_target_weight(nu), fds_guard_recover_s
 *                                      the novelty guard, when the model has one
 * Each may read `s`, the state being stepped: the library's sizes and tables live there. Two
 * have defaults: FDS_LAGS, whether the lags' code is compiled (FDS_N_LAGS > 0), and
 * FDS_GUARDED, whether a compiled guard runs (1).
 *
 * It provides fds_reset(s), fds_update_(s, time_s, raw) and fds_compensated_(s, reading); the
 * header wraps the last two under the names of its thermometers and its target's unit
 * (PREFIX_update, PREFIX_compensated_dph). */
#include <math.h>

/* fogdrift: the header's code starts here. */
#ifndef FDS_LAGS
#define FDS_LAGS (FDS_N_LAGS > 0)
#endif
#if defined(FDS_GUARD) && FDS_GUARD && !defined(FDS_GUARDED)
#define FDS_GUARDED 1
#endif

static inline void fds_reset(fds_state* s) {
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
  s->good_drift = s->good_drift_time_s = s->last_drift = s->last_comp = 0.0;
  s->data_started = 0;
  s->sum_count = 0;
  s->data_time_s = 0.0;
  for (k = 0; k < FDS_N_THERMOMETERS; ++k) {
    s->sum[k] = 0.0;
    s->seen_good[k] = s->out[k] = s->tracking[k] = 0;
    s->good_degc[k] = s->good_time_s[k] = s->good_rate[k] = s->pushed_degc[k] = 0.0;
  }
#if FDS_LAGS
  for (k = 0; k < FDS_N_LAGS; ++k) s->lag_started[k] = 0;
#endif
}

#if FDS_LAGS
/* Thermometer k's sample into the lags that read it: s += g (T - s), the term (T - s) / tau.
 * A lag starts at its first sample, as at rest. */
static inline void fds_lags_(fds_state* s, int k, fds_real v) {
  int i;
  for (i = 0; i < FDS_N_LAGS; ++i) {
    if (fds_lag_thermometer[i] != k) continue;
    if (!s->lag_started[i]) {
      s->lag_degc[i] = v;
      s->lag_started[i] = 1;
    }
    s->lag_degc[i] += fds_lag_gain[i] * (v - s->lag_degc[i]);
    s->lag_rate[i] = (v - s->lag_degc[i]) / fds_lag_tau_s[i];
  }
}
#endif

/* Thermometer k's sample pushed into its rate filter; returns its rate, deg C/s. */
static inline fds_real fds_push_(fds_state* s, int k, fds_real v) {
  const fds_real* taps;
  const fds_real* x;
  fds_real sum = 0.0;
  long used, j;
  if (k == 0) {
    if (s->size == 2 * FDS_RATE_WINDOW) { /* keep the newest window - 1 at the front */
      int m;
      for (m = 0; m < FDS_N_THERMOMETERS; ++m)
        for (j = 0; j < FDS_RATE_WINDOW - 1; ++j)
          s->buffer[m][j] = s->buffer[m][FDS_RATE_WINDOW + 1 + j];
      s->size = FDS_RATE_WINDOW - 1;
    }
    ++s->size;
    ++s->count;
  }
  s->buffer[k][s->size - 1] = v;
  used = s->count < FDS_RATE_WINDOW ? s->count : FDS_RATE_WINDOW;
  taps = fds_rate_taps + (used - 1) * used / 2;
  x = s->buffer[k] + (s->size - used);
#if FDS_DIFFERENCE_FROM_NEWEST
  /* The taps sum to 0: in float, samples less the newest lose less to rounding. */
  for (j = 0; j < used; ++j) sum += taps[j] * (x[j] - x[used - 1]);
#else
  /* The taps sum to 0; in double, the samples as they are (fogdrift's own sums). */
  for (j = 0; j < used; ++j) sum += taps[j] * x[j];
#endif
  return sum / fds_dt_s;
}

/* Whether a step between samples is more than FDS_INTERVAL_TOLERANCE off the interval dt. */
static inline int fds_off_interval_(double step, double dt) {
  return step < (1 - FDS_INTERVAL_TOLERANCE) * dt || step > (1 + FDS_INTERVAL_TOLERANCE) * dt;
}

static inline fds_real fds_clamp_degc_(const fds_state* s, fds_real v) {
  (void)s; /* the library's policy lives in the state */
  return v < FDS_TEMP_MIN_DEGC ? FDS_TEMP_MIN_DEGC
                               : (v > FDS_TEMP_MAX_DEGC ? FDS_TEMP_MAX_DEGC : v);
}

/* A faulty thermometer's stand-in: its last good reading continued along its last rate. The
 * time since that reading is a difference of doubles; the rest is in fds_real (in float, double
 * arithmetic would be emulated in software on every sample's jump check). */
static inline fds_real fds_substitute_(const fds_state* s, int k, double time_s) {
  const fds_real elapsed_s = (fds_real)(time_s - s->good_time_s[k]);
  if (!s->seen_good[k]) return fds_clamp_degc_(s, 0.0);
  return fds_clamp_degc_(s, s->good_degc[k] + s->good_rate[k] * elapsed_s);
}

/* The drift where the model cannot be evaluated: held, then stopped. */
static inline fds_real fds_degraded_(fds_state* s, double time_s) {
  if (s->has_good_drift && time_s - s->good_drift_time_s <= FDS_HOLD_S) {
    s->flags |= FDS_FAULT_HELD;
    return s->good_drift;
  }
  s->flags |= FDS_FAULT_STOPPED;
  return FDS_DRIFT_MEAN;
}

/* One sample at the model's interval, fds_dt_s: the fault policy, the rates, the model. */
static inline fds_real fds_step_(fds_state* s, double time_s, const fds_real* raw) {
  fds_real* const temp = s->temp;
  fds_real* const rate = s->rate;
  fds_real* const f = s->f;
  int* const good = s->good;
  int* const stuck = s->stuck;
  int k, j, long_gap = 0, restart_rates, any_out = 0, any_bridged = 0, refilling;
  long missing = 0, m;
  double t = time_s;
  fds_real drift;
  for (k = 0; k < FDS_N_THERMOMETERS; ++k) {
    temp[k] = rate[k] = 0.0;
    good[k] = stuck[k] = 0;
  }
  if (!isfinite(t)) {
    s->flags |= FDS_FAULT_TIME_BAD;
    t = s->started ? s->previous_time_s + fds_dt_s : 0.0;
  }
  if (s->started) {
    const double step = t - s->previous_time_s;
    if (step < -FDS_BRIDGE_S) {
      fds_reset(s);
      s->flags |= FDS_FAULT_RESTART;
    } else if (step < 0.5 * fds_dt_s) {
      s->flags |= FDS_FAULT_OUT_OF_ORDER;
      return s->last_drift;
    } else if (step > 1.5 * fds_dt_s) {
      s->flags |= FDS_FAULT_GAP;
      if (step - fds_dt_s > FDS_BRIDGE_S)
        long_gap = 1;
      else
        missing = lround(step / fds_dt_s) - 1;
    } else if (fds_off_interval_(step, fds_dt_s)) {
      s->flags |= FDS_FAULT_OFF_INTERVAL;
    }
  }
  for (k = 0; k < FDS_N_THERMOMETERS; ++k) {
    if (!fds_reads[k]) continue;
    good[k] = isfinite(raw[k]) && raw[k] >= FDS_TEMP_MIN_DEGC && raw[k] <= FDS_TEMP_MAX_DEGC;
    if (!good[k]) {
      s->flags |= FDS_FAULT_TEMP_BAD;
      continue;
    }
    /* A jump, judged within FDS_BRIDGE_S of the last good reading: a longer step is real. */
    if (FDS_TEMP_JUMP_DEGC > 0 && s->seen_good[k] && t - s->good_time_s[k] <= FDS_BRIDGE_S &&
        FDS_FABS(raw[k] - fds_substitute_(s, k, t)) > FDS_TEMP_JUMP_DEGC) {
      good[k] = 0;
      s->flags |= FDS_FAULT_TEMP_JUMP;
    }
  }
  if (FDS_STUCK_S > 0) {
    for (k = 0; k < FDS_N_THERMOMETERS; ++k) {
      if (!good[k]) continue;
      if (!s->tracking[k] || raw[k] != s->unchanged_degc[k]) {
        s->tracking[k] = 1;
        s->unchanged_degc[k] = raw[k];
        s->unchanged_since_s[k] = t;
        for (j = 0; j < FDS_N_THERMOMETERS; ++j) s->others_degc[k][j] = good[j] ? raw[j] : NAN;
        continue;
      }
      for (j = 0; j < FDS_N_THERMOMETERS; ++j) {
        if (j == k || !good[j]) continue;
        if (isnan(s->others_degc[k][j])) s->others_degc[k][j] = raw[j];
        if (t - s->unchanged_since_s[k] >= FDS_STUCK_S &&
            FDS_FABS(raw[j] - s->others_degc[k][j]) >= FDS_STUCK_DELTA_DEGC)
          stuck[k] = 1;
      }
    }
    for (k = 0; k < FDS_N_THERMOMETERS; ++k)
      if (stuck[k]) {
        good[k] = 0;
        s->flags |= FDS_FAULT_TEMP_STUCK;
      }
  }
  restart_rates = long_gap;
  for (k = 0; k < FDS_N_THERMOMETERS; ++k) {
    if (!fds_reads[k]) continue;
    if (good[k]) {
      if (s->out[k]) restart_rates = 1;
      s->out[k] = 0;
      continue;
    }
    if (!s->seen_good[k] || t - s->good_time_s[k] > FDS_BRIDGE_S) s->out[k] = 1;
    if (s->out[k])
      any_out = 1;
    else
      any_bridged = 1;
  }
  if (restart_rates) {
    s->size = 0;
    s->count = 0;
    s->refill = s->has_good_drift ? FDS_RATE_WINDOW - 1 : 0;
    missing = 0;
#if FDS_LAGS
    for (k = 0; k < FDS_N_LAGS; ++k) s->lag_started[k] = 0;
#endif
  }
  for (k = 0; k < FDS_N_THERMOMETERS; ++k)
    temp[k] = !fds_reads[k] ? 0.0 : (good[k] ? raw[k] : fds_substitute_(s, k, t));
  for (m = 1; m <= missing; ++m) {
    const double tm = s->previous_time_s + (double)m * fds_dt_s;
    for (k = 0; k < FDS_N_THERMOMETERS; ++k) {
      const fds_real v = !fds_reads[k] ? 0.0
                         : good[k]     ? s->pushed_degc[k] + (temp[k] - s->pushed_degc[k]) *
                                                             (fds_real)m / (fds_real)(missing + 1)
                                   : fds_substitute_(s, k, tm);
      (void)fds_push_(s, k, v);
#if FDS_LAGS
      fds_lags_(s, k, v);
#endif
    }
  }
  for (k = 0; k < FDS_N_THERMOMETERS; ++k) {
    rate[k] = fds_push_(s, k, temp[k]);
#if FDS_LAGS
    fds_lags_(s, k, temp[k]);
#endif
    if (!fds_reads[k]) continue;
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
    drift = fds_degraded_(s, t);
  } else {
#if FDS_LAGS
    fds_features_(temp, rate, t, s->lag_rate, f);
#else
    fds_features_(temp, rate, t, 0, f);
#endif
    drift = fds_predict_(f);
    /* Beyond FDS_DRIFT_LIMIT of the mean, no drift the model learned: as a NaN
     * (docs/reliability.md). */
    if (!(FDS_FABS(drift - FDS_DRIFT_MEAN) <= FDS_DRIFT_LIMIT)) drift = (fds_real)NAN;
    if (any_bridged) s->flags |= FDS_FAULT_BRIDGED;
#if defined(FDS_GUARD) && FDS_GUARD
    if (FDS_GUARDED) {
      const fds_real v =
          fds_target_weight(s->novelty = fds_novelty_of(f, s->count < FDS_RATE_WINDOW));
      if (!any_bridged) {
        const fds_real dt =
            s->guard_started ? (t - s->last_time_s > 0.0 ? t - s->last_time_s : 0.0) : 0.0;
        const fds_real up = s->weight + (fds_guard_recover_s > 0 ? dt / fds_guard_recover_s : 0.0);
        s->weight = up < v ? up : v;
        s->last_time_s = t;
        s->guard_started = 1;
      }
      drift =
          s->weight == 0.0 ? FDS_DRIFT_MEAN : FDS_DRIFT_MEAN + s->weight * (drift - FDS_DRIFT_MEAN);
    }
#endif
    if (isfinite(drift)) {
      s->has_good_drift = 1;
      s->good_drift = drift;
      s->good_drift_time_s = t;
    } else {
      drift = fds_degraded_(s, t);
    }
  }
  (void)rate;
  s->last_drift = drift;
  return drift;
}

/* The drift for the newest sample (every fds_data_dt_s seconds since power-on), in the
 * target's unit, from the thermometers' readings: averaged over blocks of FDS_BLOCK samples, the
 * first sample a block of its own, and the model run once per block. */
static inline fds_real fds_update_(fds_state* s, double time_s, const fds_real* raw) {
  fds_real* const mean = s->mean;
  double t = time_s, c;
  int first, k;
  s->flags = 0;
  if (FDS_BLOCK == 1) return fds_step_(s, t, raw);
  if (!isfinite(t)) {
    s->flags |= FDS_FAULT_TIME_BAD;
    t = s->data_started ? s->data_time_s + fds_data_dt_s : 0.0;
  }
  if (s->data_started) {
    const double gap = t - s->data_time_s;
    if (gap < -FDS_BRIDGE_S) {
      fds_reset(s);
      s->flags |= FDS_FAULT_RESTART;
    } else if (gap < 0.5 * fds_data_dt_s) {
      s->flags |= FDS_FAULT_OUT_OF_ORDER;
      return s->last_drift;
    } else if (gap <= 1.5 * fds_data_dt_s && fds_off_interval_(gap, fds_data_dt_s)) {
      s->flags |= FDS_FAULT_OFF_INTERVAL;
    }
  }
  first = !s->data_started;
  s->data_started = 1;
  s->data_time_s = t;
  for (k = 0; k < FDS_N_THERMOMETERS; ++k) s->sum[k] += raw[k];
  ++s->sum_count;
  if (!first && s->sum_count < FDS_BLOCK) return s->last_drift;
  c = (double)s->sum_count;
  for (k = 0; k < FDS_N_THERMOMETERS; ++k) {
    mean[k] = (fds_real)(s->sum[k] / c);
    s->sum[k] = 0.0;
  }
  s->sum_count = 0;
  return fds_step_(s, t, mean);
}

/* The reading less the last update's drift; the last good value where the reading is not a
 * number or beyond FDS_READING_LIMIT (then FDS_FAULT_GYRO_BAD is set in s->flags). */
static inline fds_real fds_compensated_(fds_state* s, fds_real reading) {
  if (isfinite(reading) && FDS_FABS(reading) <= FDS_READING_LIMIT)
    return s->last_comp = reading - s->last_drift;
  s->flags |= FDS_FAULT_GYRO_BAD;
  return s->last_comp;
}
