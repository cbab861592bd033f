#!/usr/bin/env bash
# consumer_test.sh BUILD_DIR SOURCE_DIR WORK_DIR: installs the build tree BUILD_DIR into
# WORK_DIR/prefix, then configures, builds and runs the consumer project SOURCE_DIR
# against that prefix only, with the build's compiler, build type and sanitizers. Any
# failure fails the test (ctest install.consumer).
set -eu
build_dir=$1
source_dir=$2
work_dir=$3

# A value from the exactgeo build's cache (NAME:TYPE=value), empty if unset.
cache() { sed -n "s/^$1:[A-Z]*=//p" "$build_dir/CMakeCache.txt"; }
build_type=$(cache CMAKE_BUILD_TYPE)
compiler=$(cache CMAKE_CXX_COMPILER)
flags=""
if [ "$(cache EXACTGEO_SANITIZE)" = ON ]; then
  # The installed static libraries are instrumented; the consumer must link the runtimes.
  flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
fi

rm -rf "$work_dir/prefix" "$work_dir/build" "$work_dir/build-files"
cmake --install "$build_dir" --prefix "$work_dir/prefix" ${build_type:+--config "$build_type"}

# Configures and builds the consumer in build dir $1 with the extra cmake arguments after
# it, searching only the install prefix, with the build's compiler, type and sanitizers.
build_consumer() {
  local dir=$1
  shift
  cmake -S "$source_dir" -B "$dir" --no-warn-unused-cli \
    -DCMAKE_PREFIX_PATH="$work_dir/prefix" \
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF \
    -DCMAKE_BUILD_TYPE="$build_type" \
    -DCMAKE_CXX_COMPILER="$compiler" \
    -DCMAKE_CXX_FLAGS="$flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$flags" "$@"
  local found
  found=$(sed -n 's/^exactgeo_DIR:[A-Z]*=//p' "$dir/CMakeCache.txt")
  case "$found" in
    "$work_dir/prefix/"*) ;;
    *) echo "consumer found exactgeo in '$found', not under $work_dir/prefix" >&2; exit 1 ;;
  esac
  cmake --build "$dir" ${build_type:+--config "$build_type"}
}

# The dependencies a consumer need not have (test and CLI packages, and assimp without
# exactgeo::mesh_files) are switched off: find_package(exactgeo) must not want them.
build_consumer "$work_dir/build" -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON \
  -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON -DCMAKE_DISABLE_FIND_PACKAGE_assimp=ON
"$work_dir/build/consumer"

# Again with assimp allowed: exactgeo::mesh_files is imported and loads files, by the
# exact readers and through assimp (a RAW tetrahedron, a triangle a line, welded).
build_consumer "$work_dir/build-files" -DCONSUMER_MESH_FILES=ON
cat >"$work_dir/tetrahedron.raw" <<'RAW'
0 0 0 0 1 0 1 0 0
0 0 0 1 0 0 0 0 1
0 0 0 0 0 1 0 1 0
1 0 0 0 1 0 0 0 1
RAW
"$work_dir/build-files/load_mesh_file" "$source_dir/../../data/meshes/cgal/cube_quad.off" \
  "$work_dir/tetrahedron.raw"

# The Python package, when built: installed under the prefix, importable from there, and
# its default place (relative to the prefix) is one Debian's python3 searches for the
# default prefix /usr/local.
python_dir=$(cache EXACTGEO_PYTHON_INSTALL_DIR)
if [ "$(cache EXACTGEO_BUILD_PYTHON)" = ON ] && [ -n "$python_dir" ]; then
  python=$(cache Python3_EXECUTABLE)
  test -f "$work_dir/prefix/$python_dir/exactgeo/__init__.py"
  "$python" -c "import sys; sys.exit('/usr/local/$python_dir' not in sys.path)" ||
    { echo "$python does not search /usr/local/$python_dir" >&2; exit 1; }
  if [ "$(cache EXACTGEO_SANITIZE)" != ON ]; then  # (an instrumented module needs the runtimes preloaded)
    PYTHONPATH="$work_dir/prefix/$python_dir" "$python" -c "
import exactgeo, sys
assert exactgeo.__file__.startswith('$work_dir/prefix/'), exactgeo.__file__
mesh = exactgeo.load_mesh('$source_dir/../../data/meshes/cgal/cube_quad.off')
assert exactgeo.Classifier(mesh).classify([[0.5, 0.5, 0.5]])[0] == exactgeo.INSIDE
"
  fi
fi
