#!/usr/bin/env bash
# Sparse scans (issue 17): default random scenes (`scene-sim --random --seed N`, default tilt and
# corridor) scanned at angular steps of 0.5, 1 and 2 degrees and with a 16-beam lidar
# (config/scene-sim-16beam.yaml), run through pcd-to-map and furniture-extract with their
# defaults and scored by map-eval with its defaults. Prints per case one row per seed (with
# ROWS=1) and the totals: pcd-to-map failures, object recall (truth items >= 0.1 m2) and
# precision (every object furniture-extract wrote), median |z_max error|, room polygons within
# 0.15 m Hausdorff and 3 % area, free-space IoU over the seen cells and over all truth-free
# cells (map.pgm, and the layout M_r), and the far free area: result free cells farther than
# 0.5 m from every seen cell (map-eval's floor.*.far_free; in m2 and as a share of the free
# area). The case "default" is scene-sim's own step (0.25 degrees). docs/evaluation.md holds the
# figures (scripts/eval_report.sh). Seeds 1-20 tune, 21-40 are checked once. Simulations are
# kept in OUT/<case>/sim_N and reused.
#
# Usage: scripts/sparse_eval.sh [BUILD_DIR] [FIRST_SEED] [LAST_SEED]   (default build 1 20)
# Environment: CASES ("0.5 1 2 16beam"; a number is a --step-deg, "default" scene-sim's own
# step), OUT (/tmp/sparse_eval), ROWS (1: print every seed), PCD_ARGS (extra pcd-to-map and
# furniture-extract options).
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in -h | --help) sed -n '2,18p' "$0"; exit 0 ;; esac
build="${1:-build}"
first="${2:-1}"
last="${3:-20}"
bin="$build/bin"
out="${OUT:-/tmp/sparse_eval}"
for c in ${CASES:-0.5 1 2 16beam}; do
  dir="$out/$c"
  mkdir -p "$dir"
  simargs=(--step-deg "$c")
  [ "$c" = 16beam ] && simargs=(-c config/scene-sim-16beam.yaml)
  [ "$c" = default ] && simargs=()
  for s in $(seq "$first" "$last"); do
    sim="$dir/sim_$s"
    [ -f "$sim/ground_truth.json" ] ||
      "$bin/scene-sim" --random --seed "$s" "${simargs[@]}" -q -o "$sim" >/dev/null
    rm -rf "$dir/res_$s" "$dir/fe_$s" "$dir/eval_$s" "$dir/evalfe_$s"
    # shellcheck disable=SC2086  # PCD_ARGS is a list
    if ! "$bin/pcd-to-map" "$sim/cloud.pcd" -q -o "$dir/res_$s" ${PCD_ARGS:-} >/dev/null \
      2>"$dir/err_$s"; then
      continue
    fi
    "$bin/map-eval" -q --truth "$sim/ground_truth.json" --result "$dir/res_$s" -o "$dir/eval_$s"
    # shellcheck disable=SC2086
    if "$bin/furniture-extract" "$sim/cloud.pcd" -q -o "$dir/fe_$s" ${PCD_ARGS:-} >/dev/null \
      2>>"$dir/err_$s"; then
      "$bin/map-eval" -q --truth "$sim/ground_truth.json" --result "$dir/fe_$s" \
        -o "$dir/evalfe_$s"
    fi
  done
done
python3 - "$out" "$first" "$last" "${CASES:-0.5 1 2 16beam}" "${ROWS:-0}" <<'PY'
import json, os, statistics, sys
out, first, last, cases, rows = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4].split(), sys.argv[5] == "1"
def load(p):
    return json.load(open(p)) if os.path.exists(p) else None
def g(d, *keys):
    for k in keys:
        if not isinstance(d, dict) or d.get(k) is None: return None
        d = d[k]
    return d
def border_ok(e):
    best = None
    for r in g(e, "room", "rooms") or []:
        t = r.get("truth_room")
        if not t or t.startswith("corridor"): continue
        if best is None or r["iou"] > best["iou"]: best = r
    if best is None: return False, None, None
    return (best["hausdorff_m"] <= 0.15 and abs(best["area_error_rel"]) <= 0.03,
            best["hausdorff_m"], best["area_error_rel"])
print("%-7s %5s %5s %7s %7s %6s %7s %8s %8s %8s %8s %9s %9s" % (
    "case", "seeds", "fail", "recall", "precis", "dz_med", "border", "map_seen", "map_all",
    "lay_seen", "lay_all", "map_far", "lay_far"))
for c in cases:
    n = fail = T = M = MA = R = bpass = 0
    errs, ms, ma, ls, la = [], [], [], [], []
    far = {"map": [0.0, 0.0], "layout": [0.0, 0.0]}
    for s in range(first, last + 1):
        n += 1
        e = load("%s/%s/eval_%d/eval.json" % (out, c, s))
        fe = load("%s/%s/evalfe_%d/eval.json" % (out, c, s))
        if e is None:
            fail += 1
            err = open("%s/%s/err_%d" % (out, c, s)).read().strip().splitlines()
            if rows: print("  %s seed %2d: pcd-to-map failed: %s" % (c, s, err[-1][:150] if err else "?"))
            continue
        o = (fe or {}).get("objects", {})
        if o.get("status") == "ok":
            T += o["truth_count"]; R += o["result_count"]; M += o["matched"]; MA += o["matched_all"]
            errs += [abs(m["z_max_error_m"]) for m in o["matches"] if m.get("z_max_error_m") is not None]
        ok, hd, ar = border_ok(e)
        bpass += ok
        vals = {}
        for k, lst_s, lst_a in (("map", ms, ma), ("layout", ls, la)):
            v_s = g(e, "floor", k, "seen_free_iou", "iou"); v_a = g(e, "floor", k, "free_iou_all", "iou")
            lst_s.append(v_s or 0.0); lst_a.append(v_a or 0.0)
            ff = g(e, "floor", k, "far_free") or {}
            far[k][0] += ff.get("far_m2", 0.0); far[k][1] += ff.get("free_m2", 0.0)
            vals[k] = (v_s or 0.0, v_a or 0.0, ff.get("far_m2", 0.0))
        if rows:
            print("  %s seed %2d: objects %s/%s (written %s) border %s (%.3f m, %+.1f %%) map seen %.3f far %.2f m2, layout seen %.3f far %.2f m2"
                  % (c, s, o.get("matched"), o.get("truth_count"), o.get("result_count"), "ok" if ok else "NO",
                     hd if hd is not None else -1, 100 * (ar or 0), vals["map"][0], vals["map"][2],
                     vals["layout"][0], vals["layout"][2]))
    mean = lambda l: sum(l) / len(l) if l else 0.0
    def farf(k):
        return "%.2f/%.3f" % (far[k][0], far[k][0] / far[k][1] if far[k][1] else 0.0)
    # IoU figures: the mean over the seeds, a failed run counting 0.
    pad = [0.0] * fail
    print("%-7s %5d %5d %7.3f %7.3f %6.3f %4d/%-2d %8.3f %8.3f %8.3f %8.3f %9s %9s" % (
        c, n, fail, M / max(T, 1), MA / max(R, 1), statistics.median(errs) if errs else -1,
        bpass, n, mean(ms + pad), mean(ma + pad), mean(ls + pad), mean(la + pad), farf("map"), farf("layout")))
PY
