#!/usr/bin/env bash
# make run: runs every SDNL111 input, then writes results/report.md with plots.
# usage: tools/build/run-suite.sh [BUILD_DIR]
set -uo pipefail
top="$(cd "$(dirname "$0")/../.." && pwd)"
build="${1:-$top/build}"
cd "$top"
mkdir -p results
status=0
# The SDNL111 inputs plus the configurations beyond the reference.
for input in input/sdnl111?.xml input/sdnl111a_rigid.xml input/sdnl111c_accurate.xml; do
  name=$(basename "$input" .xml)
  echo "== $name"
  "$build/choc" run "$input" -o "results/$name" > "results/$name.log" 2>&1
  rc=$?
  grep -E "checks|NOOK|exact solution|unknowns;|done in|error" "results/$name.log" | grep -v "step " || true
  echo "   exit code $rc (log: results/$name.log)"
  if [ $rc -eq 3 ] && ! grep ",NOOK," "results/$name/checks.csv" | grep -vq "known inconsistency"; then
    # Every failing row is a documented inconsistency of the document
    # (docs/verification/benchmarks.md, "The document's tables against the exact solution").
    echo "   the only NOOK rows are the document's known inconsistencies (see their note)"
  elif [ $rc -ne 0 ]; then
    status=1
  fi
done
if [ -x "$top/tools/report/make_report.py" ]; then
  /usr/bin/python3 "$top/tools/report/make_report.py" results || status=1
fi
# ParaView views of the transient results (results/paraview/); optional, never fails the run.
if command -v pvbatch >/dev/null 2>&1 && command -v xvfb-run >/dev/null 2>&1; then
  xvfb-run -a pvbatch "$top/tools/report/paraview_views.py" results > results/paraview.log 2>&1 \
    && echo "ParaView views in results/paraview/ (log: results/paraview.log)" \
    || echo "warning: ParaView views failed (see results/paraview.log)"
else
  echo "ParaView views skipped: pvbatch or xvfb-run not found (make deps installs them)"
fi
exit $status
