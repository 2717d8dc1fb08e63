#!/usr/bin/env bash
# The CTest test `includes`: every library source and every public header compiles alone
# (`-fsyntax-only`), so none leans on an include that another file of its unity batch happens
# to bring in. Builds are unity builds (docs/architecture.md): a missing include there shows up
# only once a new file shifts the batches, in someone else's change.
# Usage: includes_test.sh CXX BUILD_DIR (the build folder holds the embedded C step).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cxx=${1:?the C++ compiler}
build=${2:?the build folder}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags=(-std=c++20 -fsyntax-only -I"$root/include" -I"$root/src"
  -I"$build/src/embedded" -isystem /usr/include/eigen3)

# A header alone: a file that includes it and nothing else. A header whose source file includes
# it first (the rule of docs/architecture.md: include/fogdrift/L/N.hpp first in src/L/N.cpp) is
# compiled alone with that source already, so only the others need a file of their own.
while IFS= read -r h; do
  rel=${h#"$root/include/"}
  src=$root/src/${rel#fogdrift/}
  src=${src%.hpp}.cpp
  if [ -f "$src" ] && [ "$(grep -m1 '^#include' "$src")" = "#include \"$rel\"" ]; then continue; fi
  printf '#include "%s"\n' "$rel" >"$work/$(echo "$rel" | tr '/.' '__').cpp"
done < <(find "$root/include/fogdrift" -name '*.hpp' | sort)

# A source the build compiled on its own, outside any unity batch (one with options of its own,
# or every source of a build without batches), has an object file of its own newer than it: it
# is proven already.
list=$work/files
{
  find "$root/src" -name '*.cpp' | sort | while IFS= read -r f; do
    [ "$build/src/CMakeFiles/fogdrift.dir/${f#"$root/src/"}.o" -nt "$f" ] || echo "$f"
  done
  find "$work" -name '*.cpp' | sort
} >"$list"
export CXX_FLAGS="${flags[*]}" CXX="$cxx" WORK="$work"
# One compiler a core; each failure names its file and the compiler's first errors (kept in the
# scratch folder, never beside the source).
if ! xargs -P "$(nproc)" -I{} bash -c 'err=$WORK/$(printf %s "$1" | tr / _).err
    $CXX $CXX_FLAGS "$1" 2>"$err" || {
    echo "includes: $1 does not compile alone:"; head -20 "$err"; exit 255; }' _ {} <"$list" \
    >"$work/out" 2>&1; then
  cat "$work/out"
  exit 1
fi
echo "includes: $(wc -l <"$list") files compile alone (sources the build compiled alone not again)"
