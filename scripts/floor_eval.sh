#!/usr/bin/env bash
# Whole-floor evaluation (issue 15): simulated buildings of 4, 8 and 12 rooms along a corridor
# (fixed seeds), 1 and 2 storeys, scanned with one position per room and in the mobile-scanner
# mode, run through pcd-to-map and scored by map-eval. Modes:
#   tdtk          pcd-to-map DIR/3dtk (a pose per scan)
#   merged        pcd-to-map DIR/cloud.pcd --scanner X,Y,Z for every truth position
#   mobile-traj   scene-sim --mobile; pcd-to-map DIR/cloud.pcd --trajectory DIR/trajectory.txt
#   mobile        the same cloud without positions
# A mode whose pcd-to-map option is missing in this build is reported as "n/a". Prints one row
# per storey: doors open (share), scanners reachable (components holding scanners; 1 = all
# reachable), free-space IoU over the seen cells and over all truth-free cells (map.pgm), the
# floor error, and the share of truth furniture that map.pgm calls free (furn_free).
# Each row is followed by the rooms of that storey (map-eval's "rooms" block; issue 16): truth
# rooms (corridor included), found / missed / split / merged, rooms within 0.15 m Hausdorff and
# 3 % area, doors found, objects (>= 0.1 m2) recall / precision and objects in no truth room.
# docs/evaluation.md (scripts/eval_report.sh) holds the figures. Simulations are kept in OUT and reused by a
# later run (delete OUT after changing STEP_DEG or scene-sim).
#
# Usage: scripts/floor_eval.sh [BUILD_DIR]   (default build/)
# Environment: ROOMS ("4 8 12"), STOREYS ("1 2"), MODES ("tdtk merged mobile-traj mobile"),
# STEP_DEG (empty: scene-sim's default 0.25), OUT (/tmp/floor_eval), PCD_ARGS (extra
# pcd-to-map options), INDOORMAP_JOBS (2), SEED_OFFSET (0; 400: the fresh seeds 541 ... 622,
# never tuned on).
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in -h | --help) sed -n '2,22p' "$0"; exit 0 ;; esac
build="${1:-build}"
bin="$build/bin"
[ -f "$build/build.ninja" ] || scripts/setup.sh "$build" -DINDOORMAP_BUILD_BENCH=OFF
cmake --build "$build" -j "${INDOORMAP_JOBS:-2}" --target scene-sim pcd-to-map map-eval >/dev/null
out="${OUT:-/tmp/floor_eval}"
mkdir -p "$out"
step=()
[ -n "${STEP_DEG:-}" ] && step=(--step-deg "$STEP_DEG")
has_opt() { "$bin/pcd-to-map" --help | grep -q -- "$1"; }

# Scanner positions (cloud frame) of every storey of a scene-sim ground truth, as --scanner args.
scanner_args() {
  python3 - "$1" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
lists = [s["scanners"] for s in j.get("storeys", [])] or [j["scanners"]]
print(" ".join("--scanner %.4f,%.4f,%.4f" % tuple(s["position_cloud_m"]) for l in lists for s in l))
PY
}

# One table row per storey of eval.json (the storeys block, else the top level).
rows() {
  python3 - "$1" "$2" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))
def g(d, *keys):
    for k in keys:
        if not isinstance(d, dict) or d.get(k) is None: return None
        d = d[k]
    return d
def f(v): return "-" if v is None else ("%.3f" % v if isinstance(v, float) else str(v))
# With storeys: the top level (truth storey 0 against RESULT itself) as "-", then each storey.
parts = ([("-", e)] + [(s["k"], s) for s in e["storeys"]]) if e.get("storeys") else [(0, e)]
for k, s in parts:
    fl = s.get("floor", {})
    print("%-28s %2s %8s %6s %10s %8s %8s %9s %9s" % (sys.argv[2], k,
          f(g(fl, "doors", "open_share")), f(g(fl, "doors", "doors")),
          f(g(fl, "reachability", "components")), f(g(fl, "map", "seen_free_iou", "iou")),
          f(g(fl, "map", "free_iou_all", "iou")), f(s.get("floor_error_m")),
          f(g(fl, "map", "furniture_free", "share"))))
PY
}

# The rooms line of each storey of eval.json.
room_rows() {
  python3 - "$1" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))
parts = ([("-", e)] + [(s["k"], s) for s in e["storeys"]]) if e.get("storeys") else [(0, e)]
for k, s in parts:
    r, o = s.get("rooms", {}), s.get("objects", {})
    if r.get("status") != "ok":
        print("    rooms st %s: %s" % (k, r.get("status", "-")))
        continue
    print("    rooms st %s: truth %d found %d missed %d split %d merged %d within %d/%d "
          "doors %d/%d objects recall %.3f precision %.3f (%d), outside rooms %d" % (
          k, r["truth_rooms"], r["found"], r["missed"], r["split"], r["merged"],
          r["within_tolerance"], r["truth_rooms"], r["doors_found"], r["truth_doors"],
          o.get("recall") or 0, o.get("precision") or 0, o.get("result_count") or 0,
          r.get("objects_outside_rooms", 0)))
PY
}

printf "%-28s %2s %8s %6s %10s %8s %8s %9s %9s\n" case st doors_op doors scan_comps seen_iou all_iou \
  floor_err furn_free
seed_of() { echo $((100 + ${SEED_OFFSET:-0} + $1 * 10 + $2)); }
for rooms in ${ROOMS:-4 8 12}; do
  for storeys in ${STOREYS:-1 2}; do
    seed=$(seed_of "$rooms" "$storeys")
    base="$out/r${rooms}_s${storeys}"
    for mode in ${MODES:-tdtk merged mobile-traj mobile}; do
      sim="$base/sim_fixed"
      simargs=(--3dtk)
      case "$mode" in mobile*) sim="$base/sim_mobile"; simargs=(--mobile) ;; esac
      if [ ! -f "$sim/ground_truth.json" ]; then
        "$bin/scene-sim" --random --seed "$seed" --rooms "$rooms" --storeys "$storeys" \
          "${simargs[@]}" "${step[@]}" -q -o "$sim"
      fi
      res="$base/$mode"
      args=()
      case "$mode" in
        tdtk) input="$sim/3dtk" ;;
        merged) input="$sim/cloud.pcd"; read -r -a args <<<"$(scanner_args "$sim/ground_truth.json")" ;;
        mobile-traj)
          input="$sim/cloud.pcd"
          if ! has_opt --trajectory; then
            printf "%-28s %s\n" "r${rooms}_s${storeys}_$mode" "n/a (pcd-to-map has no --trajectory)"
            continue
          fi
          args=(--trajectory "$sim/trajectory.txt") ;;
        mobile) input="$sim/cloud.pcd" ;;
      esac
      # shellcheck disable=SC2086
      if ! "$bin/pcd-to-map" "$input" "${args[@]}" ${PCD_ARGS:-} -q -o "$res" >/dev/null 2>"$base/$mode.err"; then
        printf "%-28s %s\n" "r${rooms}_s${storeys}_$mode" "pcd-to-map failed: $(tail -1 "$base/$mode.err")"
        continue
      fi
      "$bin/map-eval" --truth "$sim/ground_truth.json" --result "$res" -o "$res/eval" 2>/dev/null || true
      rows "$res/eval/eval.json" "r${rooms}_s${storeys}_$mode (seed $seed)"
      room_rows "$res/eval/eval.json"
    done
  done
done
