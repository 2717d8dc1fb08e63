#!/usr/bin/env python3
"""Runs docs/matlab.md's Octave session as a test (octave_walkthrough).

Every ```matlab block of the page, in order, in one octave-cli session in a fresh folder, with
'build/matlab' in addpath replaced by FOGDRIFT_MATLAB_DIR; a block that raises fails the test.
Prints each block's time, the figures docs/matlab.md quotes. Usage: walkthrough.py docs/matlab.md
"""
import os
import re
import subprocess
import sys
import tempfile


def main(page):
    text = open(page, encoding="utf-8").read()
    blocks = re.findall(r"```matlab\n(.*?)```", text, re.S)
    if not blocks:
        sys.exit(f"{page}: no ```matlab blocks")
    matlab_dir = os.environ["FOGDRIFT_MATLAB_DIR"]
    script = []
    for i, block in enumerate(blocks, 1):
        block = block.replace("addpath('build/matlab')", f"addpath('{matlab_dir}')")
        script.append(f"tic;\n{block}\nprintf('walkthrough: block {i} took %.1f s\\n', toc);\n")
    script.append("disp('walkthrough passed');\n")
    with tempfile.TemporaryDirectory() as work:
        with open(os.path.join(work, "session.m"), "w", encoding="utf-8") as f:
            f.write("\n".join(script))
        r = subprocess.run(["octave-cli", "--no-window-system", "--norc", "session.m"], cwd=work,
                           capture_output=True, text=True)
        sys.stdout.write(r.stdout)
        sys.stderr.write(r.stderr)
        if r.returncode != 0 or "walkthrough passed" not in r.stdout:
            sys.exit(f"{page}: the session failed")


if __name__ == "__main__":
    main(sys.argv[1])
