#!/usr/bin/env python3
"""Writes the fixtures of tests/data/unit_logs: what a unit's own logs and its chamber sheets look
like where fogdrift meets a real unit (docs/logs.md, "The evidence" and "Judging a model").

  unit.csv         a unit's recording in fogdrift's format, a sample every 60 s for 6 hours after
                   power-on (09:00:00 on the unit's clock): the x gyro, whose drift follows its
                   thermometer, and the z gyro, whose drift is a constant bias and noise with no
                   temperature signal at all, °/h; the FOG thermometer, °C.
  sheet.csv        the chamber sheet kept by hand beside it: a time of day every 5 minutes (HH:MM)
                   on a clock that reads 437 s early, the air and a thermocouple on the unit's case
                   (reading 0.6 °C above the unit's thermometer), °C; the sheet's schedule ran on
                   for 14 rows after the readings stopped, rows with a time and empty cells.
  other_sheet.csv  a sheet of another day's run, as a user may pick up by mistake: the same form,
                   a chamber that cooled from 21 to 9 °C, nothing in common with the unit's run.

The chamber holds 20 °C, ramps to -20 °C, holds, ramps to 40 °C, holds, and returns towards 20 °C;
the unit's thermometer follows it with a lag of 900 s and 5 °C of self-heating. The x drift is
0.5 + 0.05 (T - 20) + 200 dT/dt °/h (dT/dt in °C/s), with white noise of 0.02 °/h; the z drift is
3 °/h with white noise of 0.05 °/h.

Deterministic: run it again and the files are the same, byte for byte (cli_unit_logs checks).
Usage: python3 scripts/make_unit_log_fixtures.py [OUT_DIR]
"""
import math
import os
import random
import sys

# The chamber's program is the chamber fixture's (scripts/make_chamber_fixture.py), its neighbour.
from make_chamber_fixture import chamber

RUN_S = 6 * 3600
POWER_ON_S = 9 * 3600          # 09:00:00 on the unit's clock
SHEET_CLOCK_EARLY_S = 437      # the sheet's clock reads this much early
CASE_BIAS_DEGC = 0.6
TRAILING_ROWS = 14


def other_chamber(t):
    """Another day's chamber: 21 °C cooling to 9 °C over four hours, then holding."""
    return 21.0 - 12.0 * min(max(t, 0.0), 14400.0) / 14400.0


def lagged(air, tau_s, heat_degc, heat_tau_s):
    """A node following the air with time constant tau_s, plus self-heating after power-on: a
    1 s table from 40 minutes before power-on (at rest) to 30 minutes after the run."""
    out = {}
    temp = air(0.0)
    for t in range(-2400, RUN_S + 1800 + 1):
        temp += (air(max(t, 0.0)) - temp) / tau_s
        out[t] = temp + (heat_degc * (1.0 - math.exp(-t / heat_tau_s)) if t > 0 else 0.0)
    return out


def clock(seconds):
    seconds = int(round(seconds)) % 86400
    return f"{seconds // 3600:02d}:{seconds % 3600 // 60:02d}"


def write(path, lines, newline="\n"):
    with open(path, "w", newline=newline, encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")


def sheet(path, air, node, rng):
    """A sheet read every 5 minutes of its clock from 20 minutes before power-on to the end of
    the run, then its schedule's trailing rows with a time and no values."""
    rows = ["Time,Air (C),Case (C)"]
    start = POWER_ON_S - SHEET_CLOCK_EARLY_S - 1200
    start -= start % 300
    stamp = start
    while stamp <= POWER_ON_S + RUN_S:
        t = stamp + SHEET_CLOCK_EARLY_S - POWER_ON_S  # seconds after power-on, truly
        case = node[int(round(t))] + CASE_BIAS_DEGC + rng.gauss(0.0, 0.05)
        rows.append(f"{clock(stamp)},{air(max(t, 0.0)):.1f},{case:.2f}")
        stamp += 300
    for _ in range(TRAILING_ROWS):
        rows.append(f"{clock(stamp)},,")
        stamp += 300
    write(path, rows, newline="\r\n")


def main(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    rng = random.Random(20261127)
    fog = lagged(chamber, 900.0, 5.0, 900.0)
    rows = ["time_s,gyro_dph,temp_fog_degc,gyro_z_dph"]
    for t in range(0, RUN_S + 1, 60):
        temp = fog[t]
        rate = (fog[t + 1] - fog[t - 1]) / 2.0
        x = 0.5 + 0.05 * (temp - 20.0) + 200.0 * rate + rng.gauss(0.0, 0.02)
        z = 3.0 + rng.gauss(0.0, 0.05)
        rows.append(f"{t},{x:.5f},{temp + rng.gauss(0.0, 0.01):.3f},{z:.5f}")
    write(os.path.join(out_dir, "unit.csv"), rows)
    sheet(os.path.join(out_dir, "sheet.csv"), chamber, fog, rng)
    other = lagged(other_chamber, 900.0, 5.0, 900.0)
    sheet(os.path.join(out_dir, "other_sheet.csv"), other_chamber, other, rng)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/unit_logs")
