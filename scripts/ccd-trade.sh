#!/usr/bin/env bash
# The CCD speed/accuracy trade: every method on every data set, in one run, as JSON lines
# (one per method and data set) on stdout. Usage:
#   scripts/ccd-trade.sh [DATA_DIR] > trade.jsonl
# DATA_DIR defaults to ../shared/data/ccd (falls back to the bundled tests/data/ccd).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
data="${1:-$here/../shared/data/ccd}"
[ -d "$data" ] || data="$here/tests/data/ccd"
exe="$here/build/bin/exactgeo"
for set in sample-queries scalable-ccd-data; do
  [ -d "$data/$set" ] || continue
  for method in exact parity double cubic rational; do
    # The fastest of 5 timing passes per file (1 for the slow rational reference).
    repeat=5
    [ "$method" = rational ] && repeat=1
    line=$("$exe" ccd --json --repeat "$repeat" --method "$method" "$data/$set" || true)
    printf '{"data": "%s", %s\n' "$set" "${line#\{}"
  done
done
