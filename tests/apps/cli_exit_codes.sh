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
# A type that contradicts the path, a truth file for files with their own truth column,
# and files without a single query are refused, each with a message naming the cause.
expect 2 "ccd type contradicting the path" "" ccd --type vf "$unit"
expect 2 "ccd truth file for 7-column files" "" ccd --truth "$scratch/two.json" "$unit"
: >"$scratch/empty_vf.csv"
expect 2 "ccd without queries" "" ccd "$scratch/empty_vf.csv"
# The message names the empty file (or the first empty files, when every file is empty).
printf '\n\n' >"$scratch/blank_ee.csv"
for args in "$scratch/empty_vf.csv" "$scratch/blank_ee.csv $scratch/empty_vf.csv"; do
  # shellcheck disable=SC2086
  message=$("$exe" ccd $args 2>&1 >/dev/null)
  for file in $args; do
    case "$message" in
      *"$file"*) ;;
      *) echo "FAIL: ccd on empty files does not name $file: $message"; failures=$((failures + 1)) ;;
    esac
  done
done
expect 2 "ccd zero timing passes" "" ccd --repeat 0 "$unit"
# Timing passes change the times only: the counts are those of a single pass.
untimed() {
  sed -E -e 's/"ns_per_query": [0-9.]*//g' \
    -e 's/, "query_ns": \{("[a-z_]+": (\{[^}]*\}|null)(, )?)*\}//g'
}
once=$("$exe" ccd --json "$unit" | untimed)
thrice=$("$exe" ccd --json --repeat 3 "$unit" | untimed)
case "$once" in
  *query_ns*|'') echo "FAIL: ccd --json timing fields not stripped: $once"; failures=$((failures + 1)) ;;
esac
if [ -z "$once" ] || [ "$once" != "$thrice" ]; then
  echo "FAIL: ccd --repeat 3 changed the counts: $thrice"
  failures=$((failures + 1))
fi

json=$("$exe" ccd --json --per-query "$scratch/per-query.csv" "$unit")
for key in '"method": "exact"' '"false_negatives": 0' '"false_positives": 0' '"vertex_face": {' \
           '"edge_edge": {' '"ns_per_query": '; do
  case "$json" in
    *"$key"*) ;;
    *) echo "FAIL: ccd --json lacks $key: $json"; failures=$((failures + 1)) ;;
  esac
done
queries=$(printf '%s' "$json" | sed -n 's/^{"method": "exact", "min_separation": 0, "queries": \([0-9]*\).*/\1/p')
lines=$(($(wc -l <"$scratch/per-query.csv") - 1))
if [ -z "$queries" ] || [ "$lines" != "$queries" ]; then
  echo "FAIL: --per-query wrote $lines lines for $queries queries"
  failures=$((failures + 1))
fi
if ! grep -q ',vf,1,1,' "$scratch/per-query.csv"; then
  echo "FAIL: --per-query lacks a vertex-face true positive line"
  failures=$((failures + 1))
fi
for key in '"query_ns": {"all": {"queries": ' '"median": ' '"p99": ' '"max": '; do
  case "$json" in
    *"$key"*) ;;
    *) echo "FAIL: ccd --json lacks $key: $json"; failures=$((failures + 1)) ;;
  esac
done

# --toi-width: exact only; --per-query then holds a bracket [start, end] for every
# collision (start <= end, width at most the one asked for) and none for the others.
expect 2 "ccd toi width with parity" "" ccd --method parity --toi-width 0.001 "$unit"
expect 2 "ccd toi width zero" "" ccd --toi-width 0 "$unit"
"$exe" ccd --toi-width 0.001 --per-query "$scratch/toi.csv" "$unit" >/dev/null
if ! awk -F, 'NR > 1 && $4 == 1 { if ($8 == "" || $8 > $9 || $9 - $8 > 0.001) bad++; n++ }
              NR > 1 && $4 == 0 && ($8 != "" || $9 != "") { bad++ }
              END { exit (bad > 0 || n == 0) }' "$scratch/toi.csv"; then
  echo "FAIL: --toi-width brackets in --per-query"
  failures=$((failures + 1))
fi

# --min-separation: a finite number >= 0, exact only, no --toi-width yet; the contact
# truth is not compared at a larger separation, and every contact stays a collision.
# Read as every input number: below the smallest double is refused, not taken as 0.
for bad in -1 nan inf -inf 1e999 abc "" 1e-400 0x1p-1080 0x1p-1076; do
  expect 2 "ccd min-separation '$bad'" "" ccd --min-separation "$bad" "$unit"
done
for good in 0xAp-3 0x1p-1074 4.9406564584124654e-324 -0; do
  expect 0 "ccd min-separation '$good'" "" ccd --min-separation "$good" "$unit"
done
message=$("$exe" ccd --min-separation 1e-400 "$unit" 2>&1 >/dev/null)
case "$message" in
  *"'1e-400' is outside the range of double"*) ;;
  *) echo "FAIL: ccd --min-separation 1e-400 says: $message"; failures=$((failures + 1)) ;;
esac
expect 2 "ccd min-separation with parity" "" ccd --method parity --min-separation 0.1 "$unit"
expect 0 "ccd min-separation with toi" "" ccd --toi-width 0.01 --min-separation 0.1 "$unit"
expect 0 "ccd min-separation zero" "" ccd --min-separation 0 "$unit"
json=$("$exe" ccd --json --min-separation 0.01 "$unit")
case "$json" in
  *'"min_separation": 0.01'*'"false_negatives": null'*) ;;
  *) echo "FAIL: ccd --min-separation --json: $json"; failures=$((failures + 1)) ;;
esac
positives() { sed -n 's/^{[^{]*"positives": \([0-9]*\).*/\1/p'; }  # of all queries
contacts=$("$exe" ccd --json "$unit" | positives)
within=$("$exe" ccd --json --min-separation 0.01 "$unit" | positives)
if ! [ "$within" -ge "$contacts" ] 2>/dev/null; then
  echo "FAIL: ccd --min-separation 0.01 finds $within positives, fewer than the $contacts contacts"
  failures=$((failures + 1))
