#!/bin/sh
# "choc parameters" documents every key: it exits 0; every parameter it lists (a line
# "<name> (<type>, ...)") is followed by a non-empty documentation line; and every parameter
# name used in the given inputs appears in the listing.
# usage: parameters_documented.sh CHOC INPUT.xml...
set -u
choc="$1"; shift
listing=$(mktemp)
trap 'rm -f "$listing"' EXIT
"$choc" parameters > "$listing" 2>&1
rc=$?
[ "$rc" -eq 0 ] || { echo "choc parameters exited $rc"; cat "$listing"; exit 1; }
# Each parameter line must be followed by an indented, non-blank documentation line.
awk '
  pending { if ($0 !~ /^ +[^ ]/) { print "undocumented: " prev; bad = 1 } pending = 0 }
  /^ *[^ <][^(]* \((double|int|bool|string)[,;]/ { prev = $0; pending = 1; n++ }
  END { if (pending) { print "undocumented: " prev; bad = 1 }
        if (n < 20) { print "only " n " parameters listed"; bad = 1 }
        exit bad }' "$listing" || exit 1
status=0
for f in "$@"; do
  for name in $(sed -n 's/.*<Parameter name="\([^"]*\)".*/\1/p' "$f" | tr ' ' '~' | sort -u); do
    key=$(printf '%s' "$name" | tr '~' ' ')
    if ! grep -q -F -- "$key (" "$listing"; then
      echo "$f: parameter '$key' is not in 'choc parameters'"
      status=1
    fi
  done
done
[ "$status" -eq 0 ] && echo "parameters_documented: OK"
exit $status
