#!/usr/bin/env python3
"""The library's layers as docs/architecture.md draws them, checked against its includes.

docs/architecture.md's table under "Folders and files" names each layer (a folder of src/ and
include/fogdrift/) and the layers it may include. This script reads that table and every
#include of src/ and include/fogdrift/, and fails, naming the file and line, when
  - a file includes a layer its row does not allow;
  - a row allows a layer drawn below it, so that includes would go up (the table's order is the
    order of the layers, lowest first);
  - a folder of src/ or include/fogdrift/ has no row, or a row has no folder;
  - src/ and include/fogdrift/ do not hold the same folders (tests/ may hold fewer);
  - a library file includes the command line, the Python or the Octave package.
Usage: check_layers.py [ROOT]   (default: the repository this script is in). CTest: `layers`.
"""
import os
import re
import sys

ROOT = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), ".."))
DOC = os.path.join(ROOT, "docs", "architecture.md")
SOURCES = ("c", "cpp", "h", "hpp", "inc")


def read_table():
    """[(layer, allowed set)] in the table's order, from the first table with a 'layer' column."""
    rows, in_table = [], False
    with open(DOC, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if not in_table:
                in_table = line.startswith("|") and cells[:1] == ["layer"] and "includes" in cells
                if in_table:
                    includes_at = cells.index("includes")
                continue
            if not line.startswith("|"):
                break
            if set(cells[0]) <= set("-: "):
                continue  # the separator row
            name = re.fullmatch(r"`([a-z_]+)/`", cells[0])
            if not name:
                sys.exit(f"{DOC}:{number}: the layer cell {cells[0]!r} is not a folder like `base/`")
            text = cells[includes_at]
            allowed = set() if text in ("—", "-", "") else {t.strip() for t in text.split(",")}
            for a in allowed:
                if not re.fullmatch(r"[a-z_]+", a):
                    sys.exit(f"{DOC}:{number}: the includes cell names {a!r}, which is not a layer: "
                             "list the layers by folder name, separated by commas")
            rows.append((name.group(1), allowed, number))
    if not rows:
        sys.exit(f"{DOC}: no table with the columns 'layer' and 'includes'")
    return rows


def included_layer(path):
    """The layer an include names, or None for a file of the same folder."""
    parts = path.split("/")
    if parts[0] == "fogdrift" and len(parts) > 2:
        return parts[1]
    if len(parts) > 1:
        return parts[0]  # a private header of src/, e.g. "opt/population.hpp"
    return None


def main():
    rows = read_table()
    order = {name: k for k, (name, _, _) in enumerate(rows)}
    problems = []
    for name, allowed, number in rows:
        for a in sorted(allowed):
            if a not in order:
                problems.append(f"{DOC}:{number}: layer {name} may include '{a}', which has no row")
            elif order[a] >= order[name]:
                problems.append(f"{DOC}:{number}: layer {name} may include {a}, drawn at or below it: "
                                "includes would go up; order the rows so that every layer comes "
                                "after those it includes")
    folders = {}
    for top in ("src", os.path.join("include", "fogdrift")):
        base = os.path.join(ROOT, top)
        folders[top] = {d for d in os.listdir(base) if os.path.isdir(os.path.join(base, d))}
        for d in sorted(folders[top] - set(order)):
            problems.append(f"{top}/{d}/: a folder of the library with no row in the layer table "
                            f"of {DOC}: add one saying what it holds and includes")
    for name, _, number in rows:
        if name not in folders["src"] and name not in folders[os.path.join("include", "fogdrift")]:
            problems.append(f"{DOC}:{number}: layer {name} has no folder in src/ or include/fogdrift/")
    for d in sorted(folders["src"] ^ folders[os.path.join("include", "fogdrift")]):
        problems.append(f"{d}/: in only one of src/ and include/fogdrift/; the two mirror each other")
    allowed_of = {name: allowed for name, allowed, _ in rows}
    files = 0
    for top in ("src", os.path.join("include", "fogdrift")):
        for dirpath, _, names in os.walk(os.path.join(ROOT, top)):
            rel = os.path.relpath(dirpath, os.path.join(ROOT, top))
            layer = rel.split(os.sep)[0]
            for n in sorted(names):
                if n.rsplit(".", 1)[-1] not in SOURCES or layer == ".":
                    continue
                path = os.path.join(dirpath, n)
                files += 1
                with open(path, encoding="utf-8") as f:
                    for number, line in enumerate(f, 1):
                        m = re.match(r'\s*#\s*include\s*"([^"]+)"', line)
                        if not m:
                            continue
                        target = included_layer(m.group(1))
                        where = f"{os.path.relpath(path, ROOT)}:{number}"
                        if target in ("apps", "python", "matlab"):
                            problems.append(f"{where}: the library includes {m.group(1)}, a front end")
                        elif target is not None and target != layer and target not in allowed_of.get(layer, set()):
                            problems.append(f"{where}: layer {layer} includes {m.group(1)} (layer {target}), "
                                            f"which its row in docs/architecture.md does not allow")
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        return 1
    print(f"layers: {len(rows)} layers, {files} files, every include goes down the table")
    return 0


if __name__ == "__main__":
    sys.exit(main())
