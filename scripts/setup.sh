#!/usr/bin/env bash
# Installs missing Debian packages (as root, or through sudo), then configures and builds.
# Usage: scripts/setup.sh BUILD_DIR [extra cmake args...]
#   A new BUILD_DIR is configured (Release, Ninja; clang-14 when the args hold -DINDOORMAP_FUZZ=ON);
#   an existing one is configured again only when extra args are given (they update its cache).
# Env: INDOORMAP_JOBS (default 2) build parallelism; INDOORMAP_TARGETS (default: all) the ninja
#   targets to build, space separated.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake g++ ninja-build pkg-config libpcl-dev libeigen3-dev libopencv-dev libyaml-cpp-dev
  nlohmann-json3-dev libcli11-dev libgtest-dev libgmock-dev libbenchmark-dev zlib1g-dev libpng-dev lld
  libssl-dev chromium pybind11-dev python3-dev python3-numpy parallel)
# libssl-dev: SHA-256 of the inputs (summary.json "provenance"); chromium: the headless-browser
# test of report.html (tests/test_report_slow.cpp); pybind11-dev, python3-dev, python3-numpy: the
# Python module (apps/python, tests/python); parallel: the batch recipe (scripts/batch.sh).
# The sanitizer + fuzz build (-DINDOORMAP_FUZZ=ON: ./test.sh --sanitize, scripts/fuzz.sh) needs
# clang and its sanitizer / libFuzzer runtimes.
fuzz=0
for a in "${@:2}"; do [ "$a" = "-DINDOORMAP_FUZZ=ON" ] && fuzz=1; done
[ $fuzz -eq 1 ] && packages+=(clang-14 libclang-rt-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "indoormap: installing missing packages: ${missing[*]}" >&2
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

build_dir="$1"
shift
if [ ! -f "$build_dir/build.ninja" ]; then
  if [ $fuzz -eq 1 ]; then
    CC=clang-14 CXX=clang++-14 cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >&2
  else
    cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release "$@" >&2
  fi
elif [ $# -gt 0 ]; then
  cmake "$build_dir" "$@" >/dev/null
fi
# shellcheck disable=SC2086  # INDOORMAP_TARGETS is a list
cmake --build "$build_dir" --parallel "${INDOORMAP_JOBS:-2}" ${INDOORMAP_TARGETS:+--target $INDOORMAP_TARGETS} >&2
