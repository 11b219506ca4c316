#!/usr/bin/env bash
# The Jacobs scan as a user gets it (issues 16 and 17): the shared 3DTK scan
# (../shared/data/jacobs-thermocolorlab, or $INDOORMAP_DATA/jacobs-thermocolorlab) through
# pcd-to-map and furniture-extract with their defaults, then through pcd-to-map again on parts
# of it: each of its nine 40-degree sectors alone (--scans k) and three consecutive ones (0-2,
# 3-5, 6-8). Prints the room (area, doors, rooms found), the objects (count, the smallest area,
# left-over cells) and, per part, whether it was levelled, its tilt, the angle between its up
# direction and the full scan's, and its warning about the horizon. There is no ground truth
# for this scan; scripts/eval_report.sh puts the figures into docs/evaluation.md. Without the
# data it prints "jacobs: data absent" and exits 0.
#
# Usage: scripts/jacobs_eval.sh [BUILD_DIR]   (default build/)
# Environment: OUT (/tmp/jacobs_eval), INDOORMAP_DATA (../shared/data).
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in -h | --help) sed -n '2,13p' "$0"; exit 0 ;; esac
build="${1:-build}"
bin="$build/bin"
out="${OUT:-/tmp/jacobs_eval}"
data="${INDOORMAP_DATA:-../shared/data}/jacobs-thermocolorlab"
if [ ! -d "$data" ]; then
  echo "jacobs: data absent ($data)"
  exit 0
fi
rm -rf "$out"
mkdir -p "$out"
"$bin/pcd-to-map" "$data" -q -o "$out/full" >/dev/null 2>"$out/full.err"
"$bin/furniture-extract" "$data" -q -o "$out/objects" >/dev/null 2>"$out/objects.err"
parts="0 1 2 3 4 5 6 7 8 0-2 3-5 6-8"
for p in $parts; do
  "$bin/pcd-to-map" "$data" --scans "$p" -q -o "$out/part_$p" >/dev/null 2>"$out/part_$p.err" ||
    echo "exit $?" >>"$out/part_$p.err"
done
python3 - "$out" "$parts" <<'PY'
import json, math, os, sys
out, parts = sys.argv[1], sys.argv[2].split()
def load(p):
    return json.load(open(p)) if os.path.exists(p) else None
def area(ring):
    return abs(sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(ring, ring[1:] + ring[:1]))) / 2
full = load(os.path.join(out, "full", "summary.json"))
geo = load(os.path.join(out, "full", "room.geojson")) or {"features": []}
room = [f for f in geo["features"] if f["properties"].get("kind") == "room"]
room_area = area(room[0]["geometry"]["coordinates"][0]) if room else 0.0
floor = load(os.path.join(out, "full", "rooms.geojson")) or {"features": []}
pieces = sorted(f["properties"]["area_m2"] for f in floor["features"]
                if f["properties"].get("kind") == "room")
doors = [f["properties"] for f in floor["features"] if f["properties"].get("kind") == "door"]
print("jacobs full: levelled %d tilt %.2f deg, room.geojson %.1f m2 with %d openings, "
      "rooms.geojson %d rooms (largest %.1f m2, others %s m2), %d doors (%s m wide)" % (
    full["levelling"]["levelled"], full["levelling"]["tilt_deg"], room_area,
    len(full["border"]["openings"]), len(pieces), pieces[-1] if pieces else 0.0,
    ", ".join("%.1f" % a for a in pieces[:-1]) or "none", len(doors),
    ", ".join("%.2f" % d["width_m"] for d in doors) or "-"))
objs = (load(os.path.join(out, "objects", "objects.json")) or {}).get("objects", [])
fe = load(os.path.join(out, "objects", "summary.json")) or {}
min_area = fe.get("parameters", {}).get("objects", {}).get("min_area_m2")
areas = [o["area_m2"] for o in objs]
lamps = sum(1 for o in objs if o.get("kind") in ("lamp", "hanging"))
print("jacobs objects: %d written (%d lamps), smallest %.3f m2, min_area_m2 %s, below it %d, "
      "left over %s cells" % (len(objs), lamps, min(areas) if areas else 0.0, min_area,
                              sum(1 for a in areas if min_area is not None and a < min_area - 1e-9),
                              fe.get("objects", {}).get("left_over_cells")))
up_full = full["levelling"]["up_input"]
for p in parts:
    s = load(os.path.join(out, "part_" + p, "summary.json"))
    if s is None:
        print("jacobs part %s: no output" % p)
        continue
    lv = s["levelling"]
    dot = sum(a * b for a, b in zip(lv["up_input"], up_full))
    angle = math.degrees(math.acos(max(-1.0, min(1.0, dot))))
    horizon = [w for w in s.get("warnings", []) if "of the horizon" in w]
    share = horizon[0].split("only ")[1].split(" %")[0] if horizon else "-"
    print("jacobs part %s: levelled %d tilt %.2f deg, off the full scan's up %.2f deg, "
          "horizon %s %%, warned %d" % (p, lv["levelled"], lv["tilt_deg"] if lv["levelled"] else 0.0,
                                        angle, share, 1 if horizon else 0))
PY
