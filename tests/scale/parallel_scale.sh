#!/usr/bin/env bash
# scale.mpi2_equals_serial: input/scale-3d.xml on a reduced mesh (3 x 3 x 40 HEX8 per bar,
# 3,888 unknowns, lateral motion free), 20 steps through the impact, on 1 and 2 MPI ranks
# (CG + additive Schwarz: one subdomain per rank), then the two histories must agree to the
# solver tolerances. Also checks the log reports unknowns, Krylov iterations and memory.
# usage: tests/scale/parallel_scale.sh CHOC OUTDIR
set -euo pipefail
choc="$1"; out="$2"
top="$(cd "$(dirname "$0")/../.." && pwd)"
mpi=(mpirun --allow-run-as-root --oversubscribe --mca mpi_yield_when_idle 1)
rm -rf "$out"; mkdir -p "$out"
"$top/tools/build/make-scale-mesh.sh" "$choc" 3 40 "$out/scale_small.exo" > /dev/null
sed -e 's|\.\./meshes/scale_3d\.exo|scale_small.exo|' \
    -e 's|name="End Time" type="double" value="[^"]*"|name="End Time" type="double" value="2e-5"|' \
    "$top/input/scale-3d.xml" > "$out/scale-small.xml"
grep -q 'scale_small.exo' "$out/scale-small.xml"
"$choc" run "$out/scale-small.xml" -o "$out/np1" > "$out/np1.log"
"${mpi[@]}" -np 2 "$choc" run "$out/scale-small.xml" -o "$out/np2" > "$out/np2.log"
for f in np1 np2; do
  grep -q " 3888 unknowns" "$out/$f.log" || { echo "FAIL: $f.log lacks '3888 unknowns'"; exit 1; }
  grep -q "Krylov iterations:" "$out/$f.log" || { echo "FAIL: $f.log lacks Krylov iterations"; exit 1; }
  grep -q "bytes per unknown" "$out/$f.log" || { echo "FAIL: $f.log lacks the memory line"; exit 1; }
done
# The contact must have acted (the slave nodes of the interface pushed).
python3 - "$out/np1/impact.history.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
f = max(abs(float(r["interface:force"])) for r in rows)
print(f"  peak contact force {f:.1f} N")
sys.exit(0 if f > 1000 else 1)
PY
# Solver tolerances: Newton 1e-8 on the residual; CG (1e-10 at most) stops each correction once
# it is a tenth of that (adaptive linear tolerance), so the ranks part at Newton's tolerance.
python3 "$top/tools/oracles/compare_histories.py" "$out/np1/impact.history.csv" \
  "$out/np2/impact.history.csv" --rtol-peak 1e-6
