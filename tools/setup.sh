#!/usr/bin/env bash
# Installs what anisomesh needs to build and test, from Debian packages only.
# Idempotent: apt-get update runs only when something is missing.
# usage: tools/setup.sh [--with-freecad]
set -euo pipefail
pkgs=(
  build-essential cmake
  libocct-data-exchange-dev libocct-modeling-algorithms-dev libocct-modeling-data-dev
  libocct-foundation-dev libocct-ocaf-dev
  libeigen3-dev libopenmesh-dev libgtest-dev libbenchmark-dev libcli11-dev
  nlohmann-json3-dev libmuparser-dev libtbb-dev zlib1g-dev
  gmsh python3-gmsh python3-meshio python3-numpy calculix-ccx python3-vtk9
  pybind11-dev python3-dev
)
if [ "${1:-}" = "--with-freecad" ]; then pkgs+=(freecad-python3); fi
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then exit 0; fi
echo "setup: installing ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
