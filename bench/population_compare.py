#!/usr/bin/env python3
"""Two population studies of the same instruments and campaigns, instrument by instrument
(docs/field.md, "The spread is one instrument's"): how much of a study is its search's luck.

Each study is a POPULATION_WORK folder that bench/population_study.sh kept, run with the same
count, population seed and protocol and different search seeds (POPULATION_SEARCH_SEED_OFFSET).
Prints, per instrument and path (batch = centred, causal), each study's C, σ and cv RMSE and its
share of the removable north-finding error removed under every start-up condition (guard on),
then the distribution (median / 10th percentile / worst) of
  - each study;
  - "average": the two models averaged, emulated by averaging the compensated azimuth error of
    each finding (the correction enters the four-position azimuth almost linearly);
  - "lower cv": of the two models, the one with the lower cv RMSE (a search run twice).
The shares are computed as the study computes them (fogdrift northfind's table3): from the mean
over temperatures of each temperature's RMSE, raw, compensated and with the true drift
subtracted (the floor).
Usage: python3 bench/population_compare.py WORK_A WORK_B
"""
import json
import math
import pathlib
import sys

CONDITIONS = ("calibration", "soaked", "warm", "ramping")
PATHS = ("centred", "causal")


def rms(values):
    return math.sqrt(sum(v * v for v in values) / len(values))


def share(raw, compensated, floor):
    """fogdrift's share_removed: (raw² − comp²) / (raw² − floor²), each the mean over recordings
    of a recording's RMSE; NaN where raw does not exceed the floor."""
    r = sum(map(rms, raw)) / len(raw)
    c = sum(map(rms, compensated)) / len(compensated)
    f = sum(map(rms, floor)) / len(floor)
    return (r * r - c * c) / (r * r - f * f) if r > f else float("nan")


def quantile(values, q):
    """Linear interpolation between order statistics, as population_study.sh."""
    v = sorted(values)
    x = q * (len(v) - 1)
    i = int(math.floor(x))
    return v[i] if i + 1 >= len(v) else v[i] + (x - i) * (v[i + 1] - v[i])


def instruments(work):
    return sorted(int(p.name[5:]) for p in pathlib.Path(work).glob("unit_*") if p.is_dir())


def load(work, unit, name):
    with open(pathlib.Path(work) / f"unit_{unit:02d}" / name) as f:
        return json.load(f)


def main(a, b):
    units = instruments(a)
    if not units or units != instruments(b):
        sys.exit(f"population_compare.py: {a} and {b} must hold the same instruments "
                 f"(unit_NN folders of bench/population_study.sh with POPULATION_WORK); "
                 f"found {units} and {instruments(b)}")
    kinds = ("A", "B", "average", "lower cv")
    shares = {k: {(p, c): [] for p in PATHS for c in CONDITIONS} for k in kinds}
    print("| unit | path | A: C, σ, cv RMSE | B: C, σ, cv RMSE | "
          + " | ".join(f"{c} A / B / average" for c in CONDITIONS) + " |")
    print("|---|---|---|---|" + "---|" * len(CONDITIONS))
    for unit in units:
        for path in PATHS:
            ta, tb = (load(w, unit, f"{path}.train.json") for w in (a, b))
            lower = "A" if ta["fitness_rmse"] <= tb["fitness_rmse"] else "B"
            cells = []
            for c in CONDITIONS:
                na, nb = (load(w, unit, f"{path}.{c}.on.json")["recordings"] for w in (a, b))
                if [r["file"] for r in na] != [r["file"] for r in nb]:
                    sys.exit(f"population_compare.py: unit {unit} {c}: the two studies' "
                             "north-finding campaigns differ; run both with the same count, "
                             "population seed and protocol")
                raw = [r["raw_error_deg"] for r in na]
                floor = [r["true_drift_subtracted_error_deg"] for r in na]
                ca = [r["compensated_error_deg"] for r in na]
                cb = [r["compensated_error_deg"] for r in nb]
                mean = [[(x + y) / 2 for x, y in zip(p, q)] for p, q in zip(ca, cb)]
                s = {"A": share(raw, ca, floor), "B": share(raw, cb, floor),
                     "average": share(raw, mean, floor)}
                s["lower cv"] = s[lower]
                for k in kinds:
                    shares[k][(path, c)].append(s[k])
                cells.append(f"{100 * s['A']:.0f} / {100 * s['B']:.0f} / {100 * s['average']:.0f}")
            hp = [f"{t['hyperparameters']['C']:.4g}, {t['hyperparameters']['sigma']:.3g}, "
                  f"{t['fitness_rmse']:.4f}" for t in (ta, tb)]
            print(f"| {unit} | {path} | {hp[0]} | {hp[1]} | " + " | ".join(cells) + " |")
    print()
    print(f"Share removed over {len(units)} instruments, % (median / 10th percentile / worst):")
    print()
    print("| models | path | " + " | ".join(CONDITIONS) + " | worse than raw |")
    print("|---|---|" + "---|" * len(CONDITIONS) + "---|")
    for k in kinds:
        for path in PATHS:
            cells, worse = [], 0
            for c in CONDITIONS:
                # As population_study.sh: a share with no removable error (NaN) is left out.
                v = [x for x in shares[k][(path, c)] if not math.isnan(x)]
                worse += sum(x < 0 for x in v)
                cells.append(f"{100 * quantile(v, .5):.0f} / {100 * quantile(v, .1):.0f} / "
                             f"{100 * min(v):.0f} (n = {len(v)})" if v else "n/a")
            print(f"| {k} | {path} | " + " | ".join(cells) + f" | {worse} |")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
