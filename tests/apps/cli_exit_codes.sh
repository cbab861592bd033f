#!/usr/bin/env bash
# End-to-end checks of the exactgeo binary: exit codes, and nothing on stdout on error.
set -u
exe="$1"
examples="$2"
data="$3"
failures=0

expect() {  # expect <code> <description> <stdin> <args...>
  local code="$1" what="$2" input="$3"
  shift 3
  local out rc
  out=$(printf '%b' "$input" | "$exe" "$@" 2>/dev/null)
  rc=$?
  if [ "$rc" != "$code" ]; then
    echo "FAIL: $what: exit $rc, expected $code"
    failures=$((failures + 1))
  fi
  if [ "$code" = 2 ] && [ -n "$out" ]; then
    echo "FAIL: $what: printed to stdout on error: $out"
    failures=$((failures + 1))
  fi
}

expect 0 "help" "" --help
expect 0 "version" "" --version
expect 2 "no subcommand" ""
expect 2 "unknown subcommand" "" frobnicate
expect 2 "unknown predicate" "" predicate bogus
expect 2 "unknown option" "" predicate orient3d --bogus
expect 0 "subcommand help" "" predicate --help
expect 0 "orient3d" "0 0 0 1 0 0 0 1 0 0 0 1\n" predicate orient3d
expect 2 "orient3d NaN" "0 0 0 1 0 0 0 1 0 0 0 1\n0 0 0 1 0 0 0 1 0 0 0 nan\n" predicate orient3d
expect 2 "orient3d short line" "0 0 0 1\n" predicate orient3d
expect 2 "missing file" "" predicate orient3d /nonexistent/cases.txt
expect 0 "example file" "" predicate orient3d "$examples/orient3d.txt"
expect 0 "ray-patch example" "" predicate ray-patch "$examples/ray-patch.txt"
expect 2 "ray-patch zero direction" "0 0 0 0 0 0 0 0 0 1 0 0 1 1 1 0 1 0\n" predicate ray-patch

if [ "$(printf '0 0 0 1 0 0 0 1 0 0 0 1\n' | "$exe" predicate orient3d)" != "1" ]; then
  echo "FAIL: orient3d answer"
  failures=$((failures + 1))
fi
# ccd: exit 1 exactly when a false negative is found; 2 for bad paths, types and truth.
unit="$data/ccd/sample-queries/unit-tests"
expect 0 "ccd exact on bundled data" "" ccd "$data/ccd"
expect 1 "ccd parity misses two-root cases" "" ccd --method parity "$unit"
expect 0 "ccd help" "" ccd --help
expect 2 "ccd missing path" "" ccd /nonexistent/queries
expect 2 "ccd unknown method" "" ccd --method bogus "$unit"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
head -n 8 "$unit/vertex-face/data_0_0.csv" >"$scratch/queries.csv"
expect 2 "ccd type unknown" "" ccd "$scratch/queries.csv"
expect 0 "ccd type given" "" ccd --type vf "$scratch/queries.csv"
cut -d, -f1-6 "$scratch/queries.csv" >"$scratch/six.csv"
echo "[true, false]" >"$scratch/two.json"
expect 2 "ccd truth length mismatch" "" ccd --type vf --truth "$scratch/two.json" "$scratch/six.csv"
echo "1,2,3,4,5,6,7" >"$scratch/bad.csv"
expect 2 "ccd malformed row" "" ccd --type ee "$scratch/bad.csv"

json=$("$exe" ccd --json --per-query "$scratch/per-query.csv" "$unit")
for key in '"method": "exact"' '"false_negatives": 0' '"false_positives": 0' '"vertex_face": {' \
           '"edge_edge": {' '"ns_per_query": '; do
  case "$json" in
    *"$key"*) ;;
    *) echo "FAIL: ccd --json lacks $key: $json"; failures=$((failures + 1)) ;;
  esac
done
queries=$(printf '%s' "$json" | sed -n 's/^{"method": "exact", "queries": \([0-9]*\).*/\1/p')
lines=$(($(wc -l <"$scratch/per-query.csv") - 1))
if [ -z "$queries" ] || [ "$lines" != "$queries" ]; then
  echo "FAIL: --per-query wrote $lines lines for $queries queries"
  failures=$((failures + 1))
fi
if ! grep -q ',vf,1,1$' "$scratch/per-query.csv"; then
  echo "FAIL: --per-query lacks a vertex-face true positive line"
  failures=$((failures + 1))
fi

exit $((failures > 0))
