#!/usr/bin/env bash
# Generates the mesh of input/scale-3d.xml (not committed: 5 MB): the SDNL111 two-bar scene
# with ACROSS x ACROSS HEX8 across each 0.02 x 0.02 section and ALONG along each 1 m bar, axis z.
# Default 9 x 9 x 500 per bar: 100,200 nodes, 81,000 elements, 300,300 unknowns once the
# clamped face D is removed (3 DOFs per node, lateral displacements free).
# usage: tools/build/make-scale-mesh.sh [path/to/choc] [ACROSS] [ALONG] [OUTPUT.exo]
#   (defaults: build/choc 9 500 meshes/scale_3d.exo; skipped when OUTPUT exists and is newer
#    than choc, unless FORCE=1)
set -euo pipefail
top="$(cd "$(dirname "$0")/../.." && pwd)"
choc="${1:-$top/build/choc}"
across="${2:-9}"
along="${3:-500}"
out="${4:-$top/meshes/scale_3d.exo}"
if [ "${FORCE:-0}" != 1 ] && [ -s "$out" ] && [ "$out" -nt "$choc" ] && [ $# -lt 2 ]; then
  echo "make-scale-mesh: $out is up to date"
  exit 0
fi
# Node numbering of the generator: bar 1 layer by layer from its contact face A to B, then
# bar 2 from its contact face C to the clamped end D. Ranks own contiguous node ranges
# (src/fem/DofMap.cpp), so each rank owns a slab of whole layers along the axis (plus at
# most one partial layer): a geometric partition along the bars.
"$choc" mesh --dim 3 --axis z --along1 "$along" --along2 "$along" --across1 "$across" \
  --across2 "$across" --width 0.02 --height 0.02 --gap 1e-5 -o "$out"
