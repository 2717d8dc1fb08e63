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
        subprocess.run(["cmake", "--build", str(build), "--target", "_fogdrift", "--parallel",
                        str(os.cpu_count() or 1)], check=True)
        built = sorted((build / "python" / "fogdrift").glob("_fogdrift*.so"))
        if not built:
            raise RuntimeError(f"{build}: the CMake build made no _fogdrift module")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[-1], target)


setup(
    version=version(),
    ext_modules=[Extension("fogdrift._fogdrift", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(ROOT / "build-python" / "setuptools")},
             "egg_info": {"egg_base": str(ROOT / "build-python")}},
)
