#!/usr/bin/env bash
# kill -9 of a running campaign at random moments, then a restart with the same output directory
# (docs/reliability.md, section 3). Two campaigns (MODE):
#   stages       (default) campaign_stages.lua, shaped like a calibration: four jobs, an analysis
#                between the stages that saves its choice, two more jobs, a summary;
#   calibration  the real experiments/calibrate_paddy_mud.lua in the miniature configuration of
#                tests/calibration (mini_mud.json: 40 mm spheres, small designs, both strategies,
#                the rheometer), about a minute uninterrupted on 2 cores.
# Each trial starts it, kills the runner and every job it runs with SIGKILL at a seeded random
# moment in [0, 1.05 T] (T: the uninterrupted run's time), starts it again until it completes,
# and requires:
#   (WHEN = write: not at that moment but in the first file write that any of its processes begins
#   after it. The run is started with PADDY_STOP_WRITING_AT = that moment, so the process stops
#   itself (SIGSTOP) half way through the write, its temporary half written or not yet renamed
#   (paddy/io/atomic_file.hpp); the trial kills it there, and requires the temporary to exist at
#   the kill. A run that ends before it writes again is not counted.)
#   * it completes, and its results equal the uninterrupted run's (stages: result.json,
#     stage1.json, summary.json and every job's results, compare_runs.lua; calibration: every
#     check of tests/calibration/check_calibration.lua and result.json identical); every JSON
#     file under the directory parses;
#   * every job that had finished before the kill is byte-identical afterwards (result.json,
#     pile.json, snapshots: MD5 taken at the kill);
#   * every HDF5 file opens (h5ls) and every job's snapshots hold the same data as the
#     uninterrupted run's (h5diff).
#   campaign_kill.sh PADDY SOURCE_DIR WORK_DIR TRIALS [SEED] [MODE] [WHEN]   (WHEN: random, default, or write)
set -euo pipefail
paddy=${1:?usage: campaign_kill.sh PADDY SOURCE_DIR WORK_DIR TRIALS [SEED]}
src=${2:?}
work=${3:?}
trials=${4:-3}
seed=${5:-17}
mode=${6:-stages}
when=${7:-random}
case "$when" in random | write) ;; *) echo "campaign_kill: unknown kill moment '$when' (random, write)" >&2; exit 2 ;; esac
here="$src/tests/reliability"
case "$mode" in
  stages)
    driver="$here/campaign_stages.lua"
    args=(--threads 2) ;;
  calibration)
    driver="$src/experiments/calibrate_paddy_mud.lua"
    # The miniature configuration of tests/calibration/calibration_e2e.sh.
    args=(--threads 2 --seed 3 --set "input=$src/tests/calibration/mini_mud.json" --set particle_diameter=0.04
          --set rheometer_particle_diameter=0.02 --set threads_per_job=1
          --set "experiment_params=max_time=1.5,settle_max_time=1.5"
          --set "rheometer_params=speeds_rpm=10;20;40,step_time=0.1,settle_max_time=0.6,insert_time=0.02") ;;
  *) echo "campaign_kill: unknown mode '$mode' (stages, calibration)" >&2; exit 2 ;;
esac
fail() { echo "campaign_kill: FAIL: $*" >&2; exit 1; }
rm -rf "$work"
mkdir -p "$work"
cd "$work"
now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.2f", b - a }'; }

start=$(now)
"$paddy" run "$driver" --out whole "${args[@]}" > whole.log 2>&1 || { cat whole.log >&2; fail "the uninterrupted campaign failed"; }
T=$(elapsed "$start")
n_jobs=$(find whole/campaign/jobs -name result.json | wc -l)
echo "uninterrupted: $T s, $n_jobs jobs"

