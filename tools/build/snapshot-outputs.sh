#!/usr/bin/env bash
# Runs every input (input/*.xml and regression/extremes/*.xml, whose meshes `choc mesh` writes
# beside copies of them in OUT_DIR/extremes-inputs) into one directory, two at a time, to hold a
# reshaping's outputs against the build before it:
#   tools/build/snapshot-outputs.sh OLD/choc /tmp/before; (change, build)
#   tools/build/snapshot-outputs.sh build/choc /tmp/after
#   tools/oracles/same_outputs.py /tmp/before /tmp/after
# usage: tools/build/snapshot-outputs.sh CHOC OUT_DIR [INPUT.xml ...]
#   OUT_DIR/<input name>/ holds each run's files, OUT_DIR/<input name>.log its log and exit code.
set -uo pipefail
choc="$(realpath "$1")"; out="$2"; shift 2
top="$(cd "$(dirname "$0")/../.." && pwd)"
inputs=("$@")
mkdir -p "$out"
if [ ${#inputs[@]} -eq 0 ]; then
  ext="$out/extremes-inputs"
  mkdir -p "$ext"
  cp "$top"/regression/extremes/*.xml "$ext/"
  # The meshes regression/extremes/CMakeLists.txt gives each case.
  while read -r name args; do
    # shellcheck disable=SC2086
    "$choc" mesh $args -o "$ext/$name" > /dev/null || { echo "snapshot: choc mesh $args failed"; exit 1; }
  done <<'MESHES'
bars1d_10.exo --dim 1 --along1 10 --along2 10 --gap 1e-5
bars1d_10_gap1e-3.exo --dim 1 --along1 10 --along2 10 --gap 1e-3
bars1d_10_gap1e-2.exo --dim 1 --along1 10 --along2 10 --gap 1e-2
bars3d_10.exo --dim 3 --axis z --along1 10 --along2 10 --gap 1e-5
bars3d_10_gap0.exo --dim 3 --axis z --along1 10 --along2 10 --gap 0
bars3d_10_gapneg.exo --dim 3 --axis z --along1 10 --along2 10 --gap -1e-6
sdnl111b_1d.exo --dim 1 --axis x --along1 50 --along2 50 --gap 1e-5 --shift-a -1.1e-5
MESHES
  inputs=("$top"/input/*.xml "$ext"/*.xml)
fi
run_one() {
  local choc="$1" out="$2" input="$3" name start rc
  name=$(basename "$input" .xml)
  rm -rf "$out/$name"
  start=$(date +%s)
  "$choc" run "$input" -o "$out/$name" > "$out/$name.log" 2>&1
  rc=$?
  echo "exit $rc in $(( $(date +%s) - start )) s" >> "$out/$name.log"
  echo "$name: exit $rc in $(( $(date +%s) - start )) s"
}
export -f run_one
printf '%s\n' "${inputs[@]}" | xargs -P 2 -I{} bash -c 'run_one "$@"' _ "$choc" "$out" {}
