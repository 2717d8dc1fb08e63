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
  - "lower cv": of the two models, the one with the lower cv RMSE (a search run twice);
then, instrument by instrument, B's share minus A's: the median and mean difference in points,
how many instruments B leaves better, the same (within half a point) and worse, and the sign
test's two-sided p on the better and worse ones (a change with no effect gives either sign with
probability 1/2). The 10th percentiles of two studies move by several points with the search's
luck alone; the paired differences show whether a change moves instruments one way.
Several pairs (WORK_A WORK_B WORK_A2 WORK_B2 …: one change measured with several search seeds)
are each printed, then their paired differences pooled.
The shares are computed as the study computes them (fogdrift northfind's table3): from the mean
over temperatures of each temperature's RMSE, raw, compensated and with the true drift
subtracted (the floor).
Usage: python3 bench/population_compare.py WORK_A WORK_B [WORK_A2 WORK_B2 ...]
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


def sign_test(better, worse):
    """Two-sided p of `better` successes in better + worse fair coin tosses (exact binomial)."""
    n = better + worse
    if n == 0:
        return 1.0
    k = min(better, worse)
    return min(1.0, 2 * sum(math.comb(n, i) for i in range(k + 1)) / 2**n)


# Two shares closer than this (half a point) count as the same instrument result.
SAME_POINTS = 0.5


def print_differences(title, differences):
    """differences[(path, c)]: B − A per instrument, in points."""
    print(title)
    print()
    print("| path | " + " | ".join(CONDITIONS) + " |")
    print("|---|" + "---|" * len(CONDITIONS))
    for path in PATHS:
        cells = []
        for c in CONDITIONS:
            d = [x for x in differences[(path, c)] if not math.isnan(x)]
            if not d:
                cells.append("n/a")
                continue
            better = sum(x > SAME_POINTS for x in d)
            worse = sum(x < -SAME_POINTS for x in d)
            cells.append(f"{quantile(d, .5):+.1f} / {sum(d) / len(d):+.1f}; {better} / "
                         f"{len(d) - better - worse} / {worse}, p = {sign_test(better, worse):.2f}")
        print(f"| {path} | " + " | ".join(cells) + " |")
    print()


def instruments(work):
    return sorted(int(p.name[5:]) for p in pathlib.Path(work).glob("unit_*") if p.is_dir())


def load(work, unit, name):
    with open(pathlib.Path(work) / f"unit_{unit:02d}" / name) as f:
        return json.load(f)


def main(a, b, differences):
    """Prints the two studies side by side; appends B − A per instrument to differences."""
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
                differences[(path, c)].append(100 * (s["B"] - s["A"]))
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
    print()


if __name__ == "__main__":
    works = sys.argv[1:]
    if len(works) < 2 or len(works) % 2:
        sys.exit(__doc__)
    pooled = {(p, c): [] for p in PATHS for c in CONDITIONS}
    for i in range(0, len(works), 2):
        these = {(p, c): [] for p in PATHS for c in CONDITIONS}
        main(works[i], works[i + 1], these)
        print_differences(f"B − A instrument by instrument, points: median / mean; instruments "
                          f"better / the same (within {SAME_POINTS}) / worse, sign test:", these)
        for key, d in these.items():
            pooled[key] += d
    if len(works) > 2:
        print_differences(f"Pooled over the {len(works) // 2} pairs, B − A, points: median / "
                          f"mean; better / the same / worse, sign test:", pooled)
