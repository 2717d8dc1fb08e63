#!/usr/bin/env python3
"""Writes a three-axis IMU log and the chamber sheet kept beside it on another machine.

What it imitates (docs/logs.md, "Temperatures from another file"):
  imu3.csv      a MEMS IMU on a logger that counts milliseconds from its own boot, in bursts of
                50 samples at 50 Hz once a minute (stamps jitter by a millisecond), three gyro
                axes in °/s, two accelerometers (x level, in g; z pointing up, in m/s²), the
                unit's estimate of its x gyro's scale-factor error in ppm, and one thermometer, a
                signed 16-bit register written as its unsigned bit pattern (1/256 °C per count,
                0 at 25 °C).
  truth.csv     each burst's true mean drift per axis, °/h, of each accelerometer's bias, g, and
                of the scale-factor error, ppm, at its time on a 60 s grid.
  sheet.csv     the chamber sheet: a time of day every 5 minutes (HH:MM), the chamber air in °C and
                three thermocouples in °F (on the IMU's case beside its thermometer, on the far
                side of the case, on the mounting plate), as a spreadsheet exports it: a BOM,
                trailing empty columns and trailing rows of empty cells.
The IMU was powered on at 09:12:40 by the logger's clock; the sheet's clock runs 250 s behind
it, so its stamps read 250 s early. The chamber holds 20 °C, ramps to -20 °C, holds, ramps to
40 °C, holds, and returns towards 20 °C.

Each axis drifts by a known law of the temperatures the sheet and the IMU see (°/s; T in °C,
dT/dt in °C/s), plus white noise of 0.03 °/s per sample, with no rotation:
  x: 0.02 + 0.0015 (T_imu - 20) + 0.6 dT_imu/dt
  y: -0.01 - 0.0010 (T_far - 20) + 0.4 dT_far/dt
  z: 0.005 + 0.0020 (T_plate - 20)
plus white noise of 0.03 °/s per sample, with no rotation; so do the accelerometers' biases (g)
and the scale-factor error (ppm), with noise of 0.0005 g and 5 ppm per sample:
  accel x: 0.002 + 5e-5 (T_imu - 20) + 0.02 dT_imu/dt            (level: it senses no gravity)
  accel z: -0.001 + 3e-5 (T_far - 20) + 0.01 dT_far/dt           (up: it senses 1 g besides)
  sf:      150 + 12 (T_plate - 20)
T_imu is what the IMU's thermometer reads; the case thermocouple reads it 0.3 °C high.

Deterministic: run it again and the files are the same, byte for byte.
Usage: python3 scripts/make_chamber_fixture.py [OUT_DIR]
"""
import math
import os
import random
import sys

POWER_ON_S = 9 * 3600 + 12 * 60 + 40  # 09:12:40 on the logger's clock
SHEET_CLOCK_BEHIND_S = 250
RUN_S = 6 * 3600
BURST_SAMPLES = 50


def chamber(t):
    """The chamber air, °C, t seconds after power-on."""
    legs = [(1200, 20.0, 20.0), (2400, 20.0, -20.0), (4200, -20.0, -20.0),
            (4800, -20.0, 40.0), (4200, 40.0, 40.0), (4800, 40.0, 20.0)]
    start = 0.0
    for length, a, b in legs:
        if t < start + length:
            return a + (b - a) * (t - start) / length
        start += length
    return 20.0


def lagged(tau_s, heat_degc, heat_tau_s, step_s=1.0):
    """A node following the air with time constant tau_s, plus self-heating after power-on,
    integrated every step_s from 40 minutes before power-on (at rest) to the end."""
    out = {}
    temp = 20.0
    t = -2400.0
    while t <= RUN_S + 1800:
        temp += (chamber(max(t, 0.0)) - temp) * step_s / tau_s
        heating = heat_degc * (1.0 - math.exp(-t / heat_tau_s)) if t > 0 else 0.0
        out[round(t)] = temp + heating
        t += step_s
    return out


def at(node, t):
    """Linear interpolation of a node's 1 s table."""
    lo = math.floor(t)
    w = t - lo
    return node[lo] * (1 - w) + node.get(lo + 1, node[lo]) * w


def register(temp_degc):
    return int(round((temp_degc - 25.0) * 256.0)) & 0xFFFF


def clock(seconds):
    seconds = int(round(seconds)) % 86400
    return f"{seconds // 3600:02d}:{seconds % 3600 // 60:02d}"


