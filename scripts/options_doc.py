#!/usr/bin/env python3
"""Writes (or checks) the tables of options in docs/options.md.

Each table is what `fogdrift options COMMAND` prints: the one description fogdrift keeps of the
options of a command and its Python function, for every command `fogdrift options --list` names
(docs/options.md's first table says which file of src/ holds each). This
script puts each between its two marker lines on the page, so that the page cannot fall behind
the code. It also writes the `--method a|b|…` lists of README.md and docs/tuning.md from the
registry's methods (`--method`'s allowed values), so a regressor added by docs/architecture.md's
recipe reaches them by running this script, not by hand.

Usage:
    python3 scripts/options_doc.py FOGDRIFT            # rewrite the table (FOGDRIFT: the tool)
    python3 scripts/options_doc.py FOGDRIFT --check    # exit 1 if the page differs
"""
import json
import os
import re
import subprocess
import sys

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
PAGE = os.path.join(ROOT, "docs", "options.md")
# The pages whose synopses list the methods, and how each writes the bar between them (README's
# is inside a Markdown table, where a bare | would end the cell).
METHOD_LISTS = {os.path.join(ROOT, "README.md"): "\\|", os.path.join(ROOT, "docs", "tuning.md"): "|"}


def method_lists(tool, check):
    """Rewrites (or checks) every `--method a|b|…` of METHOD_LISTS; returns the pages that
    differ."""
    options = json.loads(subprocess.run([tool, "options", "train", "--json"], check=True,
                                        capture_output=True, text=True).stdout)
    allowed = next(o["allowed"] for o in options if o["keyword"] == "method").split(", ")
    stale = []
    for path, bar in METHOD_LISTS.items():
        with open(path, encoding="utf-8") as f:
            text = f.read()
        pattern = re.compile(r"--method [a-z][a-z-]*(?:" + re.escape(bar) + r"[a-z][a-z-]*)+")
        if not pattern.search(text):
            sys.exit(f"{path}: no `--method a{bar}b` list to keep")
        wanted = pattern.sub(lambda m: "--method " + bar.join(allowed), text)
        if wanted == text:
            continue
        stale.append(path)
        if not check:
            with open(path + ".tmp", "w", encoding="utf-8") as f:
                f.write(wanted)
            os.replace(path + ".tmp", path)
    return stale


def markers(command):
    return (f"<!-- {command} options: begin (scripts/options_doc.py writes this table) -->",
            f"<!-- {command} options: end -->")


def main(argv):
    if len(argv) not in (2, 3) or (len(argv) == 3 and argv[2] != "--check"):
        sys.exit(__doc__)
    with open(PAGE, encoding="utf-8") as f:
        page = f.read()
    wanted = page
    # The commands whose options are described once, as the tool lists them: a command added
    # there without a table on the page fails here.
    commands = subprocess.run([argv[1], "options", "--list"], check=True, capture_output=True,
                              text=True).stdout.split()
    for command in commands:
        table = subprocess.run([argv[1], "options", command], check=True, capture_output=True,
                               text=True).stdout
        begin, end = markers(command)
        if begin not in wanted or end not in wanted:
            sys.exit(f"{PAGE}: the marker lines {begin!r} and {end!r} are missing")
        head, rest = wanted.split(begin, 1)
        _, tail = rest.split(end, 1)
        wanted = head + begin + "\n" + table + end + tail
    stale = method_lists(argv[1], check=len(argv) == 3)
    if len(argv) == 3:
        if wanted != page:
            sys.exit(f"{PAGE}: a table differs from `fogdrift options`; run "
                     f"python3 scripts/options_doc.py {argv[1]}")
        if stale:
            sys.exit(f"{', '.join(stale)}: the --method list differs from the registry's; run "
                     f"python3 scripts/options_doc.py {argv[1]}")
        return
    with open(PAGE + ".tmp", "w", encoding="utf-8") as f:
        f.write(wanted)
    os.replace(PAGE + ".tmp", PAGE)


if __name__ == "__main__":
    main(sys.argv)
