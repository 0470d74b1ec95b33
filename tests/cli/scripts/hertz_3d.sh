#!/bin/sh
# Hertz in 3D (docs/verification/hertz.md): runs input/hertz_3d.xml (the quarter sphere) and measures
# it against Hertz's closed form with tools/oracles/hertz.py, the force, impulse and mass being a
# quarter of the whole sphere's (its exit status is the test's). Then on 2 ranks: every history
# equals the 1-rank one to 1e-8 of its peak (docs/verification/properties.md), but the energy balance, a
# difference of energies of E0 = 0.1 J whose extreme is round-off (about -4e-8 J).
# usage: hertz_3d.sh CHOC SOURCE_DIR WORK_DIR
set -e
choc="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
"$choc" run "$src/input/hertz_3d.xml" -o "$work/impact" > "$work/impact.log" 2>&1
/usr/bin/python3 "$src/tools/oracles/hertz.py" "$work/impact" --analysis explicit --fraction 0.25 \
  --plot "$work/force_history.png"
mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1 -np 2 "$choc" run "$src/input/hertz_3d.xml" \
  -o "$work/impact_np2" > "$work/impact_np2.log" 2>&1
/usr/bin/python3 "$src/tools/oracles/compare_histories.py" "$work/impact/explicit.history.csv" \
  "$work/impact_np2/explicit.history.csv" --rtol-peak 1e-8 \
  --columns "C:DY,C:VY,O:DY,energy:kinetic,energy:strain,energy:total,plane:force,plane:gap,plane:area"
