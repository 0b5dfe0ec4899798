#!/usr/bin/env bash
# Installs the Debian 12 packages shockmap needs (only those missing), then configures and
# builds it in ./build. Sourced by run-main and run-tests, which may list extra packages in
# SHOCKMAP_EXTRA_PACKAGES first, and the build targets in SHOCKMAP_BUILD_TARGETS (every target
# when unset); safe to run again.
set -euo pipefail

SHOCKMAP_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SHOCKMAP_BUILD=${SHOCKMAP_BUILD:-$SHOCKMAP_ROOT/build}

# Each package and why it is here is listed in the README ("Dependencies").
SHOCKMAP_PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libspectra-dev libsuitesparse-dev liblapack-dev libgsl-dev libfftw3-dev
  libsqlite3-dev sqlite3 nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libopenmpi-dev openmpi-bin
  gnuplot-nox help2man
  python3-dev pybind11-dev python3-numpy python3-pandas
)

install_missing_packages() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -eq 0 ]; then
    return
  fi
  echo "shockmap: installing ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# configure_build DIR CMAKE_ARGS...: configures the build folder DIR. Ninja compiles a target's
# sources while the libraries it links are still being compiled (Make waits for each library
# whole); a build folder keeps the generator it was made with.
configure_build() {
  local dir=$1
  shift
  local generator=()
  [ -f "$dir/CMakeCache.txt" ] || generator=(-G Ninja)
  cmake -S "$SHOCKMAP_ROOT" -B "$dir" ${generator[@]+"${generator[@]}"} "$@" >/dev/null
}

build_shockmap() {
  configure_build "$SHOCKMAP_BUILD" -DCMAKE_BUILD_TYPE=Release
  local targets=()
  for t in ${SHOCKMAP_BUILD_TARGETS[@]+"${SHOCKMAP_BUILD_TARGETS[@]}"}; do
    targets+=(--target "$t")
  done
  cmake --build "$SHOCKMAP_BUILD" -j "$(nproc)" ${targets[@]+"${targets[@]}"}
}

install_missing_packages "${SHOCKMAP_PACKAGES[@]}" ${SHOCKMAP_EXTRA_PACKAGES[@]+"${SHOCKMAP_EXTRA_PACKAGES[@]}"}
build_shockmap
