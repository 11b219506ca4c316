#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz in build-san/ (clang-14, ASan + UBSan, the same
# tree and configure as ./test.sh --sanitize) and runs them, with -seed=1 -rss_limit_mb=2048
# -timeout=2 per input. Seeds: tests/fuzz/corpus/<t>/ and tests/fuzz/regressions/<t>/ (read
# only); inputs found while fuzzing go to build-san/fuzz-corpus/<t>/, crashes to
# build-san/fuzz-artifacts/<t>/. Prints one summary line per target (also in
# build-san/fuzz-summary.txt); exits 1 if any target found something or stayed below the floor.
#
# Usage: scripts/fuzz.sh [--nightly] [TARGET...]          (default: every target)
# Budget mode (default, CI): ONE wall-clock budget for all targets together, PARALLEL targets at
#   a time. Each target, when it starts, gets an even share of what is left (PARALLEL x the
#   remaining seconds, minus what the running targets still hold, over the targets not yet
#   run), and stops at its share or at RUNS executions; a target that stops early leaves its
#   time to the rest. A target that cannot make MIN_RUNS executions in FLOOR_MAX s fails.
#   INDOORMAP_FUZZ_BUDGET    (default 900)     seconds for all targets together
#   INDOORMAP_FUZZ_PARALLEL  (default 2)       targets run at a time (one per core)
#   INDOORMAP_FUZZ_RUNS      (default 200000)  executions per target at most
#   INDOORMAP_FUZZ_MIN_RUNS  (default 50000)   executions every target makes first, even beyond
#                                              its share (the stage then overruns and says so)
#   INDOORMAP_FUZZ_FLOOR_MAX (default 900)     seconds a target may take for those at most
# Per-target mode: INDOORMAP_FUZZ_SECONDS=S gives every target S seconds instead of a share.
# Nightly (long mode): --nightly = INDOORMAP_FUZZ_RUNS=10000000 INDOORMAP_FUZZ_SECONDS=600
#   INDOORMAP_FUZZ_PARALLEL=$(nproc), continuing from build-san/fuzz-corpus/ (see
#   docs/robustness.md, "Nightly-length run").
# INDOORMAP_JOBS (default 2): build parallelism.
# A finding: reproduce with build-san/bin/fuzz_<t> <crash file>, minimise with
# -minimize_crash=1 -runs=10000, fix, and add the file to tests/fuzz/regressions/<t>/ (ctest
# replays it through test_fuzz_replay in every build).
set -euo pipefail
cd "$(dirname "$0")/.."
targets=()
nightly=0
for a in "$@"; do
  case "$a" in
    --nightly) nightly=1 ;;
    -h | --help) sed -n '2,28p' "$0"; exit 0 ;;
    -*) echo "fuzz.sh: unknown option '$a' (see --help)" >&2; exit 2 ;;
    *) targets+=("$a") ;;
  esac
done
if [ $nightly = 1 ]; then
  : "${INDOORMAP_FUZZ_RUNS:=10000000}" "${INDOORMAP_FUZZ_SECONDS:=600}"
  : "${INDOORMAP_FUZZ_PARALLEL:=$(nproc)}"
fi
runs="${INDOORMAP_FUZZ_RUNS:-200000}"
min_runs="${INDOORMAP_FUZZ_MIN_RUNS:-50000}"
budget="${INDOORMAP_FUZZ_BUDGET:-900}"
floor_max="${INDOORMAP_FUZZ_FLOOR_MAX:-900}"
fixed="${INDOORMAP_FUZZ_SECONDS:-}"
parallel="${INDOORMAP_FUZZ_PARALLEL:-2}"
tree=build-san