fi

# info: exit 0 whenever the mesh loads (an open mesh is a fact to report), 2 when it does not.
meshes="$data/meshes"
expect 0 "info closed mesh" "" info "$meshes/cgal/cube_quad.off"
expect 0 "info open mesh" "" info "$meshes/negative/corner_with_hole.off"
expect 0 "info help" "" info --help
expect 2 "info no mesh" "" info
expect 2 "info missing file" "" info /nonexistent/mesh.off
expect 2 "info missing file, json" "" info --json /nonexistent/mesh.off
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1\n3 0 1 2\n' >"$scratch/short-vertex.off"
expect 2 "info malformed file" "" info "$scratch/short-vertex.off"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n' >"$scratch/bad-index.off"
expect 2 "info index out of range" "" info --json "$scratch/bad-index.off"
printf 'OFF\n5 1 0\n0 0 0\n1 0 0\n2 1 0\n1 2 0\n0 1 0\n5 0 1 2 3 4\n' >"$scratch/pentagon.off"
expect 0 "info pentagon" "" info "$scratch/pentagon.off"
printf 'OFF\n5 1 0\n0 10 0\n6 -8 0\n-10 3 0\n10 3 0\n-6 -8 0\n5 0 1 2 3 4\n' >"$scratch/pentagram.off"
expect 2 "info pentagram" "" info "$scratch/pentagram.off"
expect 0 "info pentagram as a fan" "" info --split-polygons "$scratch/pentagram.off"

expect_in() {  # expect_in <description> <text> <substrings...>
  local what="$1" text="$2"
  shift 2
  local key
  for key in "$@"; do
    case "$text" in
      *"$key"*) ;;
      *) echo "FAIL: $what lacks $key: $text"; failures=$((failures + 1)) ;;
    esac
  done
}
info_keys=('"file": ' '"format": "off"' '"coordinates_via_float": false' '"vertices": '
           '"welded_vertices": 0' '"faces": ' '"quads": ' '"triangles": ' '"bounding_box": '
           '"closed": ' '"boundary_edges": ' '"manifold": true' '"non_manifold_edges": 0'
           '"consistently_oriented": ' '"degenerate_faces": 0' '"non_planar_quads": '
           '"unreferenced_vertices": 0' '"components": 1' '"problem": ')
json=$("$exe" info --json "$meshes/cgal/cube_quad.off")
expect_in "info --json (closed)" "$json" "${info_keys[@]}" '"closed": true' \
  '"boundary_edges": 0' '"consistently_oriented": true' '"problem": null' '"lower": ['
json=$("$exe" info --json "$meshes/negative/corner_with_hole.off")
expect_in "info --json (open)" "$json" "${info_keys[@]}" '"closed": false' \
  '"consistently_oriented": null' '"problem": null'
boundary=$(printf '%s' "$json" | sed -n 's/.*"boundary_edges": \([0-9]*\).*/\1/p')
if [ -z "$boundary" ] || [ "$boundary" -le 0 ]; then
  echo "FAIL: info --json on an open mesh: boundary_edges '$boundary'"
  failures=$((failures + 1))
fi
table=$("$exe" info "$meshes/cgal/cube_quad.off")
expect_in "info table (closed)" "$table" 'closed              yes' 'usable for `exactgeo inside`: yes'
table=$("$exe" info "$meshes/negative/corner_with_hole.off")
expect_in "info table (open)" "$table" 'closed              no: ' \
  'usable for `exactgeo inside`: yes, as an open surface (4 edges run more often one way than the other): labelled by its generalized winding number'
json=$("$exe" info --json "$scratch/pentagon.off")
expect_in "info --json (split pentagon)" "$json" '"faces": 3' '"triangles": 3' '"closed": false' \
  '"boundary_edges": 5' '"bounding_box": {"lower": [0, 0, 0], "upper": [2, 2, 0]}'

# inside: labels in input order; 2 for bad meshes, bad points, bad options.
cube="$meshes/cgal/cube_quad.off"
read -r lo hi < <("$exe" info --json "$cube" | sed -n 's/.*"lower": \[\([^,]*\),.*"upper": \[\([^,]*\),.*/\1 \2/p')
mid=$(awk -v a="$lo" -v b="$hi" 'BEGIN { printf "%.17g", (a + b) / 2 }')
far=$(awk -v a="$lo" -v b="$hi" 'BEGIN { printf "%.17g", b + (b - a) }')
points="$mid $mid $mid\n# a comment\n\n$far,$far,$far\n$lo $mid $mid\n"
labels=$(printf '%b' "$points" | "$exe" inside "$cube" | tr '\n' ' ')
if [ "$labels" != "inside outside boundary " ]; then
  echo "FAIL: inside labels on the cube: '$labels'"
  failures=$((failures + 1))
fi
labels=$(printf '%b' "$points" | "$exe" inside --method double --threads 1 "$cube" - | tr '\n' ' ')
if [ "$labels" != "inside outside boundary " ]; then
  echo "FAIL: inside --method double labels on the cube: '$labels'"
  failures=$((failures + 1))
fi
json=$(printf '%b' "$points" | "$exe" inside --json "$cube")
expect_in "inside --json" "$json" '"points": 3' '"inside": 1' '"outside": 1' '"boundary": 1' \
  '"build_seconds": ' '"seconds": '
# STL is read exactly: a vertex copied from the file lies on the surface (through 32-bit
# floats, 0.7 would move below the double 0.7 and the point would be outside).
stl_facet() {  # stl_facet <x y z> <x y z> <x y z>
  printf 'facet normal 0 0 0\n outer loop\n  vertex %s\n  vertex %s\n  vertex %s\n endloop\nendfacet\n' "$@"
}
a='0.1 0.1 0.1' b='0.7 0.1 0.1' c='0.1 0.7 0.1' d='0.1 0.1 0.7'
{ echo 'solid tetrahedron'; stl_facet "$a" "$c" "$b"; stl_facet "$a" "$b" "$d"
  stl_facet "$a" "$d" "$c"; stl_facet "$b" "$c" "$d"; echo 'endsolid tetrahedron'; } >"$scratch/tet.stl"
