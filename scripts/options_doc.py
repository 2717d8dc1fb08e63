#!/usr/bin/env python3
"""Writes (or checks) the table of training options in docs/options.md.

The table is what `fogdrift options` prints: the one description fogdrift keeps of each option
of `fogdrift train` and Python's fogdrift.train (src/tune/train_option_table.cpp). This script puts
it between the page's two marker lines, so that the page cannot fall behind the code.

Usage:
    python3 scripts/options_doc.py FOGDRIFT            # rewrite the table (FOGDRIFT: the tool)
    python3 scripts/options_doc.py FOGDRIFT --check    # exit 1 if the page differs
"""
import os
import subprocess
import sys

PAGE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "docs", "options.md")
BEGIN = "<!-- train options: begin (scripts/options_doc.py writes this table) -->"
END = "<!-- train options: end -->"


def main(argv):
    if len(argv) not in (2, 3) or (len(argv) == 3 and argv[2] != "--check"):
        sys.exit(__doc__)
    table = subprocess.run([argv[1], "options"], check=True, capture_output=True,
                           text=True).stdout
    with open(PAGE, encoding="utf-8") as f:
        page = f.read()
    if BEGIN not in page or END not in page:
        sys.exit(f"{PAGE}: the marker lines {BEGIN!r} and {END!r} are missing")
    head, rest = page.split(BEGIN, 1)
    _, tail = rest.split(END, 1)
    wanted = head + BEGIN + "\n" + table + END + tail
    if len(argv) == 3:
        if wanted != page:
            sys.exit(f"{PAGE}: its table differs from `fogdrift options`; run "
                     f"python3 scripts/options_doc.py {argv[1]}")
        return
    with open(PAGE + ".tmp", "w", encoding="utf-8") as f:
        f.write(wanted)
    os.replace(PAGE + ".tmp", PAGE)


if __name__ == "__main__":
    main(sys.argv)
