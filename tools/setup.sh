#!/usr/bin/env bash
# Installs every Debian 12 package fluidsound needs (a no-op when all are present), then
# configures and builds the project in build/ (Release). Safe to run again at any time.
#   usage: tools/setup.sh [--no-build | --target TARGET]
# --target builds one CMake target and what it needs (the quick start builds the `fluidsound`
# CLI only, not the tests and benchmarks).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

packages=(
  build-essential cmake ninja-build pkg-config ccache git
  libeigen3-dev libtbb-dev libsndfile1-dev
  libopenvdb-dev libboost-iostreams-dev libembree-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libtinyobjloader-dev
  libcairo2-dev libebur128-dev libsuitesparse-dev libspectra-dev
  libmysofa-dev       # SOFA HRTF sets; its runtime package ships the MIT KEMAR set
  libbullet-dev       # rigid bodies of the solids (zlib licence)
  python3 time        # tools/make_example_bubbles.py and tools/bench.sh only
  clang-14 libclang-rt-14-dev   # tools/fuzz.sh only: libFuzzer and the sanitizers' runtimes
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -q
  "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

[ "${1:-}" = "--no-build" ] && exit 0
target=()
if [ "${1:-}" = "--target" ]; then
  [ -n "${2:-}" ] || { echo "setup: --target needs a CMake target name" >&2; exit 2; }
  target=(--target "$2")
fi

launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
if [ ! -f "$here/build/CMakeCache.txt" ]; then
  cmake -S "$here" -B "$here/build" -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >&2
fi
cmake --build "$here/build" -j"$(nproc)" "${target[@]}" >&2
