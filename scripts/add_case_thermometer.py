#!/usr/bin/env python3
"""Gives every recording of a campaign a fourth thermometer and the drift it causes.

What it imitates (docs/logs.md, "More thermometers"): a heater on the instrument's case cycles
every 400 s, each recording at its own phase; a thermometer on the case (temp_case_degc) reads
    T_case = T_fog + 3 sin(2 pi t / 400 + phase_i)   (deg C)
and the gyro drifts by 4 (T_case - T_fog) / 3 deg/h more, which the FOG and accelerometer
thermometers do not see. Recording i of the manifest has phase 0.9 i (+ OFFSET, for a test set
unlike the calibration). Rewrites the CSV files in place and keeps every other column verbatim.

Usage: python3 scripts/add_case_thermometer.py CAMPAIGN_DIR [OFFSET]
"""
import csv
import json
import math
import os
import sys


def main(folder, offset):
    with open(os.path.join(folder, "campaign.json"), encoding="utf-8") as f:
        manifest = json.load(f)
    for i, entry in enumerate(manifest["recordings"]):
        path = os.path.join(folder, entry["file"])
        with open(path, newline="", encoding="utf-8") as f:
            rows = list(csv.reader(f))
        header = rows[0]
        t, gyro, fog = (header.index(c) for c in ("time_s", "gyro_dph", "temp_fog_degc"))
        header.append("temp_case_degc")
        for row in rows[1:]:
            excess = 3.0 * math.sin(2 * math.pi * float(row[t]) / 400.0 + 0.9 * i + offset)
            row[gyro] = repr(float(row[gyro]) + 4.0 * excess / 3.0)
            row.append(repr(float(row[fog]) + excess))
        with open(path, "w", newline="", encoding="utf-8") as f:
            csv.writer(f, lineterminator="\n").writerows(rows)


if __name__ == "__main__":
    main(sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 0.0)