labels=$(printf '%s\n' "$b" '0.2 0.2 0.2' '0.7 0.7 0.7' | "$exe" inside "$scratch/tet.stl" | tr '\n' ' ')
if [ "$labels" != "boundary inside outside " ]; then
  echo "FAIL: inside labels on an ASCII STL tetrahedron: '$labels'"
  failures=$((failures + 1))
fi
expect_in "info --json (STL)" "$("$exe" info --json "$scratch/tet.stl")" '"format": "stl ascii"' \
  '"coordinates_via_float": false' '"vertices": 4' '"welded_vertices": 8' '"closed": true'
expect 0 "ccd-mesh STL frames" "" ccd-mesh "$scratch/tet.stl" "$scratch/tet.stl"
# A frame in which two corners meet welds to fewer vertices: not the same mesh.
sed "s/$d/$c/" "$scratch/tet.stl" >"$scratch/tet_flat.stl"
message=$("$exe" ccd-mesh "$scratch/tet.stl" "$scratch/tet_flat.stl" 2>&1 >/dev/null)
expect_in "ccd-mesh STL frames that weld differently" "$message" \
  "$scratch/tet.stl has 4 vertices, $scratch/tet_flat.stl has 3"
expect 0 "inside help" "" inside --help
expect 0 "inside no points" "" inside "$cube"
expect 2 "inside no mesh" "" inside
expect 0 "inside open mesh" "0 0 0\n" inside "$meshes/negative/corner_with_hole.off"
expect 2 "inside missing mesh" "0 0 0\n" inside /nonexistent/mesh.off
expect 2 "inside missing points" "" inside "$cube" /nonexistent/points.txt
expect 2 "inside two coordinates" "1 2\n" inside "$cube"
expect 2 "inside NaN" "0 0 nan\n" inside "$cube"
expect 2 "inside unknown method" "0 0 0\n" inside --method rational "$cube"
expect 2 "inside zero threads" "0 0 0\n" inside --threads 0 "$cube"
expect 2 "inside pentagram" "0 0 0\n" inside "$scratch/pentagram.off"
expect 0 "inside pentagon" "0 0 0\n" inside "$scratch/pentagon.off"
message=$(printf '1 2\n' | "$exe" inside "$cube" 2>&1 >/dev/null)
expect_in "inside error names the line" "$message" '<stdin>:1: expected 3 coordinates, found 2'
message=$(printf '0 0 0\n' | "$exe" inside "$meshes/negative/corner_with_hole.off" 2>&1 >/dev/null)
expect_in "inside open mesh note" "$message" 'corner_with_hole.off: the surface is open (4 edges run more often one way than the other): inside where its generalized winding number'

# Progress: nothing on a standard error that is not a terminal, unless --progress asks for
# it; then plain lines (no carriage returns or terminal escapes), the labels unchanged.
message=$(printf '%b' "$points" | "$exe" inside "$cube" 2>&1 >/dev/null)
if [ -n "$message" ]; then
  echo "FAIL: inside without --progress wrote to a standard error that is no terminal: $message"
  failures=$((failures + 1))
fi
message=$(printf '%b' "$points" | "$exe" inside --progress "$cube" 2>&1 >/dev/null)
expect_in "inside --progress" "$message" "reading $cube..." 'classifying...' '3 points'
if [ "$(printf '%s' "$message" | tr -d -c '\r\033' | wc -c)" != 0 ]; then
  echo "FAIL: inside --progress off a terminal wrote carriage returns or escapes: $message"
  failures=$((failures + 1))
fi
labels=$(printf '%b' "$points" | "$exe" inside --progress "$cube" 2>/dev/null | tr '\n' ' ')
if [ "$labels" != "inside outside boundary " ]; then
  echo "FAIL: inside --progress labels on the cube: '$labels'"
  failures=$((failures + 1))
fi

# inside, binary points (tests/apps/inside_command_test.cpp has the formats in depth): f64
# on stdin, 24 zero bytes a point; (0, 0, 0) is the cube's centre.
zeros24='\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0'
labels=$(printf '%b' "$zeros24$zeros24" | "$exe" inside --points-format f64 "$cube" | tr '\n' ' ')
if [ "$labels" != "inside inside " ]; then
  echo "FAIL: inside --points-format f64 on stdin: '$labels'"
  failures=$((failures + 1))
fi
expect 0 "inside f64 empty stdin" "" inside --points-format f64 "$cube"
expect 2 "inside f64 23 bytes" "${zeros24%\\0}" inside --points-format f64 "$cube"
expect 2 "inside f64 25 bytes" "$zeros24\0" inside --points-format f64 "$cube" -
expect 2 "inside npy on stdin, text" "0 0 0\n" inside --points-format npy "$cube"
expect 2 "inside unknown points format" "0 0 0\n" inside --points-format f32 "$cube"
expect 2 "inside --labels without --json" "0 0 0\n" inside --labels "$cube"
message=$(printf '%b' "$zeros24\0" | "$exe" inside --points-format f64 "$cube" 2>&1 >/dev/null)
expect_in "inside f64 error names the point" "$message" \
  '<stdin>: point 1 (byte 24): the input ends 1 byte into this point'
printf '0 0 0\n' >"$scratch/points.npy"
expect 2 "inside .npy by name" "" inside "$cube" "$scratch/points.npy"
expect 0 "inside .npy named, read as text" "" inside --points-format text "$cube" \
  "$scratch/points.npy"
json=$(printf '%b' "$points" | "$exe" inside --json --labels "$cube")
expect_in "inside --json --labels" "$json" '"points": 3' '"read_seconds": ' \
  '"labels": ["inside", "outside", "boundary"]}'
if command -v python3 >/dev/null &&
   ! printf '%s' "$json" | python3 -c 'import json, sys; json.load(sys.stdin)' 2>/dev/null; then
  echo "FAIL: inside --json --labels is not valid JSON: $json"
  failures=$((failures + 1))
