#!/usr/bin/env bash
# Object accuracy as a user gets it (issue 17): default random scenes (`scene-sim --random --seed
# N`, default scanner, tilt and corridor), `furniture-extract` with its defaults, `map-eval` with
# its defaults (recall: truth items of at least 0.1 m2; precision: every object written, floor
# items only). Prints one row per seed and the totals: recall, precision, median |z_max error|,
# objects below objects.min_area_m2 written (must be 0), furniture cells left over.
# docs/evaluation.md (scripts/eval_report.sh) holds the figures. Seeds 1-20 tune, 21-40 are
# reported once and never tuned on. Simulations are kept in OUT/sim_N and reused.
#
# Usage: scripts/objects_eval.sh [BUILD_DIR] [FIRST_SEED] [LAST_SEED]   (default build 1 20)
# Environment: OUT (/tmp/objects_eval), FE_ARGS (extra furniture-extract options).
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in -h | --help) sed -n '2,11p' "$0"; exit 0 ;; esac
build="${1:-build}"
first="${2:-1}"
last="${3:-20}"
bin="$build/bin"
out="${OUT:-/tmp/objects_eval}"
mkdir -p "$out"
for s in $(seq "$first" "$last"); do
  [ -f "$out/sim_$s/ground_truth.json" ] || "$bin/scene-sim" --random --seed "$s" -q -o "$out/sim_$s" >/dev/null
  # shellcheck disable=SC2086  # FE_ARGS is a list
  "$bin/furniture-extract" "$out/sim_$s/cloud.pcd" -q -o "$out/res_$s" ${FE_ARGS:-} >/dev/null
  "$bin/map-eval" --truth "$out/sim_$s/ground_truth.json" --result "$out/res_$s" \
    -o "$out/eval_$s" >/dev/null
done
python3 - "$out" "$first" "$last" <<'PY'
import json, sys, statistics
out, first, last = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
T = R = M = MA = small = 0
errs = []
left = 0
for s in range(first, last + 1):
    e = json.load(open("%s/eval_%d/eval.json" % (out, s)))["objects"]
    summ = json.load(open("%s/res_%d/summary.json" % (out, s)))
    objs = json.load(open("%s/res_%d/objects.json" % (out, s)))["objects"]
    min_area = summ["parameters"]["objects"]["min_area_m2"] if "parameters" in summ and "objects" in summ["parameters"] else 0
    n_small = sum(1 for o in objs if o["kind"] not in ("column", "installation") and o["area_m2"] < min_area - 1e-9)
    lo = summ["objects"].get("left_over_cells", 0)
    T += e["truth_count"]; R += e["result_count"]; M += e["matched"]
    MA += e["matched_all"]  # every match (precision); "matched": truth items >= min area (recall)
    small += n_small; left += lo
    se = [abs(m["z_max_error_m"]) for m in e["matches"] if m.get("z_max_error_m") is not None]
    errs += se
    print("seed %2d: truth %2d result %2d matched %2d recall %.2f precision %.2f small %d left_over %d"
          % (s, e["truth_count"], e["result_count"], e["matched"], e["recall"], e["precision"], n_small, lo))
print("seeds %d-%d: truth %d result %d matched %d recall %.3f precision %.3f median |dz| %.3f m, "
      "objects below min area %d, left-over cells %d"
      % (first, last, T, R, M, M / max(T, 1), MA / max(R, 1), statistics.median(errs) if errs else -1, small, left))
PY
