#!/usr/bin/env python3
"""docs/logs.md, "7. A unit's logs, end to end", run as a user would: every ```sh block of the
section in order, in one fresh folder holding tests/data/unit_logs, with the fogdrift under test
first on PATH. Each block must exit 0 (or 1 when its first line is "# exits 1"), and every line
of the ```text block that follows it must appear in its output (standard output and error).
Usage: logs_walkthrough.py PATH/TO/fogdrift
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
DOC = ROOT / "docs" / "logs.md"
SECTION = "## 7. A unit's logs, end to end"


def steps(text):
    """(code, expected exit, [lines]) for each sh block of the section, in order."""
    start = text.index(SECTION)
    end = text.find("\n## ", start + len(SECTION))
    section = text[start:end if end >= 0 else len(text)]
    blocks = re.findall(r"```(sh|text)\n(.*?)```", section, flags=re.S)
    out = []
    for kind, body in blocks:
        if kind == "sh":
            exit_code = 1 if body.startswith("# exits 1") else 0
            out.append([body, exit_code, []])
        elif out:
            out[-1][2] += [line.strip() for line in body.splitlines() if line.strip()]
    return out


def main(cli):
    cli = pathlib.Path(cli).resolve()
    found = steps(DOC.read_text(encoding="utf-8"))
    if len(found) < 6:
        print(f"FAILED: the section has {len(found)} sh blocks, expected at least 6")
        return 1
    failures = 0
    # The committed fixture is what its script writes, byte for byte.
    with tempfile.TemporaryDirectory() as again:
        subprocess.run([sys.executable, str(ROOT / "scripts" / "make_unit_log_fixtures.py"), again],
                       check=True)
        for name in ("unit.csv", "sheet.csv", "other_sheet.csv"):
            committed = (ROOT / "tests" / "data" / "unit_logs" / name).read_bytes()
            if pathlib.Path(again, name).read_bytes() != committed:
                failures += 1
                print(f"FAILED: tests/data/unit_logs/{name} is not what "
                      "scripts/make_unit_log_fixtures.py writes")
    with tempfile.TemporaryDirectory() as work:
        for name in ("unit.csv", "sheet.csv", "other_sheet.csv"):
            shutil.copy(ROOT / "tests" / "data" / "unit_logs" / name, work)
        env = dict(os.environ, PATH=f"{cli.parent}{os.pathsep}{os.environ.get('PATH', '')}")
        for number, (code, expected, lines) in enumerate(found, start=1):
            done = subprocess.run(["bash", "-c", "set -e\n" + code], cwd=work, env=env,
                                  capture_output=True, text=True)
            output = done.stdout + done.stderr
            ok = done.returncode == expected
            if not ok:
                print(f"FAILED: block {number} exited {done.returncode}, expected {expected}")
            for line in lines:
                if line not in output:
                    ok = False
                    print(f"FAILED: block {number} did not print: {line}")
            if not ok:
                failures += 1
                print(f"--- block {number}:\n{code}--- its output:\n{output}")
            else:
                print(f"ok: block {number}")
        if not list(pathlib.Path(work, "figs").glob("*.json")):
            failures += 1
            print("FAILED: no figures in figs/")
    print(f"logs walkthrough: {failures} failure(s) over {len(found)} blocks and the fixture")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