fi

# ccd-mesh: two frames of one triangle mesh (the start and the end of a step); sorted pairs,
# 0-based; 2 for anything that is not the same triangle mesh twice.
# Face 0 stands on z = 0. vf: vertex 3 falls through it at t = 1/2 (its triangle's other
# corners stay above). ee: face 1 slides along y, its edge 3-4 crossing edge 0-1 at t = 1/2.
# still: vertex 3 stops above face 0.
tri='v 0 0 0\nv 1 0 0\nv 0 1 0\n'
printf "${tri}v 0.25 0.25 1\nv 0.3 0.25 5\nv 0.25 0.3 5\nf 1 2 3\nf 4 5 6\n" >"$scratch/vf0.obj"
printf "${tri}v 0.25 0.25 -1\nv 0.3 0.25 3\nv 0.25 0.3 3\nf 1 2 3\nf 4 5 6\n" >"$scratch/vf1.obj"
printf "${tri}v 0.25 0.25 0.5\nv 0.3 0.25 4.5\nv 0.25 0.3 4.5\nf 1 2 3\nf 4 5 6\n" \
  >"$scratch/still1.obj"
printf "${tri}v 0.5 -0.25 -1\nv 0.5 -0.25 1\nv 0.5 -1 0.5\nf 1 2 3\nf 4 5 6\n" >"$scratch/ee0.obj"
printf "${tri}v 0.5 0.25 -1\nv 0.5 0.25 1\nv 0.5 -0.5 0.5\nf 1 2 3\nf 4 5 6\n" >"$scratch/ee1.obj"
vf0="$scratch/vf0.obj"
vf1="$scratch/vf1.obj"
mesh_keys=('"method": "exact"' '"candidates": ' '"vertex_face_candidates": '
           '"edge_edge_candidates": ' '"seconds": ' '"broad_phase_seconds": '
           '"narrow_phase_seconds": ')
json=$("$exe" ccd-mesh --json "$vf0" "$vf1")
expect_in "ccd-mesh --json (vertex falls through)" "$json" "${mesh_keys[@]}" \
  '"vertex_face": [[3, 0]], "edge_edge": []'
case "$json" in
  *time_of_impact*) echo "FAIL: ccd-mesh --json without --toi has time_of_impact: $json"
                    failures=$((failures + 1)) ;;
esac
if [ "$(printf '%s\n' "$json" | wc -l)" != 1 ]; then
  echo "FAIL: ccd-mesh --json is not one line: $json"
  failures=$((failures + 1))
fi
expect_toi() {  # expect_toi <description> <json> <width>: the interval holds t = 1/2
  local start end
  read -r start end < <(printf '%s' "$2" |
    sed -n 's/.*"time_of_impact": \[\([^,]*\), \([^]]*\)\].*/\1 \2/p')
  if ! awk -v s="${start:-x}" -v e="${end:-x}" -v w="$3" \
       'BEGIN { exit !(s + 0 == s && e + 0 == e && s <= 0.5 && 0.5 <= e && e - s <= w) }'; then
    echo "FAIL: $1: [$start, $end] should hold 0.5 and be at most $3 wide: $2"
    failures=$((failures + 1))
  fi
}
json=$("$exe" ccd-mesh --json --toi "$vf0" "$vf1")
expect_toi "ccd-mesh --toi" "$json" 1e-6
json=$("$exe" ccd-mesh --json --toi-width 0.25 --threads 1 "$scratch/ee0.obj" "$scratch/ee1.obj")
expect_in "ccd-mesh --json (edge crosses edge)" "$json" "${mesh_keys[@]}" \
  '"vertex_face": [], "edge_edge": [[0, 1, 3, 4]]' '"time_of_impact": ['
expect_toi "ccd-mesh --toi-width 0.25" "$json" 0.25
json=$("$exe" ccd-mesh --json --toi "$vf0" "$scratch/still1.obj")
expect_in "ccd-mesh --json (no collision)" "$json" "${mesh_keys[@]}" \
  '"vertex_face": [], "edge_edge": []' '"time_of_impact": null'
json=$("$exe" ccd-mesh --json --method parity "$vf0" "$vf1")
expect_in "ccd-mesh --json --method parity" "$json" '"method": "parity"' \
  '"vertex_face": [[3, 0]], "edge_edge": []'
table=$("$exe" ccd-mesh --toi "$vf0" "$vf1")
expect_in "ccd-mesh report (vertex falls through)" "$table" \
  'mesh                6 vertices, 2 faces, 6 edges' 'method              exact' \
  'vertex-face pairs   1' 'edge-edge pairs     0' 'candidates          ' \
  'time of impact      [' 'broad phase         ' 'narrow phase        '
if [ "$(printf '%s\n' "$table" | tail -n 1)" != "vertex-face 3 0" ]; then
  echo "FAIL: ccd-mesh report should end with 'vertex-face 3 0': $table"
  failures=$((failures + 1))
fi
table=$("$exe" ccd-mesh "$scratch/ee0.obj" "$scratch/ee1.obj")
pairs=$(printf '%s\n' "$table" | grep -E '^(vertex-face|edge-edge) [0-9]')
if [ "$pairs" != "edge-edge 0 1 3 4" ]; then
  echo "FAIL: ccd-mesh report should list exactly 'edge-edge 0 1 3 4': $table"
  failures=$((failures + 1))
fi
table=$("$exe" ccd-mesh --toi "$vf0" "$scratch/still1.obj")
expect_in "ccd-mesh report (no collision)" "$table" 'vertex-face pairs   0' \
  'edge-edge pairs     0' 'time of impact      none'
expect 0 "ccd-mesh help" "" ccd-mesh --help
expect 0 "ccd-mesh no collision" "" ccd-mesh "$vf0" "$scratch/still1.obj"
expect 0 "ccd-mesh collision" "" ccd-mesh "$vf0" "$vf1"

printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n' >"$scratch/quad.obj"
printf "${tri}v 0.25 0.25 -1\nv 0.3 0.25 3\nv 0.25 0.3 3\nf 1 2 3\nf 4 6 5\n" \
  >"$scratch/flipped1.obj"
printf "${tri}v 0.25 0.25 -1\nv 0.3 0.25 3\nv 0.25 0.3 3\nv 9 9 9\nf 1 2 3\nf 4 5 6\n" \
  >"$scratch/extra1.obj"
printf "${tri}v 0.25 0.25 -1\nv 0.3 0.25 3\nv 0.25 0.3 3\nf 1 2 3\n" >"$scratch/oneface1.obj"
printf "${tri}v 0.25 0.25 nan\nv 0.3 0.25 3\nv 0.25 0.3 3\nf 1 2 3\nf 4 5 6\n" \
  >"$scratch/nan1.obj"
printf "${tri}v 0.25 0.25 1\nv 0.3 0.25 5\nv 0.25 0.3 5\nf 1 2 3\nf 4 4 6\n" \
  >"$scratch/repeat0.obj"
printf '0 0 0 1 0 0 0 1 0\n' >"$scratch/tri.raw"  # RAW: a triangle a line, read by assimp
expect 2 "ccd-mesh no frames" "" ccd-mesh
expect 2 "ccd-mesh one frame" "" ccd-mesh "$vf0"
expect 2 "ccd-mesh quads" "" ccd-mesh "$scratch/quad.obj" "$scratch/quad.obj"
expect 2 "ccd-mesh quads, json" "" ccd-mesh --json "$vf0" "$scratch/quad.obj"
expect 2 "ccd-mesh different face" "" ccd-mesh --json "$vf0" "$scratch/flipped1.obj"
expect 2 "ccd-mesh different vertex count" "" ccd-mesh --json "$vf0" "$scratch/extra1.obj"
expect 2 "ccd-mesh different face count" "" ccd-mesh --json "$vf0" "$scratch/oneface1.obj"
expect 2 "ccd-mesh NaN coordinate" "" ccd-mesh --json "$vf0" "$scratch/nan1.obj"
expect 2 "ccd-mesh repeated corner" "" ccd-mesh --json "$scratch/repeat0.obj" \
  "$scratch/repeat0.obj"
expect 2 "ccd-mesh missing frame0" "" ccd-mesh --json /nonexistent/frame0.obj "$vf1"
expect 2 "ccd-mesh missing frame1" "" ccd-mesh --json "$vf0" /nonexistent/frame1.obj
expect 2 "ccd-mesh assimp format" "" ccd-mesh --json "$scratch/tri.raw" "$scratch/tri.raw"
expect 2 "ccd-mesh method double" "" ccd-mesh --method double "$vf0" "$vf1"
expect 2 "ccd-mesh unknown method" "" ccd-mesh --method bogus "$vf0" "$vf1"
expect 2 "ccd-mesh --toi with parity" "" ccd-mesh --toi --method parity "$vf0" "$vf1"
expect 2 "ccd-mesh zero --toi-width" "" ccd-mesh --toi-width 0 "$vf0" "$vf1"
expect 2 "ccd-mesh NaN --toi-width" "" ccd-mesh --toi-width nan "$vf0" "$vf1"
for bad in 0 -1 1e-400 abc; do
  expect 2 "ccd tolerance '$bad'" "" ccd --method cubic --tolerance "$bad" "$unit"
done
expect 0 "ccd tolerance hexfloat" "" ccd --method cubic --tolerance 0x1p-20 "$unit"
# --toi-width is read as every number too: below the double range is refused, not 0.
for bad in 1e-400 0x1p-61 2 abc; do
  expect 2 "ccd toi-width '$bad'" "" ccd --toi-width "$bad" "$unit"
done
expect 0 "ccd toi-width 2^-60" "" ccd --toi-width 0x1p-60 "$unit"
expect 2 "ccd-mesh toi-width 1e-400" "" ccd-mesh --toi-width 1e-400 "$vf0" "$vf1"
for bad in -1 nan inf 1e999 abc "" 1e-400 0x1p-1080; do
  expect 2 "ccd-mesh min-separation '$bad'" "" ccd-mesh --min-separation "$bad" "$vf0" "$vf1"
done
expect 0 "ccd-mesh min-separation hexfloat" "" ccd-mesh --min-separation 0xAp-3 "$vf0" "$vf1"
expect 0 "ccd-mesh min-separation with toi" "" ccd-mesh --toi --min-separation 0.1 "$vf0" "$vf1"
expect 2 "ccd-mesh min-separation with parity" "" ccd-mesh --method parity --min-separation 0.1 "$vf0" "$vf1"
expect 0 "ccd-mesh min-separation" "" ccd-mesh --min-separation 0.1 "$vf0" "$vf1"
expect 2 "ccd-mesh zero threads" "" ccd-mesh --threads 0 "$vf0" "$vf1"
message=$("$exe" ccd-mesh "$vf0" "$scratch/quad.obj" 2>&1 >/dev/null)
expect_in "ccd-mesh quads message" "$message" \
  'triangle meshes are needed: '"$scratch"'/quad.obj has 1 quad (first: face 0)'
message=$("$exe" ccd-mesh "$vf0" "$scratch/flipped1.obj" 2>&1 >/dev/null)
expect_in "ccd-mesh different face message" "$message" \
  "face 1 is [3, 4, 5] in $vf0 and [3, 5, 4] in $scratch/flipped1.obj"
message=$("$exe" ccd-mesh "$vf0" "$scratch/extra1.obj" 2>&1 >/dev/null)
expect_in "ccd-mesh vertex count message" "$message" \
  "$vf0 has 6 vertices, $scratch/extra1.obj has 7"
