#!/bin/sh
# Modal run of input/sdnl111a.xml: exit 0, "101 unknowns" in the log, modes.exo and
# modes.modes.csv written, 40 modes, mode 1 the free bar's rigid-body mode (|f| < 1 Hz), mode 2
# the clamped-free bar's first mode c/(4L) within the discretisation bound of linear elements
# with consistent mass (tests/unit/test_solvers_bar_frequencies.cpp derives it):
#   c/(4L) <= f_h <= c/(4L) (1 + t^2/24 (1 + t^2/80)),  t = k h = (pi/(2L)) (L/50) = pi/100,
# both ends widened by the eigen-solve accuracy 1e-8. c = sqrt(E/rho), E = 2e11, rho = 7800,
# L = 1 (the values of input/sdnl111a.xml and its mesh: 50 uniform elements per bar).
# usage: modal_run.sh CHOC INPUT OUT_DIR
set -u
choc="$1"; input="$2"; out="$3"
rm -rf "$out"
mkdir -p "$(dirname "$out")"
"$choc" run "$input" -o "$out" > "$out.log" 2>&1
rc=$?
fail() { echo "modal_run: $*"; echo "--- log (last 40 lines):"; tail -n 40 "$out.log"; exit 1; }
[ "$rc" -eq 0 ] || fail "choc exited $rc, expected 0"
grep -q "101 unknowns" "$out.log" || fail "the log does not state '101 unknowns'"
[ -s "$out/modes.exo" ] || fail "no $out/modes.exo"
csv="$out/modes.modes.csv"
[ -s "$csv" ] || fail "no $csv"
head -n 1 "$csv" | grep -q "^mode,frequency_hz" || fail "unexpected header in $csv"
rows=$(($(wc -l < "$csv") - 1))
[ "$rows" -eq 40 ] || fail "$rows modes in $csv, 40 expected"
awk -F, 'NR == 2 { f1 = $2 } NR == 3 { f2 = $2 } END {
  pi = atan2(0, -1); c = sqrt(2e11 / 7800); f = c / 4; t = pi / 100;
  lo = f * (1 - 1e-8); hi = f * (1 + t * t / 24 * (1 + t * t / 80)) * (1 + 1e-8);
  printf "mode 1: %.6f Hz (rigid, |f| < 1); mode 2: %.6f Hz in [%.6f, %.6f]\n", f1, f2, lo, hi;
  if (!(f1 < 1 && f1 > -1)) { print "mode 1 is not the rigid-body mode"; exit 1 }
  if (!(f2 >= lo && f2 <= hi)) { print "mode 2 outside the bound"; exit 1 }
}' "$csv" || fail "frequency check failed"
echo "modal_run: OK"
