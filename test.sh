#!/usr/bin/env bash
# Builds and runs the whole test suite with ctest (installs missing packages first).
#
# Usage: ./test.sh [--sanitize] [--fuzz]
#   (no flag)    build/ (Release) and ctest.
#   --sanitize   then the whole suite once more under AddressSanitizer + UndefinedBehaviorSanitizer
#                (gcc, build-asan/, -DINDOORMAP_SANITIZE=ON, benchmarks off); any report fails it.
#   --fuzz       then every libFuzzer target of tests/fuzz for a bounded time (scripts/fuzz.sh:
#                1 M executions or 120 s per target, whichever first; clang-14, build-fuzz/).
# The same through the environment: INDOORMAP_TEST_SANITIZE=1, INDOORMAP_TEST_FUZZ=1.
# .ci/run uses both. Timings on the CI machine: docs/robustness.md.
set -euo pipefail
cd "$(dirname "$0")"
sanitize="${INDOORMAP_TEST_SANITIZE:-0}"
fuzz="${INDOORMAP_TEST_FUZZ:-0}"
for a in "$@"; do
  case "$a" in
    --sanitize) sanitize=1 ;;
    --fuzz) fuzz=1 ;;
    -h | --help) sed -n '2,12p' "$0"; exit 0 ;;
    *) echo "test.sh: unknown option '$a' (see --help)" >&2; exit 2 ;;
  esac
done
jobs="${INDOORMAP_JOBS:-2}"

stage() { echo "test.sh: [$(date +%T)] $*" >&2; }

stage "build/ + ctest"
scripts/setup.sh build
(cd build && ctest --output-on-failure --timeout 1200 -j "$jobs")

if [ "$sanitize" = 1 ]; then
  stage "build-asan/ + ctest under ASan + UBSan"
  scripts/setup.sh build-asan -DINDOORMAP_SANITIZE=ON -DINDOORMAP_BUILD_BENCH=OFF
  # halt_on_error: a UBSan report fails the test instead of scrolling by. Leaks are reported at
  # exit (LeakSanitizer), in the test binaries and in the apps they run. Suppressions (third-party
  # code only, each with its reason): tests/sanitizers/.
  export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$PWD/tests/sanitizers/ubsan.supp"
  export ASAN_OPTIONS="detect_leaks=1:check_initialization_order=1"
  export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizers/lsan.supp"
  (cd build-asan && ctest --output-on-failure --timeout 2400 -j "$jobs")
fi

if [ "$fuzz" = 1 ]; then
  stage "fuzz targets (scripts/fuzz.sh)"
  scripts/fuzz.sh
fi
stage "done"
