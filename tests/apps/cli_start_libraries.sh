#!/usr/bin/env bash
# The libraries the exactgeo binary needs at start (its ELF NEEDED entries): none of those
# it opens on first use (Embree and its TBB, assimp), whose loading at every start was most
# of a short command's time (docs/inside.md, "End to end"), nor those it links statically
# (GMP, MPFR, libpng, zlib: cmake/StaticLibraries.cmake). Then, with the dynamic
# loader's trace (LD_DEBUG=files): classifying against a mesh under the box tree's face
# count never loads Embree, nor a few points against a larger one, and many points do.
set -u
exe="$1"
meshes="$2"
needed=$(objdump -p "$exe" | awk '$1 == "NEEDED" { print $2 }')
if [ -z "$needed" ]; then
  echo "FAIL: no NEEDED entries read from $exe"
  exit 1
fi
failures=0
for library in embree tbb assimp gmp mpfr png libz; do
  if printf '%s\n' "$needed" | grep -q "$library"; then
    echo "FAIL: $exe needs $(printf '%s\n' "$needed" | grep "$library" | tr '\n' ' ')at start"
    failures=$((failures + 1))
  fi
done
[ "$failures" = 0 ] && echo "needed at start: $(printf '%s\n' "$needed" | tr '\n' ' ')"

loads_embree() {  # loads_embree MESH [POINTS]: whether classifying loads libembree3
  local mesh="$1"
  shift
  printf '0 0.2 0\n' | LD_DEBUG=files "$exe" inside "$mesh" "$@" 2>&1 >/dev/null |
    grep -q 'file=libembree3[^ ]* .*dynamically loaded'
}
# kBoxTreeFaces = 4,096, kEmbreePoints = 2^19 and kBoxTreeFacesManyPoints = 256
# (inside/classifier.hpp): 2,928 quads do not load Embree for points from standard input
# (how many is not known) and do for a file of 2^19 points; 11,712 do from standard input,
# and not for a file of one point.
if loads_embree "$meshes/spot/spot_quadrangulated.obj"; then
  echo "FAIL: a mesh of 2,928 faces loads Embree"
  failures=$((failures + 1))
fi
if ! loads_embree "$meshes/spot/spot_quad_cc1.ply"; then
  echo "FAIL: a mesh of 11,712 faces does not load Embree (or the loader's trace is not read)"
  failures=$((failures + 1))
fi
points=$(mktemp)
trap 'rm -f "$points"' EXIT
printf '0 0.2 0\n' >"$points"
if loads_embree "$meshes/spot/spot_quad_cc1.ply" "$points"; then
  echo "FAIL: a mesh of 11,712 faces loads Embree for a file of one point"
  failures=$((failures + 1))
fi
many=$(mktemp)
trap 'rm -f "$points" "$many"' EXIT
head -c $((24 << 19)) /dev/zero >"$many"  # 2^19 points (0, 0, 0) as raw float64
if ! loads_embree "$meshes/spot/spot_quadrangulated.obj" "$many" --points-format f64; then
  echo "FAIL: a mesh of 2,928 faces does not load Embree for a file of 2^19 points"
  failures=$((failures + 1))
fi
exit "$failures"
