#!/usr/bin/env bash
# The CCD speed/accuracy trade: every method on every data set, in one run, as JSON lines
# (one per method, data set and round) on stdout. Usage:
#   scripts/ccd-trade.sh [DATA_DIR] > trade.jsonl
# DATA_DIR defaults to ../shared/data/ccd (falls back to the bundled tests/data/ccd).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
data="${1:-$here/../shared/data/ccd}"
[ -d "$data" ] || data="$here/tests/data/ccd"
exe="$here/build/bin/exactgeo"
# Three rounds, the methods in rotation within each, so that every method meets the
# shared machine's quiet and busy moments; the report keeps each method's fastest round.
for round in 1 2 3; do
  for set in sample-queries scalable-ccd-data; do
    [ -d "$data/$set" ] || continue
    for method in exact parity double cubic rational; do
      # The fastest of 3 timing passes per file; the slow rational reference runs once.
      repeat=3
      if [ "$method" = rational ]; then
        [ "$round" = 1 ] || continue
        repeat=1
      fi
      line=$("$exe" ccd --json --repeat "$repeat" --method "$method" "$data/$set" || true)
      printf '{"data": "%s", %s\n' "$set" "${line#\{}"
    done
  done
done