if [ ${#targets[@]} -eq 0 ]; then
  for d in tests/fuzz/corpus/*/; do targets+=("$(basename "$d")"); done
fi
# Only the fuzz binaries (a no-op after ./test.sh --sanitize, which built the whole tree).
INDOORMAP_TARGETS="$(printf 'fuzz_%s ' "${targets[@]}")" scripts/setup.sh "$tree" \
  -DINDOORMAP_FUZZ=ON -DINDOORMAP_BUILD_BENCH=OFF
for t in "${targets[@]}"; do
  [ -x "$tree/bin/fuzz_$t" ] || {
    echo "fuzz: no binary $tree/bin/fuzz_$t (is '$t' in tests/fuzz/CMakeLists.txt?)" >&2
    exit 1
  }
done
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# The targets write every input to a file (the readers take paths): in memory (/dev/shm) that is
# 2.5-7 times faster than /tmp on disk (ros_map: 450 against 3,400 executions per second).
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi

# One target, in the background: its log, then one summary line in $tree/fuzz-result-<t>.txt.
run_target() {
  local t=$1 cap=$2
  local work=$tree/fuzz-corpus/$t art=$tree/fuzz-artifacts/$t log=$tree/fuzz-$t.log
  mkdir -p "$work" "$art"
  local start rc=0
  # The seeds; a target without regressions yet has no regressions/ folder (libFuzzer stops at
  # a missing folder).
  local dirs=("$work" tests/fuzz/corpus/"$t")
  [ -d tests/fuzz/regressions/"$t" ] && dirs+=(tests/fuzz/regressions/"$t")
  start=$(date +%s)
  # A fixed seed: the same inputs in the same order from the committed seeds, so a clean run
  # here predicts a clean run in CI (a slower machine only stops earlier in the same sequence).
  local fuzz=("$tree/bin/fuzz_$t" -seed=1 -rss_limit_mb=2048 -timeout=2 -print_final_stats=1
    -artifact_prefix="$art/")
  # Part 1, the floor: MIN_RUNS executions even beyond the share (on a busy machine a slow target
  # takes longer than its share instead of failing short; the stage then overruns its budget and
  # says so), at most FLOOR_MAX seconds. Part 2: the rest of the share, from the corpus part 1
  # grew, up to RUNS executions in all.
  "${fuzz[@]}" -runs="$min_runs" -max_total_time="$floor_max" "${dirs[@]}" >"$log" 2>&1 || rc=$?
  # (|| true: a run that stopped at once has no stats, and pipefail would end this runner)
  local execs1 more=0
  execs1=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1 || true)
  local left=$((cap - ($(date +%s) - start)))
  if [ $rc -eq 0 ] && [ $left -ge 5 ] && [ "${execs1:-0}" -lt "$runs" ]; then
    "${fuzz[@]}" -runs=$((runs - ${execs1:-0})) -max_total_time=$left "${dirs[@]}" \
      >"$log.2" 2>&1 || rc=$?
    more=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log.2" | tail -1 || true)
    cat "$log.2" >>"$log"
    rm -f "$log.2"
  fi
  local secs execs rss cov result=clean
  secs=$(($(date +%s) - start))
  execs=$((${execs1:-0} + ${more:-0}))
  rss=$(sed -n 's/^stat::peak_rss_mb: *//p' "$log" | sort -n | tail -1 || true)
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | cut -d' ' -f2 || true)
  if [ $rc -ne 0 ]; then
    result="FAILED (exit $rc): $(ls "$art" | tr '\n' ' ')"
    grep -E "ERROR|SUMMARY|indoormap fuzz target|runtime error" "$log" | head -5 >&2 || true
  elif [ "${execs:-0}" -lt "$min_runs" ]; then
    result="SHORT: fewer than $min_runs executions in $floor_max s (INDOORMAP_FUZZ_FLOOR_MAX)"
  fi
  printf '%-11s %10s execs %5ss of %5ss %6s exec/s  cov %-6s corpus %-5s peak %4s MB  %s\n' \
    "$t" "${execs:-?}" "$secs" "$cap" "$((${execs:-0} / (secs > 0 ? secs : 1)))" "${cov:-?}" \
    "$(ls "$work" | wc -l)" "${rss:-?}" "$result" >"$tree/fuzz-result-$t.txt"
}

stage_start=$(date +%s)
deadline=$((stage_start + budget))
declare -A pid_end=()  # running pid -> the second its share ends
queue=("${targets[@]}")
while [ ${#queue[@]} -gt 0 ] || [ ${#pid_end[@]} -gt 0 ]; do
  while [ ${#queue[@]} -gt 0 ] && [ ${#pid_end[@]} -lt "$parallel" ]; do
    now=$(date +%s)
    if [ -n "$fixed" ]; then
      cap=$fixed
    else
      held=0
      for p in "${!pid_end[@]}"; do
        left=$((pid_end[$p] - now))
        [ $left -gt 0 ] && held=$((held + left))
      done
      cap=$(((parallel * (deadline - now) - held) / ${#queue[@]}))
      [ $cap -gt $((deadline - now)) ] && cap=$((deadline - now))
      [ $cap -lt 10 ] && cap=10  # over budget already: the run is short, and says so
    fi
    t=${queue[0]}
    queue=("${queue[@]:1}")
    rm -f "$tree/fuzz-result-$t.txt"
    run_target "$t" "$cap" &
    pid_end[$!]=$((now + cap))
    echo "fuzz: [$(date +%T)] $t started, $cap s at most" >&2
  done
  # wait -n can return for a target that ended earlier (bash keeps its status): a slot is free
  # only when its process is really gone, so at most PARALLEL targets ever run at once.
  wait -n "${!pid_end[@]}" 2>/dev/null || true
  freed=0
  for p in "${!pid_end[@]}"; do
    if ! kill -0 "$p" 2>/dev/null; then
      unset "pid_end[$p]"
      freed=1
    fi
  done
  [ $freed = 1 ] || sleep 0.5
done
wait  # every runner has written its result line

summary=$tree/fuzz-summary.txt
: >"$summary"
failed=0
for t in "${targets[@]}"; do
  line=$(cat "$tree/fuzz-result-$t.txt" 2>/dev/null || echo "$t  no result (the runner died)")
  echo "fuzz: $line" >&2
  echo "$line" >>"$summary"
  [[ "$line" == *" clean" ]] || failed=1
done
limit="budget $budget s"
[ -n "$fixed" ] && limit="$fixed s per target"
echo "fuzz: ${#targets[@]} targets in $(($(date +%s) - stage_start)) s of wall time ($limit," \
  "$parallel at a time)" | tee -a "$summary" >&2
exit $failed