message=$("$exe" ccd-mesh "$vf0" "$scratch/nan1.obj" 2>&1 >/dev/null)
expect_in "ccd-mesh NaN message" "$message" "$scratch/nan1.obj:4: "
message=$("$exe" ccd-mesh "$scratch/repeat0.obj" "$scratch/repeat0.obj" 2>&1 >/dev/null)
expect_in "ccd-mesh repeated corner message" "$message" "$scratch/repeat0.obj: " 'face 1: '
message=$("$exe" ccd-mesh "$vf0" /nonexistent/frame1.obj 2>&1 >/dev/null)
expect_in "ccd-mesh missing file message" "$message" '/nonexistent/frame1.obj: cannot open file'
message=$("$exe" ccd-mesh "$scratch/tri.raw" "$scratch/tri.raw" 2>&1 >/dev/null)
expect_in "ccd-mesh assimp format message" "$message" \
  "$scratch/tri.raw: ccd-mesh reads OBJ, OFF, PLY and STL files only"
message=$("$exe" ccd-mesh "$vf0" "$scratch/oneface1.obj" 2>&1 >/dev/null)
expect_in "ccd-mesh face count message" "$message" "$vf0 has 2 faces, $scratch/oneface1.obj has 1"

message=$("$exe" ccd --type vf "$unit" 2>&1 >/dev/null)
expect_in "ccd contradicting type message" "$message" "exactgeo ccd: " "edge-edge queries by its path"
message=$("$exe" ccd --truth "$scratch/two.json" "$unit" 2>&1 >/dev/null)
expect_in "ccd truth file message" "$message" "has its own truth column"
message=$("$exe" ccd "$scratch/empty_vf.csv" 2>&1 >/dev/null)
expect_in "ccd no queries message" "$message" "exactgeo ccd: no queries"
# Option errors name their subcommand and stay short (no 300-digit range).
message=$("$exe" ccd --tolerance -1 "$unit" 2>&1 >/dev/null)
expect_in "ccd --tolerance -1 message" "$message" "exactgeo ccd: --tolerance: expected a positive number, got '-1'"
if [ "${#message}" -gt 200 ]; then
  echo "FAIL: ccd --tolerance -1 message is ${#message} characters long"
  failures=$((failures + 1))
fi
message=$("$exe" inside --threads 0 x 2>&1 >/dev/null)
expect_in "inside option error message" "$message" "exactgeo inside: --threads"

# A face soup that welding would close: refused, with the hint.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 0\nv 0 0 1\nv 1 0 0\nv 0 0 0\nv 0 1 0\nv 0 0 1\nv 1 0 0\nv 0 0 1\nv 0 1 0\nf 1 3 2\nf 4 6 5\nf 7 9 8\nf 10 11 12\n' >"$scratch/soup.obj"
expect 2 "inside face soup" "0.1 0.1 0.1\n" inside "$scratch/soup.obj"
expect 0 "inside face soup welded" "0.1 0.1 0.1\n" inside --weld "$scratch/soup.obj"
message=$(printf '0.1 0.1 0.1\n' | "$exe" inside "$scratch/soup.obj" 2>&1 >/dev/null)
expect_in "inside face soup hint" "$message" "mesh is not closed" "with --weld, which merges the 8 vertices"
# OBJ numbers vertices from 1: so do the messages about an OBJ file, and they say so.
expect_in "inside OBJ numbering" "$message" "first: 1-2, 1-3, 2-3" "numbered from 1, as in the file"
message=$(printf '0.1 0.1 0.1\n' | "$exe" inside "$scratch/oneface1.obj" 2>&1 >/dev/null)
case "$message" in
  *--weld*) echo "FAIL: a mesh that welding cannot close got the --weld hint: $message"; failures=$((failures + 1)) ;;
esac
# A tetrahedron with a flat sliver closing a T-junction on edge 1-2 (vertex 5 is its
# midpoint): the sliver has zero area, is dropped, and the note says which face it was.
printf 'v 0 0 0\nv 2 0 0\nv 0 2 0\nv 0 0 2\nv 1 0 0\nf 1 3 2\nf 1 5 4\nf 5 2 4\nf 2 3 4\nf 3 1 4\nf 1 2 5\n' >"$scratch/sliver.obj"
out=$(printf '0.2 0.2 0.2\n3 3 3\n1 0 0\n' | "$exe" inside "$scratch/sliver.obj" 2>"$scratch/sliver.err")
[ "$out" = "$(printf 'inside\noutside\nboundary')" ] || { echo "FAIL: inside with a zero-area face: $out"; failures=$((failures + 1)); }
expect_in "inside zero-area note" "$(cat "$scratch/sliver.err")" \
  "sliver.obj: 1 face of zero area (first: 6) bounds nothing: dropped (faces numbered from 1, as in the file)"
# An open box (its top face z = 1 missing): the centre of the missing face has w = 1/2
# exactly, undecided; deep inside is inside, above the hole outside; --winding prints w.
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\nf 1 4 3 2\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n' >"$scratch/openbox.obj"
out=$(printf '0.5 0.5 0.1\n0.5 0.5 1\n0.5 0.5 1.5\n' | "$exe" inside "$scratch/openbox.obj" 2>/dev/null | tr '\n' ' ')
[ "$out" = "inside undecided outside " ] || { echo "FAIL: inside on an open box: '$out'"; failures=$((failures + 1)); }
json=$(printf '0.5 0.5 0.1\n0.5 0.5 1\n' | "$exe" inside --json "$scratch/openbox.obj" 2>/dev/null)
expect_in "inside --json open box" "$json" '"inside": 1' '"undecided": 1' '"rule": "nonzero"'
# Above the hole at height 1/2 the missing square subtends 4 asin(1/2): w = 1/6; the
# missing face's centre 1/2; on the bottom face no value.
out=$(printf '0.5 0.5 1.5\n0.5 0.5 1\n0.5 0.5 0\n' | "$exe" inside --winding "$scratch/openbox.obj" 2>/dev/null | tr '\n' ' ')
if ! printf '%s' "$out" | awk '{ d1 = $1 - 1/6; d2 = $2 - 0.5; if (d1 < 0) d1 = -d1; if (d2 < 0) d2 = -d2
                                 exit !(NF == 3 && d1 < 1e-12 && d2 < 1e-12 && $3 == "boundary") }'; then
  echo "FAIL: inside --winding on an open box: '$out'"
  failures=$((failures + 1))
