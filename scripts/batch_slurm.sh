#!/usr/bin/env bash
#SBATCH --job-name=indoormap
#SBATCH --cpus-per-task=1
#SBATCH --mem=8G
#SBATCH --time=01:00:00
#SBATCH --output=slurm-%A_%a.out
# Many scans at once on a Slurm cluster (docs/batch.md): the recipe of scripts/batch.sh as a job
# array, one task per input, and an index job that runs after every task, failed or not.
#
# Usage (on the login node, from the checkout, with pcd-to-map built):
#   scripts/batch_slurm.sh submit LIST OUTROOT [-- ARGS...]
#     submits an array of one task per input of LIST (the list format of scripts/batch.sh; at
#     most INDOORMAP_ARRAY_MAX, default 50, running at once) and the index job
#     (--dependency=afterany: it runs whatever the tasks' exit codes). Extra sbatch options:
#     SBATCH_* environment variables (e.g. SBATCH_PARTITION), or edit the #SBATCH lines above.
# Run by Slurm:
#   scripts/batch_slurm.sh task LIST OUTROOT [ARGS...]   one input: SLURM_ARRAY_TASK_ID
#   scripts/batch_slurm.sh index OUTROOT                 OUTROOT/index.csv + index.json
# Each task writes OUTROOT/<KKKK>_<name>/ (pcd-to-map's outputs), OUTROOT/logs/ and
# OUTROOT/status/ as batch.sh does; a failed task exits with pcd-to-map's exit code (Slurm shows
# it FAILED) and does not stop the others. The index job exits 1 when some input failed.
set -euo pipefail
# Slurm runs a copy of this file from its spool directory: the checkout is passed explicitly.
root="${INDOORMAP_ROOT:-$(cd "$(dirname "$0")/.." && pwd)}"
batch="$root/scripts/batch.sh"

die() { echo "batch_slurm.sh: $*" >&2; exit 2; }

mode="${1:-}"
[ $# -gt 0 ] && shift
case "$mode" in
  submit)
    [ $# -ge 2 ] || die "submit LIST OUTROOT [ARGS...]"
    list="$(realpath "$1")" outroot="$(realpath -m "$2")"
    shift 2
    [ "${1:-}" = "--" ] && shift
    [ -f "$list" ] || die "'$list': no such list file"
    n=$("$batch" --prepare "$outroot" "$list") || exit 2  # the index is of this submission only
    mkdir -p "$outroot/slurm"
    self="$root/scripts/batch_slurm.sh"
    array_job=$(sbatch --parsable --array="1-$n%${INDOORMAP_ARRAY_MAX:-50}" \
      --export="ALL,INDOORMAP_ROOT=$root" --output="$outroot/slurm/task-%A_%a.out" \
      "$self" task "$list" "$outroot" "$@")
    array_job="${array_job%%;*}"  # --parsable: "jobid[;cluster]"
    index_job=$(sbatch --parsable --dependency="afterany:$array_job" --ntasks=1 --time=00:10:00 \
      --export="ALL,INDOORMAP_ROOT=$root" --output="$outroot/slurm/index-%j.out" \
      "$self" index "$outroot")
    echo "batch_slurm.sh: $n inputs: array job $array_job, index job ${index_job%%;*};" \
      "results in $outroot/index.csv" >&2
    ;;
  task)
    [ $# -ge 2 ] || die "task LIST OUTROOT [ARGS...]"
    [ -n "${SLURM_ARRAY_TASK_ID:-}" ] || die "task: not in a Slurm array job (no SLURM_ARRAY_TASK_ID)"
    list=$1 outroot=$2
    shift 2
    [ "${1:-}" = "--" ] && shift
    exec "$batch" --run-one "$SLURM_ARRAY_TASK_ID" "$outroot" "$list" -- "$@"
    ;;
  index)
    [ $# -eq 1 ] || die "index OUTROOT"
    exec "$batch" --index "$1"
    ;;
  *)
    awk 'NR >= 7 && !/^#/ { exit } NR >= 7 { print }' "$0"
    [ "$mode" = "-h" ] || [ "$mode" = "--help" ] || exit 2
    ;;
esac
