#!/usr/bin/env bash
# Benchmark (prints figures; not a test): wall time of each input, start-up included, best of
# N runs, and the per-step figures from the run log.
# usage: tools/bench.sh [BUILD_DIR] [N] [input ...]
set -uo pipefail
top="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$top/build}"; n="${2:-5}"; shift 2 2>/dev/null || shift $#
inputs=("$@")
[ ${#inputs[@]} -gt 0 ] || inputs=("$top"/input/sdnl111?.xml)
out=$(mktemp -d)
printf "%-14s %10s %10s   %s\n" input "best [s]" "median [s]" "per analysis (last run)"
for input in "${inputs[@]}"; do
  name=$(basename "$input" .xml)
  times=()
  for ((i = 0; i < n; i++)); do
    s=$EPOCHREALTIME
    "$build/choc" run "$input" -o "$out/$name" > "$out/$name.log" 2>&1
    e=$EPOCHREALTIME
    times+=("$(awk -v a="$s" -v b="$e" 'BEGIN { printf "%.4f", b - a }')")
  done
  sorted=($(printf "%s\n" "${times[@]}" | sort -g))
  best=${sorted[0]}; med=${sorted[$((n / 2))]}
  steps=$(grep -oE "[0-9.]+ us per step|done in [0-9.e-]+ s" "$out/$name.log" | tr '\n' ';' | cut -c1-160)
  printf "%-14s %10.3f %10.3f   %s\n" "$name" "$best" "$med" "$steps"
done
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
rm -rf "$out"
