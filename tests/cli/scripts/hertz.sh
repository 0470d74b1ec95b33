#!/bin/sh
# Hertz (docs/verification/hertz.md): runs input/hertz.xml and input/hertz_static.xml and measures
# them against Hertz's closed form with tools/oracles/hertz.py (its exit status is the test's).
# usage: hertz.sh CHOC SOURCE_DIR WORK_DIR
set -e
choc="$1"; src="$2"; work="$3"
rm -rf "$work"; mkdir -p "$work"
"$choc" run "$src/input/hertz_static.xml" -o "$work/static" > "$work/static.log" 2>&1
/usr/bin/python3 "$src/tools/oracles/hertz.py" --static "$work/static"
"$choc" run "$src/input/hertz.xml" -o "$work/impact" > "$work/impact.log" 2>&1
/usr/bin/python3 "$src/tools/oracles/hertz.py" "$work/impact" --plot "$work/force_history.png"