fi
expect 2 "inside --rule parity open box" "0.5 0.5 0.1\n" inside --rule parity "$scratch/openbox.obj"
# A PLY header line of no keyword (exporters write "Created by ..."): skipped, and said.
printf 'ply\nformat ascii 1.0\nCreated by an exporter\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' >"$scratch/created.ply"
out=$(printf '0.1 0.1 0.1\n' | "$exe" inside "$scratch/created.ply" 2>"$scratch/created.err")
[ "$out" = "inside" ] || { echo "FAIL: inside with a skipped PLY header line: '$out'"; failures=$((failures + 1)); }
expect_in "inside skipped PLY header line" "$(cat "$scratch/created.err")" \
  "warning: " "created.ply:3: skipped header line 'Created by an exporter'"
message=$("$exe" ccd-mesh "$scratch/created.ply" "$scratch/created.ply" 2>&1 >/dev/null)
expect_in "ccd-mesh skipped PLY header line" "$message" \
  "exactgeo ccd-mesh: warning: " "created.ply:3: skipped header line 'Created by an exporter'"
message=$("$exe" info "$scratch/created.ply" 2>&1 >/dev/null)
expect_in "info skipped PLY header line" "$message" "exactgeo info: warning: " "created.ply:3:"
# info numbers an OBJ's vertices and faces as the file does, and says so.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 3\n' >"$scratch/degenerate.obj"
message=$("$exe" info "$scratch/degenerate.obj")
expect_in "info OBJ numbering" "$message" "1 face repeats a corner (first: 1) (vertices and faces numbered from 1, as in the file)"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2 2\n' >"$scratch/degenerate.off"
message=$("$exe" info "$scratch/degenerate.off")
expect_in "info OFF numbering" "$message" "(first: 0) (vertices and faces numbered from 0)"

# --format: a mesh from standard input, or from a file whose name does not tell its format.
spot="$data/meshes/spot/spot_quadrangulated.obj"
cp "$spot" "$scratch/spot_without_extension"
expect 2 "info without extension" "" info "$scratch/spot_without_extension"
message=$("$exe" info "$scratch/spot_without_extension" 2>&1 >/dev/null)
expect_in "info without extension message" "$message" "no file extension; name it with --format"
expect 0 "info --format obj" "" info --format obj "$scratch/spot_without_extension"
expect 2 "info --format unknown" "" info --format xyz "$scratch/spot_without_extension"
expect 2 "info stdin without --format" "$(cat "$spot")" info -
message=$("$exe" info - </dev/null 2>&1 >/dev/null)
expect_in "info stdin without --format message" "$message" "standard input" "--format"
from_file=$("$exe" info --json "$spot" | sed 's/"file": "[^"]*"//')
from_stdin=$("$exe" info --json --format obj - <"$spot" | sed 's/"file": "[^"]*"//')
if [ "$from_file" != "$from_stdin" ]; then
  echo "FAIL: info of a mesh from standard input differs from the file's: $from_stdin"
  failures=$((failures + 1))
fi
printf '0 0.2 0\n0 0 2\n' >"$scratch/two_points.txt"
labels=$("$exe" inside --format obj - "$scratch/two_points.txt" <"$spot")
if [ "$labels" != "$(printf 'inside\noutside')" ]; then
  echo "FAIL: inside with the mesh from standard input: $labels"
  failures=$((failures + 1))
fi
expect 2 "inside mesh and points both from stdin" "0 0 0\n" inside --format obj -
# A mesh refused from standard input is explained as one read from a file: its own
# numbering, and the --weld hint.
message=$("$exe" inside --format obj - "$scratch/two_points.txt" <"$scratch/soup.obj" 2>&1 >/dev/null)
expect_in "inside refused mesh from stdin" "$message" \
  "exactgeo inside: standard input: mesh is not closed" "first: 1-2, 1-3, 2-3" \
  "numbered from 1, as in the file" "with --weld, which merges the 8 vertices"
frames="$examples/falling-vertex"
expect 0 "ccd-mesh frame from stdin" "$(cat "$frames/frame0.obj")" ccd-mesh --format obj - "$frames/frame1.obj"
expect 2 "ccd-mesh both frames from stdin" "" ccd-mesh --format obj - -