def main(out_dir):
    rng = random.Random(20261125)
    imu = lagged(900.0, 6.0, 900.0)
    far = lagged(1500.0, 4.0, 1200.0)
    plate = lagged(600.0, 0.0, 1.0)

    def rate(node, t):
        return (at(node, t + 1.0) - at(node, t - 1.0)) / 2.0

    lines = ["millis,gx_dps,gy_dps,gz_dps,ax_g,az_ms2,sf_ppm,temp_raw,status"]
    truth = ["time_s,drift_x_dph,drift_y_dph,drift_z_dph,bias_x_g,bias_z_g,sf_ppm"]
    # The accelerometers and the scale factor draw their noise from a generator of their own, so
    # that the gyros' columns are those of the fixture before they were added.
    rng_other = random.Random(20261126)
    boot_ms = 1730
    for burst in range(RUN_S // 60):
        start_ms = boot_ms + 60000 * burst
        sums = [0.0, 0.0, 0.0]
        other_sums = [0.0, 0.0, 0.0]
        for j in range(BURST_SAMPLES):
            ms = start_ms + round(20.0 * j + rng.uniform(-1.2, 1.2))
            t = ms / 1000.0
            ti, tf, tp = at(imu, t), at(far, t), at(plate, t)
            gx = 0.02 + 0.0015 * (ti - 20.0) + 0.6 * rate(imu, t)
            gy = -0.01 - 0.0010 * (tf - 20.0) + 0.4 * rate(far, t)
            gz = 0.005 + 0.0020 * (tp - 20.0)
            bx = 0.002 + 5e-5 * (ti - 20.0) + 0.02 * rate(imu, t)
            bz = -0.001 + 3e-5 * (tf - 20.0) + 0.01 * rate(far, t)
            sf = 150.0 + 12.0 * (tp - 20.0)
            sums = [a + b for a, b in zip(sums, (gx, gy, gz))]
            other_sums = [a + b for a, b in zip(other_sums, (bx, bz, sf))]
            noisy = [g + rng.gauss(0.0, 0.03) for g in (gx, gy, gz)]
            raw = register(ti + rng.gauss(0.0, 0.02))
            ax = bx + rng_other.gauss(0.0, 0.0005)
            az = (1.0 + bz + rng_other.gauss(0.0, 0.0005)) * 9.80665
            sf_logged = sf + rng_other.gauss(0.0, 5.0)
            lines.append(f"{ms},{noisy[0]:.5f},{noisy[1]:.5f},{noisy[2]:.5f},{ax:.6f},{az:.6f},"
                         f"{sf_logged:.2f},{raw},OK")
        # The burst's true mean drift, °/h, at the grid time import --step-s 60 gives it.
        truth.append(f"{60 * burst}," + ",".join(f"{3600.0 * x / BURST_SAMPLES:.6f}" for x in sums)
                     + "," + ",".join(f"{x / BURST_SAMPLES:.8f}" for x in other_sums))
    with open(os.path.join(out_dir, "imu3.csv"), "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(out_dir, "truth.csv"), "w", newline="\n") as f:
        f.write("\n".join(truth) + "\n")

    def fahrenheit(c):
        return c * 9.0 / 5.0 + 32.0

    rows = ["\ufeffTime,Air (C),TC1 case (F),TC2 far side (F),TC3 plate (F),,"]
    # Every 5 minutes of the sheet's clock, from 20 minutes before power-on to 10 minutes after
    # the IMU's log ends.
    sheet_start = POWER_ON_S - SHEET_CLOCK_BEHIND_S - 1200
    sheet_start -= sheet_start % 300
    stamp = sheet_start
    while stamp <= POWER_ON_S + RUN_S + 600:
        t = stamp + SHEET_CLOCK_BEHIND_S - POWER_ON_S  # seconds after power-on, truly
        rows.append(",".join([
            clock(stamp), f"{chamber(max(t, 0.0)):.1f}",
            f"{fahrenheit(at(imu, t) + 0.3):.1f}", f"{fahrenheit(at(far, t)):.1f}",
            f"{fahrenheit(at(plate, t)):.1f}", "", ""]))
        stamp += 300
    rows += [",,,,,,", ",,,,,,"]
    with open(os.path.join(out_dir, "sheet.csv"), "w", newline="\r\n", encoding="utf-8") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "tests/data/chamber")
