#!/bin/sh
# Regenerates the parameter reference from the declarations in the source:
#   BUILD_DIR/choc parameters --format markdown > OUT_FILE
# usage: tools/docs/parameters_reference.sh BUILD_DIR OUT_FILE
#   e.g. tools/docs/parameters_reference.sh build docs/reference/parameters.md
# The ctest test docs.parameters_reference_current fails while the committed file differs.
set -eu
if [ $# -ne 2 ]; then
  echo "usage: $0 BUILD_DIR OUT_FILE (e.g. $0 build docs/reference/parameters.md)" >&2
  exit 1
fi
choc="$1/choc"
out="$2"
if [ ! -x "$choc" ]; then
  echo "$0: $choc is not an executable: build choc first (make build)" >&2
  exit 1
fi
mkdir -p "$(dirname "$out")"
tmp="$out.tmp.$$"
trap 'rm -f "$tmp"' EXIT
"$choc" parameters --format markdown > "$tmp"
mv "$tmp" "$out"
echo "wrote $out"
