#!/bin/sh
# Installs the Debian 12 packages exactgeo builds and tests with, skipping those present.
# Nothing else is ever downloaded: the build uses only these system packages.
set -eu

packages="g++ cmake make pkg-config libgmp-dev libmpfr-dev libgtest-dev libgmock-dev libbenchmark-dev
libcli11-dev libembree-dev libassimp-dev libeigen3-dev libpng-dev zlib1g-dev
python3 python3-dev pybind11-dev python3-numpy python3-pytest python3-dask python3-distributed
python3-pil"

missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0

sudo=""
[ "$(id -u)" -ne 0 ] && sudo="sudo"
echo "installing:$missing" >&2
$sudo apt-get update
# shellcheck disable=SC2086
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $missing
