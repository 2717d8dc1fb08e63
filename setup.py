"""Builds fogdrift's extension module with CMake for pip and python3 -m build (pyproject.toml).

The extension is the target _fogdrift of this tree's CMake project (python/CMakeLists.txt),
configured for the interpreter that runs the build. FOGDRIFT_CMAKE_BUILD_DIR names a CMake build
folder to build it in (and reuse: the test suite installs from its own build this way); without
it the build goes under build-python/.
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent

# pip builds a wheel through setuptools' bdist_wheel, which the 'wheel' package provides. A virtual
# environment of another interpreter than Debian's lacks it, and there is no PyPI to fetch it
# from: say so, instead of setuptools' "invalid command 'bdist_wheel'" (which pip's metadata step,
# dist_info, meets first).
if {"bdist_wheel", "dist_info"} & set(sys.argv):
    try:
        import wheel  # noqa: F401
    except ImportError:
        sys.exit(f"fogdrift: building a wheel needs the 'wheel' package, which {sys.executable} "
                 "lacks. Make the environment with Debian's interpreter and its packages: "
                 "/usr/bin/python3 -m venv --system-site-packages ENV (apt-get install "
                 "python3-wheel python3-venv), or install 'wheel' into it from a local copy; "
                 "then pip install --no-build-isolation . (docs/python.md, \"Install\")")


def version():
    """The one version, from include/fogdrift/base/version.hpp."""
    text = (ROOT / "include" / "fogdrift" / "base" / "version.hpp").read_text()
    found = re.search(r'kVersion = "([0-9]+\.[0-9]+\.[0-9]+)"', text)
    if not found:
        raise RuntimeError("include/fogdrift/base/version.hpp: no kVersion = \"X.Y.Z\"")
    return found.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = Path(os.environ.get("FOGDRIFT_CMAKE_BUILD_DIR") or ROOT / "build-python" / "cmake")
        if not (build / "CMakeCache.txt").exists():
            subprocess.run(
                ["cmake", "-S", str(ROOT), "-B", str(build), "-G", "Ninja",
                 "-DCMAKE_BUILD_TYPE=Release", "-DFOGDRIFT_BUILD_TESTS=OFF",
                 "-DFOGDRIFT_BUILD_BENCH=OFF", "-DFOGDRIFT_BUILD_PYTHON=ON",
                 f"-DPython_EXECUTABLE={sys.executable}"], check=True)
        subprocess.run(["cmake", "--build", str(build), "--target", "fogdrift_python", "--parallel",
                        str(os.cpu_count() or 1)], check=True)
        built = sorted((build / "python" / "fogdrift").glob("_fogdrift*.so"))
        if not built:
            raise RuntimeError(f"{build}: the CMake build made no _fogdrift module")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)
        # The compiled module's type stub, beside it (py.typed is package data).
        shutil.copyfile(build / "python" / "fogdrift" / "_fogdrift.pyi",
                        target.parent / "_fogdrift.pyi")


setup(
    version=version(),
    ext_modules=[Extension("fogdrift._fogdrift", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(ROOT / "build-python" / "setuptools")},
             "egg_info": {"egg_base": str(ROOT / "build-python")}},
)
