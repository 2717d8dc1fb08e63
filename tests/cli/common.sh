# Shared by the CLI test scripts: a scratch folder and the check/run helpers.
# Sourced after setting fd (the fogdrift binary) and data (tests/data).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0

check() {  # check NAME CONDITION-COMMAND...
  local name=$1
  shift
  if "$@"; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAILED: $name" >&2
  fi
}

# run EXPECTED_STATUS CMD... : runs, keeps stdout/stderr in $work/out, $work/err
run() {
  local expected=$1
  shift
  "$@" >"$work/out" 2>"$work/err"
  local status=$?
  if [ "$status" -ne "$expected" ]; then
    echo "  '$*' exited $status, expected $expected; stderr:" >&2
    sed 's/^/    /' "$work/err" >&2
    return 1
  fi
}
err_has() { grep -qF -- "$1" "$work/err" || { echo "  stderr lacks: $1" >&2; sed 's/^/    /' "$work/err" >&2; return 1; }; }
out_has() { grep -qF -- "$1" "$work/out" || { echo "  stdout lacks: $1" >&2; return 1; }; }

