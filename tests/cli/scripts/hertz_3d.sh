#!/bin/sh
# Hertz in 3D (BENCHMARKS section 2): runs input/hertz_3d.xml (the quarter sphere) and measures
# it against Hertz's closed form with tools/hertz.py, the force, impulse and mass being a
# quarter of the whole sphere's (its exit status is the test's).
# usage: hertz_3d.sh CHOC SOURCE_DIR WORK_DIR
set -e
choc="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
"$choc" run "$src/input/hertz_3d.xml" -o "$work/impact" > "$work/impact.log" 2>&1
/usr/bin/python3 "$src/tools/hertz.py" "$work/impact" --analysis explicit --fraction 0.25 \
  --plot "$work/force_history.png"
