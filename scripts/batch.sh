#!/usr/bin/env bash
# Many scans at once (docs/batch.md): pcd-to-map on every input of a list, in parallel with GNU
# parallel; one output directory per input, a failure reported per input without stopping the
# others, and one index of all results (index.csv and index.json).
#
# Usage: scripts/batch.sh [-j JOBS] [-t SECONDS] [-b PCD_TO_MAP] -o OUTROOT LIST [-- ARGS...]
#   LIST        inputs, one a line: a cloud file or a 3DTK directory, then optionally pcd-to-map
#               options for that input alone (whitespace separated: no spaces in paths). Blank
#               lines and lines starting with '#' are skipped; input K is the K-th other line.
#   -o OUTROOT  OUTROOT/<KKKK>_<name>/ the outputs of input K (name: its file name without the
#               extension), OUTROOT/logs/<KKKK>_<name>.log its stdout + stderr,
#               OUTROOT/index.csv + index.json one row per input (scripts/batch_index.py).
#   -j JOBS     runs at once (default 2); each pcd-to-map is single-threaded.
#   -t SECONDS  time limit of one input (coreutils timeout: exit code 124 in the index).
#   -b BINARY   pcd-to-map to run (default: build/bin/pcd-to-map of this checkout, else PATH).
#   ARGS        pcd-to-map options for every input (e.g. -c site.yaml --cell-m 0.05).
# Exit code: 0 every input done, 1 some input failed (see the index), 2 bad usage.
# Internal modes (used by GNU parallel and scripts/batch_slurm.sh):
#   scripts/batch.sh --run-one K OUTROOT LIST [-- ARGS...]   input K only (status in OUTROOT/status/)
#   scripts/batch.sh --prepare OUTROOT LIST    a new run: clears OUTROOT/status, writes the
#                                              inputs to OUTROOT/inputs.txt, prints their number
#   scripts/batch.sh --index OUTROOT                         (re)writes the index
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
python="${BATCH_PYTHON:-/usr/bin/python3}"

usage() { sed -n '2,26p' "$0"; }
die() { echo "batch.sh: $*" >&2; exit 2; }

# inputs LIST: the input lines of LIST (no blank or comment lines), one a line.
inputs() { grep -v -E '^[[:space:]]*(#|$)' "$1"; }

# job_name K LINE: KKKK_<file name without extension>, safe as a directory name.
job_name() {
  local first="${2%%[[:space:]]*}" base
  base="$(basename "$first")"
  base="${base%.*}"
  printf '%04d_%s' "$1" "$(printf '%s' "$base" | tr -c 'A-Za-z0-9._-' '_')"
}

binary() {
  if [ -n "${PCD_TO_MAP:-}" ]; then echo "$PCD_TO_MAP"
  elif [ -x "$root/build/bin/pcd-to-map" ]; then echo "$root/build/bin/pcd-to-map"
  else command -v pcd-to-map || die "pcd-to-map not found: build it or give -b BINARY"
  fi
}

# run_one K OUTROOT LIST ARGS...: runs input K; writes OUTROOT/status/NAME.tsv (K, input line,
# outdir, exit code, seconds) whatever happens. Exits with pcd-to-map's exit code.
run_one() {
  local k=$1 outroot=$2 list=$3
  shift 3
  local line name dir log start rc=0 secs
  line="$(inputs "$list" | sed -n "${k}p")"
  [ -n "$line" ] || die "$list has no input $k"
  name="$(job_name "$k" "$line")"
  dir="$outroot/$name"
  log="$outroot/logs/$name.log"
  mkdir -p "$outroot/logs" "$outroot/status"
  rm -rf "$dir"  # a rerun replaces the input's outputs: a failure must not show older ones
  local -a own
  read -r -a own <<<"$line"
  local -a cmd=("$(binary)" "${own[0]}" -o "$dir" -q "${own[@]:1}" "$@")
  [ -n "${BATCH_TIMEOUT:-}" ] && cmd=(timeout "$BATCH_TIMEOUT" "${cmd[@]}")
  start=$(date +%s.%N)
  "${cmd[@]}" >"$log" 2>&1 || rc=$?
  secs=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$k" "$line" "$name" "$rc" "$secs" "logs/$name.log" \
    >"$outroot/status/$name.tsv.tmp" && mv "$outroot/status/$name.tsv.tmp" "$outroot/status/$name.tsv"
  if [ $rc -ne 0 ]; then
    rmdir "$dir" 2>/dev/null  # pcd-to-map made it before reading: a failure leaves it empty
    echo "batch.sh: input $k ($line) failed, exit $rc: $(tail -n 1 "$log")" >&2
  fi
  return $rc
}

# prepare OUTROOT LIST: a new run: no status of an earlier one, and OUTROOT/inputs.txt the
# inputs, so that the index has a row for an input whose run never finished. Prints N.
prepare() {
  mkdir -p "$1" || die "cannot create '$1'"
  rm -rf "$1/status"  # the index is of this run only
  inputs "$2" >"$1/inputs.txt" || die "'$2' lists no input"
  wc -l <"$1/inputs.txt"
}

case "${1:-}" in
  --prepare)
    [ $# -eq 3 ] || die "--prepare OUTROOT LIST"
    prepare "$2" "$3"
    exit $? ;;
  --run-one)
    [ $# -ge 4 ] || die "--run-one K OUTROOT LIST [-- ARGS...]"
    k=$2 outroot=$3 list=$4
    shift 4
    [ "${1:-}" = "--" ] && shift
    run_one "$k" "$outroot" "$list" "$@"
    exit $? ;;
  --index)
    [ $# -eq 2 ] || die "--index OUTROOT"
    exec "$python" "$here/batch_index.py" "$2" ;;
  -h | --help) usage; exit 0 ;;
esac

jobs=2 outroot=""
while getopts "j:t:b:o:h" opt; do
  case $opt in
    j) jobs=$OPTARG ;;
    t) export BATCH_TIMEOUT=$OPTARG ;;
    b) export PCD_TO_MAP=$OPTARG ;;
    o) outroot=$OPTARG ;;
    h) usage; exit 0 ;;
    *) die "see --help" ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 1 ] || die "no LIST given (see --help)"
list=$1
shift
[ "${1:-}" = "--" ] && shift
[ -n "$outroot" ] || die "no output root given: use -o OUTROOT"
[ -f "$list" ] || die "'$list': no such list file"
command -v parallel >/dev/null || die "GNU parallel not found (Debian: apt-get install parallel)"
binary >/dev/null || exit 2
n=$(prepare "$outroot" "$list") || exit 2

echo "batch.sh: $n inputs, $jobs at a time, into $outroot" >&2
# --halt never: a failed input does not stop the others. -q: the arguments reach run-one as
# they are (no shell in between).
seq 1 "$n" | parallel --will-cite --halt never -j "$jobs" -q \
  "$0" --run-one {} "$outroot" "$list" -- "$@"
"$python" "$here/batch_index.py" "$outroot"
