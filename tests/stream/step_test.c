/* The streaming step (src/stream/step.h) as C99 on its own, against a model small enough to
 * compute by hand: two thermometers, inputs T0, dT0/dt and T0 - T1, a linear drift, rates by a
 * three-sample central difference. Built twice (tests/CMakeLists.txt): in double with one
 * sample a block; with FDS_TEST_FLOAT, in float with two samples a block, a lagged rate and a
 * novelty guard the test drives. Every header fogdrift writes embeds this code, and the library
 * runs it (compensator.cpp); their agreement, sample by sample, is tested by compensator_test.cpp
 * and firmware_qemu. */
#include <math.h>
#include <stdio.h>

#ifdef FDS_TEST_FLOAT
typedef float fds_real;
#define FDS_FABS fabsf
#define FDS_DIFFERENCE_FROM_NEWEST 1
#define FDS_BLOCK 2
#define FDS_N_LAGS 1
#define FDS_GUARD 1
#define TOL 1e-5
#else
typedef double fds_real;
#define FDS_FABS fabs
#define FDS_DIFFERENCE_FROM_NEWEST 0
#define FDS_BLOCK 1
#define FDS_N_LAGS 0
#define TOL 1e-12
#endif

#define FDS_N_THERMOMETERS 2
#define FDS_N_FEATURES 3
#define FDS_RATE_WINDOW 3
static const double fds_data_dt_s = 1.0;
static const double fds_dt_s = 1.0 * FDS_BLOCK;
static const int fds_reads[FDS_N_THERMOMETERS] = {1, 1};
/* One sample: no rate; two: their difference; three: the central difference. */
static const fds_real fds_rate_taps[6] = {0.0, -1.0, 1.0, -0.5, 0.0, 0.5};
#if FDS_N_LAGS > 0
static const int fds_lag_thermometer[FDS_N_LAGS] = {1};
static const fds_real fds_lag_gain[FDS_N_LAGS] = {0.5};
static const fds_real fds_lag_tau_s[FDS_N_LAGS] = {4.0};
#endif
#define FDS_TEMP_MIN_DEGC (-60.0)
#define FDS_TEMP_MAX_DEGC (100.0)
#define FDS_READING_LIMIT (1000.0)
#define FDS_BRIDGE_S (5.0)
#define FDS_HOLD_S (20.0)
#define FDS_STUCK_S (0.0)
#define FDS_STUCK_DELTA_DEGC (0.5)
#define FDS_TEMP_JUMP_DEGC (0.0)
#define FDS_FAULT_TEMP_BAD 1u
#define FDS_FAULT_TEMP_JUMP 2u
#define FDS_FAULT_TEMP_STUCK 4u
#define FDS_FAULT_GYRO_BAD 8u
#define FDS_FAULT_TIME_BAD 16u
#define FDS_FAULT_GAP 32u
#define FDS_FAULT_OUT_OF_ORDER 64u
#define FDS_FAULT_BRIDGED 128u
#define FDS_FAULT_HELD 256u
#define FDS_FAULT_STOPPED 512u
#define FDS_FAULT_RESTART 1024u
#define FDS_FAULT_OFF_INTERVAL 2048u
#define FDS_INTERVAL_TOLERANCE (0.1)
#define FDS_DRIFT_MEAN ((fds_real)7.0)
#define FDS_DRIFT_LIMIT ((fds_real)1e6)

static void fds_features_(const fds_real temp[FDS_N_THERMOMETERS],
                          const fds_real rate[FDS_N_THERMOMETERS], double t,
                          const fds_real* lag_rate, fds_real f[FDS_N_FEATURES]) {
  (void)t;
  f[0] = temp[0];
  f[1] = rate[0];
  f[2] = temp[0] - temp[1];
#if FDS_N_LAGS > 0
  f[2] += lag_rate[0]; /* the lag of T1 takes the gradient's place: seen when T1 steps */
#else
  (void)lag_rate;
#endif
}

static fds_real model(fds_real t0, fds_real rate0, fds_real third) {
  return (fds_real)(1.0 + 2.0 * t0 + 100.0 * rate0 + 0.5 * third);
}

static fds_real fds_predict_(const fds_real f[FDS_N_FEATURES]) {
  return model(f[0], f[1], f[2]);
}

