#!/usr/bin/env bash
# End-to-end checks of the exactgeo binary: exit codes, and nothing on stdout on error.
set -u
exe="$1"
examples="$2"
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
exit $((failures > 0))
