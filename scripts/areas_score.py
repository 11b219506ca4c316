#!/usr/bin/env python3
"""Scores grid-areas on every room-segmentation map with a ground truth (docs/grid-areas.md).

Runs BUILD/bin/grid-areas with its defaults on the four variants of each map (empty, furnitures,
trashbins, furnitures_trashbins) with --score NAME_gt_segmentation.png, and prints a Markdown
table of recall / precision (%) per map and variant, the averages over the furnished maps (the
issue's target: *_furnitures), over the tuning maps (*_scan, lab_*) and the held-out ones
(office_*), and the split time per map.

Usage: scripts/areas_score.py [BUILD_DIR] [DATA_DIR] [OUT_DIR]
  defaults: build, ../shared/data/room-segmentation-maps, /tmp/indoormap-areas-score
"""
import json
import pathlib
import subprocess
import sys

MAPS = ["Freiburg52_scan", "Freiburg79_scan", "lab_a_scan", "lab_b_scan", "lab_c_scan",
        "lab_intel", "office_a", "office_b", "office_c", "office_d"]
VARIANTS = ["", "_furnitures", "_trashbins", "_furnitures_trashbins"]


def main():
    root = pathlib.Path(__file__).resolve().parent.parent
    build = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else root / "build"
    data = pathlib.Path(sys.argv[2]) if len(sys.argv) > 2 else root / ".." / "shared" / "data" / "room-segmentation-maps"
    out = pathlib.Path(sys.argv[3]) if len(sys.argv) > 3 else pathlib.Path("/tmp/indoormap-areas-score")
    rows = {}
    for m in MAPS:
        for v in VARIANTS:
            o = out / (m + v)
            cmd = [str(build / "bin" / "grid-areas"), str(data / (m + v + ".png")), "--resolution", "0.05",
                   "--score", str(data / (m + "_gt_segmentation.png")), "-q", "-o", str(o)]
            if subprocess.run(cmd).returncode != 0:  # e.g. an image of another size than its truth
                rows[(m, v)] = None
                continue
            s = json.loads((o / "score.json").read_text())
            t = json.loads((o / "summary.json").read_text())
            rows[(m, v)] = (100 * s["recall"], 100 * s["precision"], t["timings_ms"]["split"])
    print("| map | empty | furnitures | trashbins | furnitures + trashbins | split ms (furnished) |")
    print("|---|---|---|---|---|---|")
    for m in MAPS:
        cells = ["%.1f / %.1f" % rows[(m, v)][:2] if rows[(m, v)] else "n/a" for v in VARIANTS]
        print("| %s | %s | %.0f |" % (m, " | ".join(cells), rows[(m, "_furnitures")][2]))

    def avg(maps, v):
        got = [rows[(m, v)] for m in maps if rows[(m, v)]]
        r = sum(g[0] for g in got) / len(got)
        p = sum(g[1] for g in got) / len(got)
        return "%.1f / %.1f" % (r, p) + ("" if len(got) == len(maps) else " (%d maps)" % len(got))

    tune = [m for m in MAPS if not m.startswith("office")]
    held = [m for m in MAPS if m.startswith("office")]
    for name, maps in (("all 10", MAPS), ("tuning (*_scan, lab_*)", tune), ("held out (office_*)", held)):
        print("| **average, %s** | %s |  |" % (name, " | ".join(avg(maps, v) for v in VARIANTS)))


if __name__ == "__main__":
    main()
