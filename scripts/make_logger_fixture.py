#!/usr/bin/env python3
"""Writes tests/data/logger/tvac_log.csv: a logger file as a thermal chamber gives it.

What it imitates (docs/logs.md): a MEMS IMU on a microcontroller logger, power-cycled at four
chamber temperatures in one file. The logger
  - counts milliseconds from its own boot (the clock restarts at each power cycle),
  - logs in bursts: 50 samples at 50 Hz once a minute, stamps rounded to the millisecond
    (steps of 19, 20 and 21 ms),
  - reads one thermometer, a signed 16-bit register (1/256 °C per count, 0 at 25 °C) written as
    its unsigned bit pattern, so anything below 25 °C reads 32768..65535,
  - loses five bursts in the third cycle, and writes three spikes (two in the gyro, one in the
    thermometer).
The gyro's drift is known: 0.02 + 0.0015 (T - 20) + 0.6 dT/dt °/s (T in °C, dT/dt in °C/s),
plus white noise of 0.03 °/s per sample, with the axis seeing no rotation.

Deterministic: run it again and the file is the same, byte for byte.
Usage: python3 scripts/make_logger_fixture.py [OUT.csv]
"""
import math
import random
import sys

CHAMBER_DEGC = [-10.0, 5.0, 20.0, 35.0]
CYCLE_MIN = 60
BURST_SAMPLES = 50
HEATING_DEGC = 8.0  # self-heating after power-on
TAU_S = 900.0  # its time constant


def temperature(chamber, t):
    return chamber + HEATING_DEGC * (1.0 - math.exp(-t / TAU_S))


def rate(t):
    return HEATING_DEGC / TAU_S * math.exp(-t / TAU_S)


def register(temp_degc):
    raw = int(round((temp_degc - 25.0) * 256.0))
    return raw & 0xFFFF  # the unsigned bit pattern of the signed register


def main(out):
    rng = random.Random(20261123)
    lines = ["millis,gx_dps,temp_raw,status"]
    for cycle, chamber in enumerate(CHAMBER_DEGC):
        boot_ms = 1500 + rng.randint(0, 400)
        for burst in range(CYCLE_MIN):
            if cycle == 2 and 30 <= burst < 35:
                continue  # the logger's SD card stalled
            start_ms = boot_ms + 60000 * burst
            for j in range(BURST_SAMPLES):
                ms = start_ms + round(20.0 * j + rng.uniform(-1.2, 1.2))
                t = ms / 1000.0
                temp = temperature(chamber, t)
                drift = 0.02 + 0.0015 * (temp - 20.0) + 0.6 * rate(t)
                gyro = drift + rng.gauss(0.0, 0.03)
                raw = register(temp + rng.gauss(0.0, 0.02))
                if (cycle, burst, j) in ((0, 12, 7), (3, 40, 30)):
                    gyro = 8.0  # a bus glitch
                if (cycle, burst, j) == (1, 20, 11):
                    raw = 0x7FFF  # the register's error value
                lines.append(f"{ms},{gyro:.5f},{raw},OK")
    with open(out, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/logger/tvac_log.csv")
