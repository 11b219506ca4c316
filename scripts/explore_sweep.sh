#!/usr/bin/env bash
# The full shared-map exploration sweep: every furnished room-segmentation map of
# ../shared/data (or $INDOORMAP_DATA) from three fixed starts, with both goal rules (the paper's
# nearest frontier and gain per cost): 60 runs, 3.5-8 minutes in Release on two cores, depending
# on load. It prints every run's figures and checks that the gain rule reaches 95 % of the
# reachable free space in every run, the paper rule in 28 of 30, and that the gain rule needs at
# most 0.85 x the paper rule's distance to 95 % (ratio of the sums). The test is
# ExploreShared.EveryFurnishedMapFromThreeStarts in tests/test_exploration.cpp; ctest skips it
# (CI's budget) and runs the two-map subset ExploreShared.TwoFreiburgMapsFromTheirMiddleStart.
#
# Usage: scripts/explore_sweep.sh [BUILD_DIR]   (default build/; configured first if new)
# INDOORMAP_JOBS (default 2): build parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in -h | --help) sed -n '2,12p' "$0"; exit 0 ;; esac
build="${1:-build}"
[ -f "$build/build.ninja" ] || scripts/setup.sh "$build" -DINDOORMAP_BUILD_BENCH=OFF
cmake --build "$build" -j "${INDOORMAP_JOBS:-2}" --target test_exploration
INDOORMAP_EXPLORE_SWEEP=1 "$build/bin/test_exploration" \
  --gtest_filter='ExploreShared.EveryFurnishedMapFromThreeStarts'
