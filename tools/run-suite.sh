#!/usr/bin/env bash
# make run: runs every SDNL111 input, then writes results/report.md with plots.
# usage: tools/run-suite.sh [BUILD_DIR]
set -uo pipefail
top="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$top/build}"
cd "$top"
status=0
for input in input/sdnl111?.xml; do
  name=$(basename "$input" .xml)
  echo "== $name"
  "$build/choc" run "$input" -o "results/$name" > "results/$name.log" 2>&1
  rc=$?
  grep -E "checks|NOOK|exact solution|unknowns;|done in|error" "results/$name.log" | grep -v "step " || true
  echo "   exit code $rc (log: results/$name.log)"
  [ $rc -eq 0 ] || status=1
done
if [ -x "$top/tools/make_report.py" ]; then
  python3 "$top/tools/make_report.py" results || status=1
fi
# ParaView views of the transient results (results/paraview/); optional, never fails the run.
if command -v pvbatch >/dev/null 2>&1 && command -v xvfb-run >/dev/null 2>&1; then
  xvfb-run -a pvbatch "$top/tools/paraview_views.py" results > results/paraview.log 2>&1 \
    && echo "ParaView views in results/paraview/ (log: results/paraview.log)" \
    || echo "warning: ParaView views failed (see results/paraview.log)"
else
  echo "ParaView views skipped: pvbatch or xvfb-run not found (make deps installs them)"
fi
exit $status
