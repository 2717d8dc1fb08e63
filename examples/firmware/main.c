/* The compensator on a microcontroller: a recording in, the compensated gyro out, sample by
 * sample, as a unit's main loop runs it (fogdrift docs/firmware.md).
 *
 *   main RECORDING.csv OUT.csv
 *
 * RECORDING.csv is a fogdrift recording (time_s, gyro_dph, temp_fog_degc, temp_acc1_degc,
 * temp_acc2_degc first, a header line); the files are the host's, reached by semihosting.
 * OUT.csv gets drift_dph, gyro_comp_dph and fault_flags for every sample. Standard output gets
 * what one update costs here: SysTick ticks, the deepest stack it used and the state's size.
 *
 * The header is the one `fogdrift export-c MODEL.json -o model.h --prefix unit
 * --stream-rate-hz HZ [--precision float]` writes; build with -DMODEL_HEADER='"model.h"'. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef MODEL_HEADER
#define MODEL_HEADER "model.h"
#endif
#include MODEL_HEADER

/* SysTick, the Cortex-M core timer: counts down from its reload value at the core clock. */
#define SYST_CSR (*(volatile uint32_t*)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t*)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t*)0xE000E018u)

static unit_state state; /* all the compensator's memory: no heap */

/* One update, not inlined, so that its stack and its time can be measured around the call. */
static __attribute__((noinline)) unit_real update(double time_s, unit_real gyro_dph,
                                                  unit_real fog, unit_real acc1, unit_real acc2,
                                                  unit_real* comp_dph) {
  const unit_real drift = unit_update(&state, time_s, fog, acc1, acc2);
  *comp_dph = unit_compensated_dph(&state, gyro_dph);
  return drift;
}

/* The first five comma-separated fields of a line as numbers; 0 when the line has fewer. */
static int parse(const char* line, double v[5]) {
  int k;
  char* end;
  for (k = 0; k < 5; ++k) {
    v[k] = strtod(line, &end);
    if (end == line) return 0;
    line = end;
    if (k < 4) {
      if (*line != ',') return 0;
      ++line;
    }
  }
  return 1;
}

/* SysTick ticks that 2,000,000 instructions take (a loop of subs and bne, two instructions an
 * iteration): under QEMU's -icount every instruction takes the same time, so ticks turn into
 * instructions; on a unit, ticks are core cycles. */
static unsigned long ticks_per_2m_instructions(void) {
  uint32_t t0, t1, n = 1000000u;
  t0 = SYST_CVR;
  __asm volatile("1: subs %0, %0, #1\n\tbne 1b" : "+r"(n) : : "cc");
  t1 = SYST_CVR;
  return (t0 - t1) & 0xFFFFFFu;
}

#define STACK_PROBE_BYTES 8192u
#define PAINT 0xA5A5A5A5u

int main(int argc, char** argv) {
  static char line[4096];
  FILE *in, *out;
  unsigned long n = 0, ticks = 0, ticks_max = 0, stack_max = 0;
  if (argc != 3) {
    fprintf(stderr, "usage: main RECORDING.csv OUT.csv\n");
    return 2;
  }
  in = fopen(argv[1], "r");
  out = fopen(argv[2], "w");
  if (!in || !out) {
    fprintf(stderr, "cannot open %s or %s\n", argv[1], argv[2]);
    return 1;
  }
  if (!fgets(line, sizeof line, in)) return 1; /* the header */
  fprintf(out, "drift_dph,gyro_comp_dph,fault_flags\n");
  unit_reset(&state);
  SYST_RVR = 0xFFFFFFu;
  SYST_CVR = 0u;
  SYST_CSR = 5u; /* enabled, core clock, no interrupt */
  while (fgets(line, sizeof line, in)) {
    double v[5];
    unit_real drift, comp;
    uint32_t sp, t0, t1;
    volatile uint32_t *p, *lo; /* volatile: the paint loop must not become a call to memset */
    if (!parse(line, v)) continue;
    /* Paint the stack below this frame, update, and see how deep the paint was overwritten. */
    __asm volatile("mov %0, sp" : "=r"(sp));
    lo = (volatile uint32_t*)(sp - STACK_PROBE_BYTES);
    for (p = lo; p < (volatile uint32_t*)sp; ++p) *p = PAINT;
    t0 = SYST_CVR;
    drift = update(v[0], (unit_real)v[1], (unit_real)v[2], (unit_real)v[3], (unit_real)v[4], &comp);
    t1 = SYST_CVR;
    for (p = lo; p < (volatile uint32_t*)sp && *p == PAINT; ++p) {
    }
    if (sp - (uint32_t)p > stack_max) stack_max = sp - (uint32_t)p;
    {
      const unsigned long dt = (t0 - t1) & 0xFFFFFFu;
      ticks += dt;
      if (dt > ticks_max) ticks_max = dt;
    }
    ++n;
    fprintf(out, "%.17g,%.17g,%u\n", (double)drift, (double)comp, state.flags);
  }
  fclose(out);
  fclose(in);
  printf("updates %lu ticks_total %lu ticks_max %lu stack_bytes %lu state_bytes %lu "
         "ticks_per_2m_instructions %lu\n",
         n, ticks, ticks_max, stack_max, (unsigned long)sizeof state, ticks_per_2m_instructions());
  return 0;
}
