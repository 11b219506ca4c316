#!/usr/bin/env bash
# plan-route on a 6000 x 6000 map with a far goal (docs/robustness.md, row R25): a synthetic
# 300 x 300 m building of 10 x 10 m rooms at 0.05 m, each wall with a 1.5 m door; start (5, 5),
# goal (295, 295). Prints the run's stderr, its exit code, wall time and peak memory.
# Usage: scripts/plan_route_big_map.sh [BUILD_DIR (default build)] [extra plan-route args...]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
shift || true
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
python3 - "$work" <<'PY'
import sys
n, d = 6000, sys.argv[1]
walls = set(range(3)) | set(range(n - 3, n))
for k in range(200, n, 200): walls |= {k, k + 1, k + 2}
def door(k, j): return (j * 7 + k * 3) % 150 + 20   # start of a 30-cell door in wall k, block j
open_rows = {}
for k in range(200, n, 200):
    for j in range(0, n, 200):
        for r in range(j + door(k, j), min(j + door(k, j) + 30, n)): open_rows.setdefault(r, []).append(k)
base = bytearray([254]) * n
for c in walls: base[c] = 0
img = bytearray()
for r in range(n):
    if r in walls:
        line = bytearray(n)
        if 3 <= r < n - 3:
            k = next(w for w in range(200, n, 200) if w <= r < w + 3)
            for j in range(0, n, 200):
                o = j + door(k, j)
                line[o:o + 30] = bytes([254]) * len(line[o:o + 30])
            line[0:3] = line[n - 3:n] = bytes(3)
    else:
        line = bytearray(base)
        for k in open_rows.get(r, []): line[k:k + 3] = b"\xfe\xfe\xfe"
    img += line
with open(d + "/big.pgm", "wb") as f: f.write(b"P5\n%d %d\n255\n" % (n, n) + img)
open(d + "/big.yaml", "w").write("image: big.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n")
PY
set +e
/usr/bin/time -v "$build/bin/plan-route" --map "$work/big.yaml" --start 5,5 --goal 295,295 \
  -o "$work/out" "$@" 2>"$work/err"
code=$?
set -e
grep -v '^\s' "$work/err" | grep -v 'Command exited' || true
echo "exit code: $code"
grep -E 'Elapsed \(wall clock\)|Maximum resident set size' "$work/err"
