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
    line=$("$exe" ccd --json --method "$method" "$data/$set" || true)
    printf '{"data": "%s", %s\n' "$set" "${line#\{}"
  done
done
