#!/usr/bin/env python3
"""Kilohertz logs through the command line (issue 60's goals): 30 minutes at 1 kHz and 2 kHz,
the wall time and peak memory of `fogdrift inspect`, `compensate` and `stream`, medians of RUNS,
beside pandas reading the same file (read_csv) and reading and writing it (to_csv), the peer a
user would otherwise script. The model is a 1 Hz causal SSA-SVR, fogdrift train's defaults
(docs/compensation.md, "Any sample rate").
Usage: python3 bench/khz_io.py [BUILD_DIR] [RUNS]   (default build/, 3); prints a Markdown table.
"""
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
# Debian's interpreter, where python3-pandas installs; a python3 earlier on PATH often lacks it.
PEER = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable


def measured(cmd, stdin=None):
    """(seconds, peak resident memory in bytes) of one run of `cmd`, its output discarded;
    `stdin`, a file its standard input reads."""
    start = time.perf_counter()
    source = open(stdin, "rb") if stdin else subprocess.DEVNULL
    child = subprocess.Popen(cmd, stdin=source, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    _, status, usage = os.wait4(child.pid, 0)
    seconds = time.perf_counter() - start
    if os.waitstatus_to_exitcode(status) != 0:
        sys.exit(f"failed: {' '.join(map(str, cmd))}: {child.stderr.read().decode()}")
    return seconds, usage.ru_maxrss * 1024


def main(build, runs):
    fd = str(pathlib.Path(build).resolve() / "apps" / "fogdrift" / "fogdrift")
    with tempfile.TemporaryDirectory() as work:
        w = pathlib.Path(work)
        subprocess.run([fd, "simulate", "calibration", "--out", w / "cal", "--seed", "1"],
                       check=True, stdout=subprocess.DEVNULL)
        subprocess.run([fd, "train", w / "cal", "--differentiator", "causal", "-q", "-o",
                        w / "model.json"], check=True)
        inst = json.loads(subprocess.run([fd, "simulate", "--print-instrument"], check=True,
                                         capture_output=True, text=True).stdout)
        print("| logger | file | command | wall, s | peak memory | memory / file |")
        print("|---|---|---|---|---|---|")
        # 1 kHz from the simulator (its highest rate); 2 kHz made from it, a row midway
        # between each two.
        inst["fog"]["fine_step_s"] = 0.001  # the simulator's step divides the interval
        (w / "inst.json").write_text(json.dumps(inst))
        subprocess.run([fd, "simulate", "northfind", "--out", w / "nf1000", "--temps", "17",
                        "--findings", "5", "--rate-hz", "1000", "--instrument", w / "inst.json"],
                       check=True, stdout=subprocess.DEVNULL)
        (w / "nf2000").mkdir()
        with open(w / "nf1000" / "nf_17C.csv") as src, \
                open(w / "nf2000" / "nf_17C.csv", "w") as dst:
            dst.write(next(src))
            before = None
            for line in src:
                row = [float(v) for v in line.split(",")]
                if before is not None:
                    dst.write(",".join(repr((a + b) / 2) for a, b in zip(before, row)) + "\n")
                dst.write(line)
                before = row
        for hz in (1000, 2000):
            rec = w / f"nf{hz}" / "nf_17C.csv"
            size = rec.stat().st_size
            out = w / "out.csv"
            commands = [
                ("fogdrift inspect", [fd, "inspect", rec]),
                ("fogdrift compensate", [fd, "compensate", w / "model.json", rec, "-o", out,
                                         "-q"]),
                ("fogdrift stream", [fd, "stream", w / "model.json", rec, "--rate-hz", str(hz)]),
                ("fogdrift stream < file", [fd, "stream", w / "model.json", "-", "--rate-hz",
                                            str(hz)], rec),
                ("pandas read_csv", [PEER, "-c",
                                     f"import pandas; pandas.read_csv({str(rec)!r})"]),
                ("pandas read_csv + to_csv", [PEER, "-c",
                                              f"import pandas; pandas.read_csv({str(rec)!r})"
                                              f".to_csv({str(out)!r}, index=False)"]),
            ]
            for name, cmd, *stdin in commands:
                got = [measured(cmd, *stdin) for _ in range(runs)]
                t = statistics.median(g[0] for g in got)
                m = statistics.median(g[1] for g in got)
                print(f"| {hz} Hz | {size / 1e6:.0f} MB | {name} | {t:.2f} | "
                      f"{m / 1e6:.0f} MB | {m / size:.2f} |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build"),
         int(sys.argv[2]) if len(sys.argv) > 2 else 3)
