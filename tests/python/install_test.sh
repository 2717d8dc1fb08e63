#!/usr/bin/env bash
# The Python package as a user installs it (docs/python.md, "Install"): pip into a fresh virtual
# environment (--system-site-packages for NumPy and scikit-learn, no network), then the package's
# tests run from outside the source tree against what was installed; and python3 -m build to a
# wheel that installs into a second environment. The extension is built in BUILD (already built
# by the suite, so not again).
# Usage: install_test.sh PYTHON3 SOURCE_DIR BUILD_DIR FOGDRIFT_CLI
set -u
py=$1
root=$2
build=$3
cli=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
fail() { echo "FAILED: $*" >&2; failed=1; }
export FOGDRIFT_CMAKE_BUILD_DIR=$build PIP_NO_INDEX=1 PIP_DISABLE_PIP_VERSION_CHECK=1
unset PYTHONPATH
cd "$work" || exit 1

"$py" -m venv --system-site-packages "$work/venv" || fail "venv"
"$work/venv/bin/pip" install -q --no-build-isolation --no-deps "$root" >"$work/pip.log" 2>&1 ||
  { cat "$work/pip.log" >&2; fail "pip install"; }
where=$("$work/venv/bin/python" -c "import fogdrift; print(fogdrift.__file__)")
case $where in
  "$work/venv/"*) ;;
  *) fail "fogdrift imported from $where, not from the environment" ;;
esac
expected=$(sed -n 's/.*kVersion = "\([0-9.]*\)".*/\1/p' "$root/include/fogdrift/base/version.hpp")
got=$("$work/venv/bin/python" -c "import fogdrift; print(fogdrift.__version__)")
[ "$got" = "$expected" ] || fail "version $got, not version.hpp's $expected"
got=$("$work/venv/bin/pip" show fogdrift 2>/dev/null | sed -n 's/^Version: //p')
[ "$got" = "$expected" ] || fail "pip says version $got, not $expected"
# The tests of the model files and the scikit-learn estimator, against the installed package
# (not the byte-for-byte training against the command line, a minute of the same code the
# python test runs on the built package).
FOGDRIFT_CLI=$cli "$work/venv/bin/python" -m pytest -q -p no:cacheprovider -k "not byte_for_byte" \
  "$root/tests/python/test_model.py" "$root/tests/python/test_svr.py" >"$work/pytest.log" 2>&1 ||
  { tail -30 "$work/pytest.log" >&2; fail "pytest against the installed package"; }
grep -q "passed" "$work/pytest.log" || fail "pytest ran nothing"

# A wheel, when python3-build is there (scripts/setup.sh installs it).
if "$py" -c "import build" 2>/dev/null; then
  (cd "$root" && "$py" -m build --no-isolation --wheel --outdir "$work/dist" . >"$work/build.log" 2>&1) ||
    { tail -20 "$work/build.log" >&2; fail "python3 -m build"; }
  "$py" -m venv --system-site-packages "$work/venv2" || fail "venv2"
  "$work/venv2/bin/pip" install -q --no-deps "$work"/dist/fogdrift-*.whl >"$work/pip2.log" 2>&1 ||
    { cat "$work/pip2.log" >&2; fail "pip install the wheel"; }
  "$work/venv2/bin/python" -c "import fogdrift, numpy as np; m = fogdrift.SVR(C=1.0).fit(np.eye(3), [1.0, 2.0, 3.0]); assert m.predict(np.eye(3)).shape == (3,)" ||
    fail "the wheel's package does not fit an SVR"
  # Types: py.typed and the compiled module's stub are in the wheel.
  for f in py.typed _fogdrift.pyi; do
    "$py" -c "import sys, zipfile; names = zipfile.ZipFile(sys.argv[1]).namelist(); sys.exit('fogdrift/$f' not in names)" \
      "$work"/dist/fogdrift-*.whl || fail "the wheel lacks fogdrift/$f"
  done
else
  fail "python3-build is missing (scripts/setup.sh installs it)"
fi
# An environment without the 'wheel' package (one made from another interpreter, say): pip's
# build stops with what to do, not setuptools' "invalid command 'bdist_wheel'".
"$py" -m venv "$work/bare" || fail "bare venv"
if ! "$work/bare/bin/python" -c "import wheel" 2>/dev/null; then
  "$work/bare/bin/pip" install -q --no-build-isolation --no-deps "$root" >"$work/bare.log" 2>&1 &&
    fail "pip install without 'wheel' succeeded"
  grep -q "building a wheel needs the 'wheel' package" "$work/bare.log" ||
    { tail -5 "$work/bare.log" >&2; fail "no word on the missing 'wheel' package"; }
fi
[ "$failed" -eq 0 ] && echo "python install: passed"
exit "$failed"