# inside --slice: a PNG cross-section instead of labels. Every mistake: exit 2, a message
# naming the option or the file, nothing on stdout, and no file left behind.
slices="$scratch/slices"
mkdir -p "$slices"
slice_refused() {  # slice_refused <description> <message substring> <args...>
  local what="$1" key="$2" message
  shift 2
  expect 2 "$what" "" "$@"
  message=$("$exe" "$@" 2>&1 >/dev/null)
  expect_in "$what message" "$message" "$key"
  if [ -n "$(ls -A "$slices")" ]; then
    echo "FAIL: $what left files behind: $(ls -A "$slices")"
    failures=$((failures + 1))
    rm -rf "${slices:?}"/*
  fi
}
png="$slices/cube.png"
slice_refused "inside --slice bad axis" "exactgeo inside: --slice: expected AXIS=VALUE" \
  inside "$cube" --slice w=1 --image "$png"
slice_refused "inside --slice bad value" "exactgeo inside: --slice: the value in 'z=abc'" \
  inside "$cube" --slice z=abc --image "$png"
slice_refused "inside --slice no value" "exactgeo inside: --slice: " inside "$cube" --slice z= --image "$png"
slice_refused "inside --slice nan" "exactgeo inside: --slice: " inside "$cube" --slice z=nan --image "$png"
slice_refused "inside --slice 1e999" "exactgeo inside: --slice: " inside "$cube" --slice x=1e999 --image "$png"
slice_refused "inside --image without --slice" "--image requires --slice" inside "$cube" --image "$png"
slice_refused "inside --slice without --image" "--slice requires --image" inside "$cube" --slice z=0
slice_refused "inside --slice unwritable image" "cannot write '$slices/missing/cube.png'" \
  inside "$cube" --slice z=0 --image "$slices/missing/cube.png"
slice_refused "inside --resolution 15" "exactgeo inside: --resolution" \
  inside "$cube" --slice z=0 --image "$png" --resolution 15
slice_refused "inside --resolution 8193" "exactgeo inside: --resolution" \
  inside "$cube" --slice z=0 --image "$png" --resolution 8193
slice_refused "inside --resolution without --slice" "--resolution requires --slice" \
  inside "$cube" --resolution 64
slice_refused "inside --slice with points" "excludes --slice" \
  inside "$cube" "$scratch/points.npy" --slice z=0 --image "$png"
slice_refused "inside --slice with --labels" "excludes --slice" \
  inside --json --labels "$cube" --slice z=0 --image "$png"
report=$("$exe" inside "$meshes/negative/corner_with_hole.off" --slice z=0.5 --image "$png" --resolution 16 2>/dev/null)
expect_in "inside --slice open mesh" "$report" "image               $png" "inside              "
report=$("$exe" inside "$cube" --slice "z=$mid" --image "$png" --resolution 16)
expect_in "inside --slice report" "$report" "image               $png, 16 x 16 pixels" \
  "plane               z = " "right               x from " "up                  y from " \
  "inside              " "boundary            0 pixels"
if [ "$(head -c 8 "$png" | od -An -c | tr -d ' ')" != '211PNG\r\n032\n' ]; then
  echo "FAIL: inside --slice did not write a PNG file"
  failures=$((failures + 1))
fi
json=$("$exe" inside "$cube" --json --slice "x=$far" --image "$png" --resolution 16 --threads 1)
expect_in "inside --slice --json" "$json" '"width": 16, "height": 16' '"plane": {"axis": "x"' \
  '"plane_meets_box": false' '"inside": 0, "outside": 256, "boundary": 0, "undecided": 0, "outline": 0'
report=$("$exe" inside "$cube" --slice "x=$far" --image "$png" --resolution 16)
expect_in "inside --slice beside the mesh" "$report" "every pixel is outside"
if [ "$(ls -A "$slices")" != "cube.png" ]; then
  echo "FAIL: inside --slice left other files: $(ls -A "$slices")"
  failures=$((failures + 1))
fi

# --mark: an unwritable path fails before any work, with nothing on stdout and no file.
expect 2 "info --mark unwritable" "" info --mark /nonexistent/dir/marked.ply "$spot"
expect 2 "ccd-mesh --mark unwritable" "" ccd-mesh --mark /nonexistent/dir/marked.ply \
  "$frames/frame0.obj" "$frames/frame1.obj"
expect 0 "ccd-mesh --mark" "" ccd-mesh --mark "$scratch/collisions.ply" "$frames/frame0.obj" \
  "$frames/frame1.obj"
if ! head -n 1 "$scratch/collisions.ply" | grep -qx ply; then
  echo "FAIL: ccd-mesh --mark wrote no PLY file"
  failures=$((failures + 1))
fi
json=$("$exe" info --json --mark "$scratch/findings.ply" "$spot")
expect_in "info --json --mark" "$json" '"intersecting_face_pairs": 0' '"undecided_face_pairs": 0' \
  '"mark": {"file": ' '"legend": [{"element": "face", "colour": "#'

# --per-query: an unwritable file is refused before the run, naming the option.
expect 2 "ccd --per-query unwritable" "" ccd --per-query /nonexistent/dir/q.csv "$unit"
message=$("$exe" ccd --per-query /nonexistent/dir/q.csv "$unit" 2>&1 >/dev/null)
expect_in "ccd --per-query unwritable message" "$message" \
  "exactgeo ccd: --per-query: cannot write '/nonexistent/dir/q.csv'"

# inside --output-dir: a labels file per mesh; exit 2 when one fails (after the others),
# and nothing run, nothing on stdout, when the meshes cannot be listed.
mkdir -p "$scratch/set/sub"
cp "$cube" "$scratch/set/cube.off"
cp "$cube" "$scratch/set/sub/cube.off"
printf '%b' "$points" >"$scratch/set_points.txt"
expect 0 "inside --output-dir" "" inside "$scratch/set" "$scratch/set_points.txt" \
  --output-dir "$scratch/set_labels"
for f in cube sub/cube; do
  labels=$(tr '\n' ' ' <"$scratch/set_labels/$f.labels.txt")
  if [ "$labels" != "inside outside boundary " ]; then
    echo "FAIL: inside --output-dir labels of $f: '$labels'"
    failures=$((failures + 1))
  fi
done
printf 'OFF\n3 1 0\n' >"$scratch/set/broken.off"
expect 2 "inside --output-dir with a broken mesh" "" inside "$scratch/set" \
  "$scratch/set_points.txt" --output-dir "$scratch/set_labels2"
if [ -e "$scratch/set_labels2/broken.labels.txt" ] || [ ! -e "$scratch/set_labels2/cube.labels.txt" ]; then
  echo "FAIL: inside --output-dir with a broken mesh: wrong files written"
  failures=$((failures + 1))
fi
expect 2 "inside --output-dir, no list" "" inside "$scratch/no-such-list.txt" \
  "$scratch/set_points.txt" --output-dir "$scratch/set_labels3"
expect 2 "inside --output-dir, points on stdin" "0 0 0\n" inside "$scratch/set" \
  --output-dir "$scratch/set_labels3"
expect 2 "inside --output-dir with --winding" "" inside "$scratch/set" "$scratch/set_points.txt" \
  --output-dir "$scratch/set_labels3" --winding
if [ -e "$scratch/set_labels3" ]; then
  echo "FAIL: inside --output-dir refused but wrote $scratch/set_labels3"
  failures=$((failures + 1))
fi

# ccd --progress off a terminal: the count of queries, as lines.
message=$("$exe" ccd --progress "$unit" 2>&1 >/dev/null)
expect_in "ccd --progress" "$message" ' queries (100.0%)'

exit $((failures > 0))
