#!/usr/bin/env bash
# Runs one regression case: regression/<case>/case.cfg names the input and what it requires.
# usage: tools/build/regression-case.sh CHOC CASE_DIR OUT_DIR [serial|mpi2|baseline-update]
#   serial  (default): the run must exit 0 (every declared check OK), checks.csv must hold the
#           expected number of rows, and each history listed in the case must match its
#           baseline (regression/<case>/baseline/*.csv) to the case's baseline tolerance.
#   mpi2:   runs on 2 MPI ranks and compares every history with the serial run's (which must
#           exist in OUT_DIR/serial) to the case's rank tolerance.
#   baseline-update: rewrites the baselines from OUT_DIR/serial (explicit, never automatic).
set -euo pipefail
choc="$1"; case_dir="$2"; out="$3"; mode="${4:-serial}"
here="$(cd "$(dirname "$0")" && pwd)"
cfg="$case_dir/case.cfg"
[ -f "$cfg" ] || { echo "regression: missing $cfg"; exit 1; }
# shellcheck disable=SC1090
RANK_COLUMNS=""  # optional in case.cfg: the columns compared across ranks (default: all)
source "$cfg"   # sets INPUT, CHECKS, HISTORIES, BASELINE_COLUMNS, BASELINE_RTOL, RANK_RTOL
input="$case_dir/../../$INPUT"
case "$mode" in
  serial)
    rm -rf "$out/serial"
    set +e
    "$choc" run "$input" -o "$out/serial" > "$out/serial.log" 2>&1
    rc=$?
    set -e
    tail -n 40 "$out/serial.log"
    [ "$rc" -eq 0 ] || { echo "regression: choc exited $rc (0 expected)"; exit 1; }
    rows=$(($(wc -l < "$out/serial/checks.csv") - 1))
    [ "$rows" -eq "$CHECKS" ] || { echo "regression: $rows check rows, $CHECKS expected"; exit 1; }
    if grep -q ",NOOK," "$out/serial/checks.csv"; then echo "regression: NOOK rows"; exit 1; fi
    for h in $HISTORIES; do
      base="$case_dir/baseline/$h.history.csv"
      [ -f "$base" ] || { echo "regression: missing baseline $base (tools/build/update-baselines.sh)"; exit 1; }
      echo "baseline $h:"
      python3 "$here/../oracles/compare_histories.py" "$base" "$out/serial/$h.history.csv" \
        --columns "$BASELINE_COLUMNS" --rtol-peak "$BASELINE_RTOL"
    done
    ;;
  mpi2)
    [ -d "$out/serial" ] || { echo "regression: run the serial case first"; exit 1; }
    rm -rf "$out/mpi2"
    mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1 -np 2 "$choc" run "$input" -o "$out/mpi2" \
      > "$out/mpi2.log" 2>&1 || { tail -n 20 "$out/mpi2.log"; echo "regression: 2-rank run failed"; exit 1; }
    for h in $HISTORIES; do
      echo "2 ranks vs 1 rank, $h:"
      python3 "$here/../oracles/compare_histories.py" "$out/serial/$h.history.csv" "$out/mpi2/$h.history.csv" \
        --rtol-peak "$RANK_RTOL" ${RANK_COLUMNS:+--columns "$RANK_COLUMNS"}
    done
    ;;
  baseline-update)
    mkdir -p "$case_dir/baseline"
    for h in $HISTORIES; do
      # Every 10th row of the probed columns: enough to catch any change, small to keep.
      python3 - "$out/serial/$h.history.csv" "$case_dir/baseline/$h.history.csv" "$BASELINE_COLUMNS" <<'PY'
import csv, sys
src, dst, cols = sys.argv[1], sys.argv[2], sys.argv[3].split(",")
rows = list(csv.reader(open(src, newline="")))
idx = [0] + [rows[0].index(c) for c in cols]
with open(dst, "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    for i, r in enumerate(rows):
        if i == 0 or (i - 1) % 10 == 0:
            w.writerow([r[j] for j in idx])
PY
      echo "baseline updated: $case_dir/baseline/$h.history.csv"
    done
    ;;
  *) echo "regression: unknown mode $mode"; exit 1 ;;
esac