#ifdef FDS_TEST_FLOAT
/* The guard: novelty is what the test sets; weight 1 below 1, 0 from 2. */
static fds_real novelty_now = 0.0f;
static const fds_real fds_guard_recover_s = 10.0f;
static fds_real fds_novelty_of(const fds_real f[FDS_N_FEATURES], int warming) {
  (void)f;
  (void)warming;
  return novelty_now;
}
static fds_real fds_target_weight(fds_real nu) {
  return nu <= 1 ? 1.0f : (nu >= 2 ? 0.0f : 2.0f - nu);
}
#endif

/* The state first: the step reads it. */
#include "stream/step_state.h"

#include "stream/step.h"

static int failed = 0;
#define CHECK(what, condition)                                                  \
  do {                                                                          \
    if (!(condition)) {                                                         \
      fprintf(stderr, "%s:%d: %s: %s\n", __FILE__, __LINE__, what, #condition); \
      ++failed;                                                                 \
    }                                                                           \
  } while (0)
#define NEAR(a, b) (fabs((double)(a) - (double)(b)) <= TOL * (1.0 + fabs((double)(b))))

/* Feeds `n` samples of T0 = a + b t, T1 = c from time t0 on; returns the last drift. */
static fds_real feed(fds_state* s, double t0, int n, double a, double b, double c) {
  fds_real d = 0;
  int i;
  for (i = 0; i < n; ++i) {
    const double t = t0 + i;
    const fds_real raw[2] = {(fds_real)(a + b * t), (fds_real)c};
    d = fds_update_(s, t, raw);
  }
  return d;
}

#ifndef FDS_TEST_FLOAT
static void steady_and_ramp(void) {
  fds_state s;
  fds_real d;
  fds_reset(&s);
  /* At rest: no rate from the first sample on, the drift of the temperatures alone. */
  d = feed(&s, 0.0, 1, 20.0, 0.0, 18.0);
  CHECK("first sample", NEAR(d, model(20, 0, 2)) && s.flags == 0);
  d = feed(&s, 1.0, 5, 20.0, 0.0, 18.0);
  CHECK("at rest", NEAR(d, model(20, 0, 2)) && s.flags == 0);
  /* A ramp of 0.1 degC/s from t = 10: the central difference is exact once the window holds
   * three samples of it. */
  fds_reset(&s);
  d = feed(&s, 10.0, 6, 20.0 - 1.0, 0.1, 18.0);
  CHECK("ramp rate", NEAR(d, model(20.5, 0.1, 2.5)));
  CHECK("ramp flags", s.flags == 0);
  /* The reading less the drift; a reading that is not a number keeps the last good value. */
  CHECK("compensated", NEAR(fds_compensated_(&s, 50.0), 50.0 - d));
  CHECK("bad reading", NEAR(fds_compensated_(&s, NAN), 50.0 - d) && (s.flags & FDS_FAULT_GYRO_BAD));
  CHECK("beyond the limit", NEAR(fds_compensated_(&s, 5000.0), 50.0 - d));
}

static void faults(void) {
  fds_state s;
  fds_real d;
  fds_real raw[2] = {20.0, 18.0};
  int i;
  fds_reset(&s);
  (void)feed(&s, 0.0, 10, 20.0, 0.1, 18.0); /* T0 = 20.9 at t = 9, rising 0.1 degC/s */
  /* A reading that is not a number is continued along its last rate, and flagged. */
  raw[0] = NAN;
  d = fds_update_(&s, 10.0, raw);
  CHECK("bridged flags", (s.flags & FDS_FAULT_TEMP_BAD) && (s.flags & FDS_FAULT_BRIDGED));
  CHECK("bridged along the rate", NEAR(d, model(21.0, 0.1, 3.0)));
  /* Time that does not advance is skipped: the last drift, flagged. */
  raw[0] = 21.1;
  CHECK("out of order", fds_update_(&s, 10.0, raw) == d && (s.flags & FDS_FAULT_OUT_OF_ORDER));
  /* A short gap is bridged by filling the samples between: the rate holds. */
  raw[0] = 21.3;
  d = fds_update_(&s, 13.0, raw);
  CHECK("gap flag", (s.flags & FDS_FAULT_GAP) && !(s.flags & FDS_FAULT_HELD));
  CHECK("across a gap", NEAR(d, model(21.3, 0.1, 3.3)));
  /* An outage longer than the bridge: the last good drift held, then the mean drift. */
  raw[0] = NAN;
  for (i = 14; i <= 16; ++i) d = fds_update_(&s, i, raw);
  CHECK("still bridged", !(s.flags & FDS_FAULT_HELD));
  for (i = 17; i <= 25; ++i) d = fds_update_(&s, i, raw);
  CHECK("held", (s.flags & FDS_FAULT_HELD) && isfinite(d));
  for (i = 26; i <= 40; ++i) d = fds_update_(&s, i, raw);
  CHECK("stopped", (s.flags & FDS_FAULT_STOPPED) && d == FDS_DRIFT_MEAN);
  /* The thermometer back: the rates start again, and the model waits until their window has
   * refilled (W - 1 samples), rather than run on a rate of one sample. */
  raw[0] = 25.0;
  for (i = 41; i <= 42; ++i) {
    d = fds_update_(&s, i, raw);
    CHECK("refilling", d == FDS_DRIFT_MEAN && (s.flags & FDS_FAULT_STOPPED));
  }
  d = fds_update_(&s, 43.0, raw);
  CHECK("refilled", s.flags == 0 && NEAR(d, model(25, 0, 7)));
  /* A clock that goes back further than the bridge starts again, as at power-on. */
  raw[0] = 20.0;
  d = fds_update_(&s, 1.0, raw);
  CHECK("restart", (s.flags & FDS_FAULT_RESTART) && NEAR(d, model(20, 0, 2)));
  /* A time that is not a number is taken as the next sample's. */
  d = fds_update_(&s, NAN, raw);
  CHECK("time not a number", (s.flags & FDS_FAULT_TIME_BAD) && NEAR(d, model(20, 0, 2)));
}
#else
static void blocks_lags_and_guard(void) {
  fds_state s;
  fds_real d, first;
  fds_real raw[2] = {20.0f, 18.0f};
  fds_reset(&s);
  /* The first sample is a block of its own; the next waits for its block's second sample. */
  first = fds_update_(&s, 0.0, raw);
  CHECK("first block", NEAR(first, model(20, 0, 2)));
  raw[0] = 22.0f;
  CHECK("mid-block", fds_update_(&s, 1.0, raw) == first);
  raw[0] = 24.0f;
  d = fds_update_(&s, 2.0, raw); /* the block's mean, 23, two seconds after 20 */
  CHECK("block mean", NEAR(d, model(23, 1.5, 5)));
  /* A step in T1 moves its lag: (T1 - lag) / tau, the lag halfway after one model sample. */
  fds_reset(&s);
  (void)feed(&s, 0.0, 5, 20.0, 0.0, 18.0);
  raw[0] = 20.0f;
  raw[1] = 26.0f;
  (void)fds_update_(&s, 5.0, raw);
  d = fds_update_(&s, 6.0, raw);
  CHECK("lagged rate", NEAR(d, model(20, 0, 20 - 26 + (26 - 22) / 4.0)));
  /* The guard: a novel sample takes the correction to the mean drift at once; it comes back
   * over guard_recover_s. */
  fds_reset(&s);
  (void)feed(&s, 0.0, 7, 20.0, 0.0, 18.0);
  novelty_now = 3.0f;
  d = feed(&s, 7.0, 2, 20.0, 0.0, 18.0);
  CHECK("guarded", d == FDS_DRIFT_MEAN && s.weight == 0 && s.novelty == 3.0f);
  novelty_now = 0.0f;
  d = feed(&s, 9.0, 2, 20.0, 0.0, 18.0); /* 2 s of 10: a fifth of the way back */
  CHECK("recovering",
        NEAR(d, FDS_DRIFT_MEAN + 0.2 * (model(20, 0, 2) - FDS_DRIFT_MEAN)) && NEAR(s.weight, 0.2));
}
#endif

int main(void) {
#ifndef FDS_TEST_FLOAT
  steady_and_ramp();
  faults();
#else
  blocks_lags_and_guard();
#endif
  if (failed) fprintf(stderr, "%d checks failed\n", failed);
  return failed != 0;
}
