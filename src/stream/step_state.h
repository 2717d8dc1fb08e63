/* The state of fogdrift's per-sample step (step.h) as firmware holds it: every size fixed at
 * compile time by the model's constants, nothing allocated (fogdrift docs/firmware.md).
 *
 * Every C header fogdrift writes embeds this struct before the step's code, under the header's
 * prefix. fogdrift's own library sizes the same members at run time instead
 * (src/stream/compensator.cpp): the step's code reads them by these names in both. */

/* fogdrift: the header's code starts here. */
typedef struct {
  fds_real buffer[FDS_N_THERMOMETERS][2 * FDS_RATE_WINDOW]; /* newest at size - 1 */
  long size;                                                /* samples in the buffer */
  long count;         /* samples since the rate filters started */
  fds_real weight;    /* the guard's weight w, 1 at power-on */
  int guard_started;  /* the guard has seen a sample */
  double last_time_s; /* time of the guard's previous sample */
  fds_real novelty;   /* nu of the last evaluated sample (0 without a guard) */
  unsigned flags;     /* FDS_FAULT_* bits of the last sample */
  /* the fault policy's state */
  int started;
  double previous_time_s;
  long refill;
  int has_good_drift;
  fds_real good_drift, last_drift, last_comp;
  double good_drift_time_s;
  int seen_good[FDS_N_THERMOMETERS], out[FDS_N_THERMOMETERS], tracking[FDS_N_THERMOMETERS];
  fds_real good_degc[FDS_N_THERMOMETERS], good_rate[FDS_N_THERMOMETERS];
  fds_real pushed_degc[FDS_N_THERMOMETERS];
  double good_time_s[FDS_N_THERMOMETERS];
  fds_real unchanged_degc[FDS_N_THERMOMETERS], others_degc[FDS_N_THERMOMETERS][FDS_N_THERMOMETERS];
  double unchanged_since_s[FDS_N_THERMOMETERS];
  /* the block being averaged (FDS_BLOCK > 1) */
  int data_started;
  long sum_count;
  double data_time_s;             /* time of the last data sample */
  double sum[FDS_N_THERMOMETERS]; /* sums of a block in double: up to 2000 samples */
#if FDS_N_LAGS > 0
  /* the lags of the inputs dT@tau: state, deg C; term, deg C/s; started since power-on */
  fds_real lag_degc[FDS_N_LAGS], lag_rate[FDS_N_LAGS];
  int lag_started[FDS_N_LAGS];
#endif
  /* one step's working values: the block's mean, the thermometers' verdicts, the temperatures
   * and rates the model reads, its inputs */
  fds_real mean[FDS_N_THERMOMETERS], temp[FDS_N_THERMOMETERS], rate[FDS_N_THERMOMETERS];
  int good[FDS_N_THERMOMETERS], stuck[FDS_N_THERMOMETERS];
  fds_real f[FDS_N_FEATURES];
} fds_state;
