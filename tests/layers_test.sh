#!/usr/bin/env bash
# The CTest test `layers`: the library's includes go only down docs/architecture.md's layer
# table (scripts/check_layers.py), and the check fails where it must: on a copy of the tree with
# an upward include, a folder without a row, and a row that allows a layer below it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
check=$root/scripts/check_layers.py
python3 "$check" "$root"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fresh() { # a copy of what the check reads
  rm -rf "$work/t"
  mkdir -p "$work/t/docs" "$work/t/include"
  cp "$root/docs/architecture.md" "$work/t/docs/"
  cp -r "$root/src" "$work/t/"
  cp -r "$root/include/fogdrift" "$work/t/include/"
}
expect_failure() { # $1: what the message must say
  if python3 "$check" "$work/t" 2>"$work/err"; then
    echo "layers_test: the check passed a tree where it must fail ($1)" >&2
    exit 1
  fi
  grep -qF -- "$1" "$work/err" || {
    echo "layers_test: expected '$1' in:" >&2
    cat "$work/err" >&2
    exit 1
  }
}
fresh
sed -i '0,/^#include "/s//#include "fogdrift\/train\/tune.hpp"\n#include "/' "$work/t/src/svr/smo.hpp"
expect_failure "src/svr/smo.hpp:"
expect_failure "layer svr includes fogdrift/train/tune.hpp (layer train)"
fresh
mkdir "$work/t/src/stray" "$work/t/include/fogdrift/stray"
expect_failure "src/stray/: a folder of the library with no row"
fresh
sed -i 's/^| `svr\/` | \(.*\) | base |$/| `svr\/` | \1 | base, train |/' "$work/t/docs/architecture.md"
expect_failure "layer svr may include train, drawn at or below it"
fresh
sed -i '0,/^#include "/s//#include "apps\/fogdrift\/command.hpp"\n#include "/' "$work/t/src/base/error.cpp"
expect_failure "a front end"
echo "layers_test: the check passes the tree and fails each broken copy"
