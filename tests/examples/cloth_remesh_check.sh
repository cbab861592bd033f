#!/usr/bin/env bash
# examples.cloth_remesh: the adaptive cloth (exactgeo-cloth --remesh) runs short versions of
# both scenes. The example itself exits 1 when a filtered step collides or the exact
# self-intersection finder sees an intersecting face pair after a step or a remesh, so
# exit 0 is the main check; the summary must also show that the run exercised what it
# claims: the finder ran after every step, splits, collapses and flips were applied, the
# cloth's triangle count changed, and the sheets met themselves (and the ball).
set -u
exe="$1"
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}
value() {  # value <json> <key>: the first integer after "key":
  printf '%s' "$1" | sed -n "s/^[^{]*{.*\"$2\": \([0-9][0-9]*\).*/\1/p" | head -n 1
}
applied() {  # applied <json> <kind>: the applied count of that kind of operation
  printf '%s' "$1" | sed -n "s/.*\"$2\": {\"applied\": \([0-9][0-9]*\).*/\1/p"
}
check_run() {  # check_run <name> <minimum intersection checks> <args...>
  local name="$1" checks="$2"
  shift 2
  local out rc
  out=$("$exe" "$@" --remesh --json)
  rc=$?
  echo "$name: $out"
  [ "$rc" = 0 ] || fail "$name: exit $rc, expected 0"
  local n
  n=$(value "$out" intersection_checks)
  [ -n "$n" ] && [ "$n" -ge "$checks" ] || fail "$name: $n intersection checks, expected >= $checks"
  for kind in split collapse flip; do
    n=$(applied "$out" "$kind")
    [ -n "$n" ] && [ "$n" -gt 0 ] || fail "$name: no $kind applied"
  done
  local start end
  start=$(value "$out" sheet_triangles_start)
  end=$(value "$out" sheet_triangles_end)
  [ -n "$start" ] && [ "$start" != "$end" ] || fail "$name: the cloth kept $start triangles"
  n=$(value "$out" self_collisions_total)
  [ -n "$n" ] && [ "$n" -gt 0 ] || fail "$name: the sheets never met themselves"
  LAST="$out"
}

# 30 steps: one check at the start and one after every step.
check_run stack 31 --scene stack --resolution 6 --steps 30
check_run ball 31 --scene ball --resolution 8 --layers 2 --steps 30 --time-narrow-phase
n=$(value "$LAST" obstacle_collisions_total)
[ -n "$n" ] && [ "$n" -gt 0 ] || fail "ball: the sheets never met the ball or the floor"
printf '%s' "$LAST" | grep -q '"cubic": {"vertex_face": {"calls": [1-9]' ||
  fail "ball: no cubic narrow-phase timing"

if [ "$failures" != 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "ok"
