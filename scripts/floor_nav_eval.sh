#!/usr/bin/env bash
# The navigation-map figures of docs/evaluation.md ("Whole floors"): scene-sim buildings of N rooms
# (fixed seeds), pcd-to-map from the 3DTK scans and from the merged cloud.pcd with --scanner per
# position, scored by scripts/floor_nav_eval.py. Usage: scripts/floor_nav_eval.sh [BIN] [WORK]
set -euo pipefail
BIN=${1:-build/bin}
WORK=${2:-/tmp/floor_nav_eval}
HERE=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$WORK"
for rooms in 4 8 12; do
  seed=1
  scene="$WORK/b${rooms}"
  [ -f "$scene/cloud.pcd" ] || "$BIN/scene-sim" --random --rooms "$rooms" --seed "$seed" --3dtk -q -o "$scene"
  scanners=$(for f in "$scene"/3dtk/*.pose; do
    head -1 "$f" | awk '{printf " --scanner %.4f,%.4f,%.4f", $3/100, -$1/100, $2/100}'; done)
  "$BIN/pcd-to-map" "$scene/3dtk" -q -o "$WORK/b${rooms}_3dtk" >/dev/null
  # shellcheck disable=SC2086
  "$BIN/pcd-to-map" "$scene/cloud.pcd" $scanners -q -o "$WORK/b${rooms}_merged" >/dev/null 2>&1
  for run in 3dtk merged; do
    printf '%s rooms=%s seed=%s %s ' "$(date -u +%F)" "$rooms" "$seed" "$run"
    python3 "$HERE/floor_nav_eval.py" "$scene" "$WORK/b${rooms}_${run}"
  done
done
