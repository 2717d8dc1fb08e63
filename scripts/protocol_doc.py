#!/usr/bin/env python3
"""Writes (or checks) the table of studied calibration protocols in docs/field.md.

The table is what `fogdrift plan --hours 100000 --json` lists under "studied": every protocol
kept in src/sim/protocol_front.cpp with what it removed on the population and its service
chamber hours on the default instrument. This script puts it between its two marker lines on
the page, so that the page cannot fall behind the code.

Usage:
    python3 scripts/protocol_doc.py FOGDRIFT            # rewrite the table (FOGDRIFT: the tool)
    python3 scripts/protocol_doc.py FOGDRIFT --check    # exit 1 if the page differs
"""
import json
import os
import subprocess
import sys

PAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "field.md")
BEGIN = "<!-- studied protocols: begin (scripts/protocol_doc.py writes this table) -->"
END = "<!-- studied protocols: end -->"
CONDITIONS = ("calibration", "soaked", "warm", "ramping")


def minus(text):
    """Negative figures with the typographic minus the page uses elsewhere."""
    return text.replace("-", "\u2212")


def table(fogdrift):
    out = subprocess.run([fogdrift, "plan", "--hours", "100000", "--json"], check=True,
                         capture_output=True, text=True).stdout
    rows = ["| protocol | service hours | path | " + " | ".join(CONDITIONS)
            + " | worse than raw | train, s |",
            "|---|---|---|" + "---|" * len(CONDITIONS) + "---|---|"]
    for p in json.loads(out)["studied"]:
        name = p["name"]
        if p["instruments"] != 20:
            name += f" ({p['instruments']} instruments)"
        first = [name, f"{p['service_hours']:.1f}"]
        last = [f"{p['worse_than_raw']} of {8 * p['instruments']}", f"{p['train_median_s']:g}"]
        # The study, then the same study with other search seeds where it was repeated.
        studies = [("", p, first, last)] + [
            (f", search seeds k + {r['search_seed_offset']}", r, ["", ""],
             [f"{r['worse_than_raw']} of {8 * p['instruments']}", ""])
            for r in p.get("reruns", [])]
        for seeds, study, lead, tail in studies:
            for path in ("batch", "causal"):
                cells = [minus(" / ".join(f"{study[path][c][k]:g}"
                                          for k in ("median_pct", "p10_pct", "worst_pct")))
                         for c in CONDITIONS]
                row = lead + [path + seeds] + cells + tail if path == "batch" else \
                    ["", "", path + seeds] + cells + ["", ""]
                rows.append("| " + " | ".join(row) + " |")
    return "\n".join(rows) + "\n"


def main():
    if len(sys.argv) not in (2, 3) or (len(sys.argv) == 3 and sys.argv[2] != "--check"):
        sys.exit(__doc__)
    text = open(PAGE, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        sys.exit(f"{PAGE}: the markers of the studied protocols' table are missing")
    head, rest = text.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    new = head + BEGIN + "\n" + table(sys.argv[1]) + END + tail
    if len(sys.argv) == 3:
        if new != text:
            sys.exit(f"{PAGE}: the studied protocols' table differs from `fogdrift plan --hours "
                     "100000 --json`; run python3 scripts/protocol_doc.py FOGDRIFT")
        return
    open(PAGE, "w", encoding="utf-8").write(new)


if __name__ == "__main__":
    main()
