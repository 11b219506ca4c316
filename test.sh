#!/usr/bin/env bash
# Builds and runs the whole test suite with ctest (installs missing packages first).
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh build
cd build
ctest --output-on-failure --timeout 1200 -j "${INDOORMAP_JOBS:-2}"
