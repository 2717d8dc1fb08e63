#!/usr/bin/env python3
"""Writes a +fogdrift function with its help made from fogdrift's option tables.

A line "%   {options:COMMAND}" in the source becomes one entry per option of `fogdrift options
COMMAND --json` (name, type, default, unit, help), so `help fogdrift.train` in Octave or MATLAB
says what --help and Python's docstrings say (docs/matlab.md). Usage:
    make_help.py FOGDRIFT_CLI SOURCE.m OUTPUT.m
"""
import json
import os
import re
import subprocess
import sys
import tempfile
import textwrap


def entries(cli, command):
    text = subprocess.run([cli, "options", command, "--json"], check=True, capture_output=True,
                          text=True).stdout
    lines = []
    for o in json.loads(text):
        head = f"'{o['keyword']}' ({o['type']}, default {o['default'] or 'none'}"
        head += f", {o['unit']})" if o["unit"] else ")"
        lines.append(f"%   {head}")
        for line in textwrap.wrap(o["doc"], 88):
            lines.append(f"%       {line}")
    return lines


def main(cli, source, output):
    out = []
    with open(source, encoding="utf-8") as f:
        for line in f.read().splitlines():
            m = re.fullmatch(r"%\s*\{options:([a-z-]+)\}", line.strip())
            out.extend(entries(cli, m.group(1)) if m else [line])
    os.makedirs(os.path.dirname(output), exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=os.path.dirname(output))
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write("\n".join(out) + "\n")
    os.replace(tmp, output)


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