# Files of the finished jobs (result.json complete) and of the run itself, with their MD5.
finished_sums() {
  local dir=$1 j
  for j in "$dir"/campaign/jobs/*/; do
    grep -qs '"status": "complete"' "$j/result.json" || continue
    find "$j" -type f \( -name result.json -o -name pile.json -o -name '*.h5' -o -name particles.xmf \) -print0 \
      | xargs -0 -r md5sum
  done
  for j in stage1.json summary.json result.json; do [ -f "$dir/$j" ] && md5sum "$dir/$j"; done
  true
}
# The phase the runner was in, from its last progress marker (calibration: its last numbered
# step, "1. Plackett-Burman screening ...", or the surrogate strategy).
phase_of() {
  if [ "$mode" = calibration ]; then
    local line
    line=$(grep -E '^calibration: ([0-9]\. |Surrogate|report)' "$1" 2> /dev/null | tail -n 1 | cut -c14-40)
    echo "${line:-start-up}"
    return
  fi
  case "$(tail -n 1 "$1" 2> /dev/null)" in
    "") echo "start-up" ;;
    "stage 1 submitted") echo "stage 1 jobs" ;;
    "stage 1 done" | "analysis") echo "analysis between stages" ;;
    "stage 2 submitted") echo "stage 2 jobs" ;;
    "stage 2 done" | "summary") echo "summary" ;;
    "end") echo "final result.json" ;;
    *) echo "other" ;;
  esac
}
gone() {  # the process has ended (a zombie counts as ended: its parent may be gone)
  [ ! -e "/proc/$1" ] || [ "$(awk '{print $3}' "/proc/$1/stat" 2> /dev/null)" = Z ]
}

declare -A phases=()
killed=0 with_tmp=0 jobs_killed=0 restarts=0 stale_tmp=0 in_runner=0
for ((k = 0; k < trials; ++k)); do
  out="trial_$k"
  delay=$(awk -v s="$seed" -v k="$k" -v T="$T" 'BEGIN { srand(s * 1000 + k); printf "%.3f", rand() * 1.05 * T }')
  writer=""
  if [ "$when" = write ]; then
    at=$(awk -v t="$(now)" -v d="$delay" 'BEGIN { printf "%.3f", t + d }')
    PADDY_STOP_WRITING_AT=$at setsid "$paddy" run "$driver" --out "$out" "${args[@]}" > "$out.first.log" 2>&1 &
    pid=$!
    # Until one of its processes has stopped itself in a write, or the run has ended.
    until gone "$pid"; do
      for q in "$pid" $(pgrep -P "$pid" || true); do
        [ "$(awk '{print $3}' "/proc/$q/stat" 2> /dev/null)" = T ] && { writer=$q; break; }
      done
      [ -n "$writer" ] && break
      sleep 0.01
    done
    if [ -z "$writer" ]; then
      wait "$pid" || true
      echo "trial $k: the campaign wrote nothing after $delay s (not counted)"
      continue
    fi
    kill -STOP -- "-$pid" 2> /dev/null || true
    [ "$writer" = "$pid" ] && writer="the runner" || writer="a job"
  else
    setsid "$paddy" run "$driver" --out "$out" "${args[@]}" > "$out.first.log" 2>&1 &
    pid=$!
    sleep "$delay"
    if ! kill -STOP -- "-$pid" 2> /dev/null; then
      wait "$pid" || true
      echo "trial $k: the campaign ended before the kill at $delay s (not counted)"
      continue
    fi
  fi
  # Frozen: the runner cannot start another job. Record, then SIGKILL the runner's process group
  # and the group of every job it runs.
  kids=$(pgrep -P "$pid" || true)
  phase=$(phase_of "$out.first.log")
  tmp_now=$(find "$out" -name '*.tmp*' 2> /dev/null | wc -l)
  finished_sums "$out" > "$out.before.md5"
  groups=("-$pid")
  for c in $kids; do groups+=("-$c"); done
  kill -KILL -- "${groups[@]}" 2> /dev/null || true
  wait "$pid" 2> /dev/null || true
  for c in $kids; do
    for ((i = 0; i < 500; ++i)); do gone "$c" && break; sleep 0.01; done
    gone "$c" || fail "trial $k: job process $c survived SIGKILL"
  done
  n_kids=$(echo $kids | wc -w)
  killed=$((killed + 1))
  jobs_killed=$((jobs_killed + n_kids))
  label="$phase"
  if [ "$tmp_now" -gt 0 ]; then
    being=$(find "$out" -name '*.tmp*' -printf '%f\n' 2> /dev/null | sed 's/\.tmp\.[0-9]*$//' | sort -u | paste -sd, -)
    label="$phase, a file being written: $being"
    with_tmp=$((with_tmp + 1))
  fi
  if [ -n "$writer" ]; then
    [ "$tmp_now" -gt 0 ] || fail "trial $k: $writer stopped in a write, but no temporary file exists"
    label="$label by $writer"
    [ "$writer" = "the runner" ] && in_runner=$((in_runner + 1))
  fi
  phases[$phase]=$(( ${phases[$phase]:-0} + 1 ))
  # Start it again until it completes (a restart that fails by itself is an error).
  runs=0
  until grep -qs '"status": "complete"' "$out/result.json"; do
    runs=$((runs + 1))
    [ "$runs" -le 3 ] || fail "trial $k: not complete after 3 restarts"
    "$paddy" run "$driver" --out "$out" "${args[@]}" > "$out.restart$runs.log" 2>&1 \
      || { cat "$out.restart$runs.log" >&2; fail "trial $k: the restarted campaign failed"; }
  done
  restarts=$((restarts + runs))
  # Finished before the kill: byte-identical now.
  if [ -s "$out.before.md5" ]; then
    md5sum --quiet -c "$out.before.md5" > "$out.md5check" 2>&1 \
      || { cat "$out.md5check" >&2; fail "trial $k: a file finished before the kill changed"; }
  fi
  n_before=$(grep -c '/result.json$' "$out.before.md5" || true)
  # Same results as the uninterrupted run; every JSON parses.
  if [ "$mode" = calibration ]; then
    "$paddy" run "$src/tests/calibration/check_calibration.lua" --out "$out.check" --set "dir=$out" \
      --set "same_as=whole/result.json" > "$out.compare" 2>&1 \
      || { cat "$out.compare" >&2; fail "trial $k: the calibration's checks fail or its result differs from the uninterrupted run"; }
    list=""
    while IFS= read -r f; do list+="$f;"; done < <(find "$out" -name '*.json' -type f)
    "$paddy" run "$here/check_json.lua" --out "$out.check_json" --set "files=$list" >> "$out.compare" 2>&1 \
      || { cat "$out.compare" >&2; fail "trial $k: a JSON file does not parse"; }
    echo "same result, $(find "$out/campaign/jobs" -name result.json | wc -l) jobs, every JSON parsed" >> "$out.compare"
  else
    "$paddy" run "$here/compare_runs.lua" --out "$out.check" --set "dir=$out" --set reference=whole > "$out.compare" 2>&1 \
      || { cat "$out.compare" >&2; fail "trial $k: the result differs from the uninterrupted run"; }
  fi
  # Every HDF5 file opens; the snapshots hold the uninterrupted run's data.
  while IFS= read -r f; do
    h5ls -r "$f" > /dev/null 2>&1 || fail "trial $k: $f does not open as HDF5"
    ref="whole/${f#"$out"/}"
    [ -f "$ref" ] || fail "trial $k: $f has no counterpart in the uninterrupted run"
    h5diff -q "$f" "$ref" > /dev/null 2>&1 || fail "trial $k: $f differs from $ref"
  done < <(find "$out" -name '*.h5' -type f)
  tmps=$(find "$out" -name '*.tmp*' | wc -l)
  stale_tmp=$((stale_tmp + tmps))
  echo "trial $k: killed at $delay s ($label; $n_kids job(s) running, $n_before result files finished before the kill)," \
       "completed after $runs restart(s): $(tail -n 1 "$out.compare")${tmps:+, $tmps stale temporaries}"
done
echo "campaign_kill: $killed of $trials trials killed with SIGKILL and completed with the uninterrupted result" \
     "($jobs_killed running jobs killed, $restarts restarts, $with_tmp kills while a temporary file existed," \
     "$stale_tmp stale temporaries left); $(elapsed "$start") s in all"
[ "$when" = write ] && echo "  killed in a write: $killed ($in_runner by the runner, $((killed - in_runner)) by a job)"
for p in "${!phases[@]}"; do
  echo "  killed during $p: ${phases[$p]}"
done
[ "$killed" -ge 1 ] || fail "no trial was killed: the campaign is too short for this machine"
