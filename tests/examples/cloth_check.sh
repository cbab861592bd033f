#!/usr/bin/env bash
# examples.cloth: the cloth example (examples/cloth) runs a short simulation that
# verifies every filtered step with a second MeshCcd (exit 1 on a collision), and the scene
# must exercise the filter: collisions with the obstacle and of the sheet with itself.
set -u
exe="$1"
failures=0
fail() {
  echo "FAIL: $*"
  failures=$((failures + 1))
}

out=$("$exe" --resolution 12 --steps 60 --json)
rc=$?
[ "$rc" = 0 ] || fail "exit $rc, expected 0"
echo "$out"
value() {  # value <key>: the integer after "key": in the JSON summary
  printf '%s' "$out" | sed -n "s/.*\"$1\": \([0-9][0-9]*\).*/\1/p"
}
for key in collisions_total self_collisions_total obstacle_collisions_total; do
  n=$(value "$key")
  if [ -z "$n" ]; then
    fail "no $key in the JSON summary"
  elif [ "$n" -le 0 ]; then
    fail "$key is $n: the filter was not exercised"
  fi
done

# Bad options: exit 2 and nothing on stdout.
for args in "--resolution 1" "--dt 0" "--dt nan" "--steps -1" "--every 0" "--bogus" \
  "--scene bogus" "--layers 0" "--scene stack --jitter 0.001"; do
  # shellcheck disable=SC2086
  bad=$("$exe" $args 2>/dev/null)
  rc=$?
  [ "$rc" = 2 ] || fail "$args: exit $rc, expected 2"
  [ -z "$bad" ] || fail "$args: printed to stdout on error"
done

if [ "$failures" != 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "ok"
