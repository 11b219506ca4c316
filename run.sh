#!/usr/bin/env bash
# Quick start: builds what is needed, then runs pcd-to-map on the project's default cloud.
# Extra arguments are passed to pcd-to-map (e.g. ./run.sh --print-config).
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh build
cloud="clouds/office/cloud.pcd"  # simulated office, made by scene-sim (docs/scene-sim.md)
out="out"
build/bin/pcd-to-map "$cloud" -o "$out" "$@"
echo "indoormap: outputs in $(pwd)/$out: map.pgm + map.yaml (ROS map), layout.png, layout.pgm, objects.json,"
echo "           room.geojson, border.png, summary.json"
