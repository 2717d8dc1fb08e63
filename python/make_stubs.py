#!/usr/bin/env python3
"""Writes _fogdrift.pyi, the type stub of the compiled module, from the signatures pybind11
puts on the first line of each function's docstring (docs/python.md, "Types").

With it and py.typed, type checkers and editors see fogdrift's compiled functions and classes
with their parameters' types. Usage: make_stubs.py PACKAGE_DIR (the folder holding
_fogdrift*.so; the stub is written there).
"""
import importlib.util
import inspect
import os
import re
import sys
import tempfile

HEADER = '''# The type stub of fogdrift._fogdrift, written by python/make_stubs.py from the compiled
# module's own signatures. Do not edit.
import os
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy
'''


def clean(text):
    """pybind11's type names as stub text."""
    text = text.replace("fogdrift._fogdrift.", "")
    text = re.sub(r"numpy\.ndarray\[[^\]]*\]", "numpy.ndarray", text)
    return text.replace("object", "Any")


def load(package_dir, name, filename):
    """A module of the package by its file, without the package's __init__."""
    spec = importlib.util.spec_from_file_location(name, os.path.join(package_dir, filename))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def defaults_as_ellipsis(params, split_top):
    """A parameter list with every default written `...`, as stubs write them."""
    out = []
    for p in split_top(params):
        if "=" in p and not p.startswith("*"):
            p = p.split("=", 1)[0].rstrip() + " = ..."
        out.append(p)
    return ", ".join(out)


def stub_of(name, function, split_top, indent="", decorator=None):
    """`def name(...) -> T: ...` lines from the first docstring line(s) (one per overload)."""
    doc = getattr(function, "__doc__", None) or ""
    found = re.findall(r"^(?:\d+\. )?" + re.escape(name) + r"\((.*)\)(?: -> (.+))?$", doc, re.M)
    if not found:
        return [f"{indent}def {name}(*args: Any, **kwargs: Any) -> Any: ..."]
    lines = []
    overloads = len(found) > 1
    for params, returns in found:
        if overloads:
            lines.append(f"{indent}@overload")
        if decorator:
            lines.append(f"{indent}{decorator}")
        lines.append(f"{indent}def {name}({clean(defaults_as_ellipsis(params, split_top))}) -> "
                     f"{clean(returns) if returns else 'Any'}: ...")
    return lines


def main(package_dir):
    built = [f for f in os.listdir(package_dir) if f.startswith("_fogdrift") and f.endswith(".so")]
    if not built:
        sys.exit(f"{package_dir}: no _fogdrift module")
    module = load(package_dir, "fogdrift._fogdrift", built[0])
    # The splitter of a parameter list the keyword messages use (_keywords.py).
    split_top = load(package_dir, "fogdrift_keywords", "_keywords.py")._split_top
    lines = [HEADER.rstrip("\n"), "from typing import overload", "",
             "__version__: str", ""]
    for name, value in sorted(vars(module).items()):
        if name.startswith("__"):
            continue
        if inspect.isclass(value):
            lines.append(f"class {name}:")
            body = []
            for attr, member in sorted(vars(value).items()):
                if attr.startswith("__") and attr not in ("__init__", "__call__"):
                    continue
                if isinstance(member, property):
                    body.append(f"    @property\n    def {attr}(self) -> Any: ...")
                elif isinstance(member, staticmethod) or type(member).__name__ == "staticmethod":
                    body += stub_of(attr, getattr(value, attr), split_top, "    ", "@staticmethod")
                elif callable(member):
                    body += stub_of(attr, member, split_top, "    ")
            lines += body or ["    ..."]
            lines.append("")
        elif callable(value):
            lines += stub_of(name, value, split_top)
            lines.append("")
    fd, tmp = tempfile.mkstemp(dir=package_dir)
    with os.fdopen(fd, "w") as f:
        f.write("\n".join(lines).rstrip("\n") + "\n")
    os.replace(tmp, os.path.join(package_dir, "_fogdrift.pyi"))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
