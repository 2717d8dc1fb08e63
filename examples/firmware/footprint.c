/* The compensator alone, for `arm-none-eabi-size`: the code and tables a unit's flash holds and
 * the state its RAM holds (fogdrift docs/firmware.md, "What it costs"). */
#include MODEL_HEADER

unit_state fogdrift_state;

unit_real fogdrift_update(double time_s, unit_real fog, unit_real acc1, unit_real acc2) {
  return unit_update(&fogdrift_state, time_s, fog, acc1, acc2);
}

unit_real fogdrift_compensated(unit_real gyro_dph) {
  return unit_compensated_dph(&fogdrift_state, gyro_dph);
}

void fogdrift_power_on(void) { unit_reset(&fogdrift_state); }
