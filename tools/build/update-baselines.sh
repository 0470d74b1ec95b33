#!/usr/bin/env bash
# Rewrites the non-regression baselines of the named cases (or all) from fresh serial runs.
# Baselines change only through this command; say why in the commit that records them.
# usage: tools/build/update-baselines.sh [BUILD_DIR] [case ...]
set -euo pipefail
top="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$top/build}"; shift || true
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=($(cd "$top/regression" && ls -d */ | tr -d / | grep -v extremes))
for c in "${cases[@]}"; do
  out="$build/regression/$c"
  mkdir -p "$out"
  "$top/tools/build/regression-case.sh" "$build/choc" "$top/regression/$c" "$out" serial >/dev/null 2>&1 || true
  [ -d "$out/serial" ] || { echo "update-baselines: $c did not run"; exit 1; }
  "$top/tools/build/regression-case.sh" "$build/choc" "$top/regression/$c" "$out" baseline-update
done
