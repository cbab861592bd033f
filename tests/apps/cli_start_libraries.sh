#!/usr/bin/env bash
# The libraries the exactgeo binary needs at start (its ELF NEEDED entries): none of those
# it opens on first use (Embree and its TBB, assimp), whose loading at every start was most
# of a short command's time (docs/inside.md, "End to end").
set -u
exe="$1"
needed=$(objdump -p "$exe" | awk '$1 == "NEEDED" { print $2 }')
if [ -z "$needed" ]; then
  echo "FAIL: no NEEDED entries read from $exe"
  exit 1
fi
failures=0
for library in embree tbb assimp; do
  if printf '%s\n' "$needed" | grep -q "$library"; then
    echo "FAIL: $exe needs $(printf '%s\n' "$needed" | grep "$library" | tr '\n' ' ')at start"
    failures=$((failures + 1))
  fi
done
[ "$failures" = 0 ] && echo "needed at start: $(printf '%s\n' "$needed" | tr '\n' ' ')"
exit "$failures"
