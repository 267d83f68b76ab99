#!/usr/bin/env bash
# kill -9 of a single simulation, then a restart: it resumes from the last periodic checkpoint of
# sim:run and ends in the same state hash as an uninterrupted run (docs/reliability.md).
#   kill_resume.sh PADDY WORK TRIALS
# A timing run measures D, the time from the first checkpoint's appearance to the run's end on
# this machine; trial k kills the run at a seeded random moment u_k · 0.9 D after its first
# checkpoint appeared (u_k uniform in [0, 1), awk's generator seeded with 1000 + k), so the kills
# spread over the whole run whatever the machine's speed. The timing run and the trials may see a
# different load (under ctest -j the timing run can be slowed by a neighbour and the trials not):
# a trial whose run ends before its kill is run again with the delay halved, up to 4 times. With
# 10 or more trials at least 90 % of them must be killed mid-run (a run that ends first every time
# is not counted).
set -euo pipefail
paddy="$1"; work="$2"; trials="${3:-2}"
here="$(cd "$(dirname "$0")" && pwd)"
script="$here/resume_pile.lua"
rm -rf "$work"; mkdir -p "$work"; cd "$work"
args=(--threads 2 --seed 11 --set run_steps=2000 --set checkpoint_steps=100)
# Fields of result.json: the script's "hash" (results) and the steps taken by this process (metadata).
field() { grep -o "\"$2\": *[\"0-9a-f]*" "$1" | head -1 | sed 's/.*: *//; s/"//g'; }

"$paddy" run "$script" --out whole "${args[@]}" --set checkpoint_steps=0 >/dev/null 2>&1
want="$(field whole/result.json hash)"
[ -n "$want" ] || { echo "the uninterrupted run gave no hash" >&2; exit 1; }
echo "uninterrupted: $want"
now() { date +%s.%N; }
wait_for_checkpoint() {  # $1 output directory, $2 pid
  for ((i = 0; i < 6000; ++i)); do
    [ -f "$1/pile.h5" ] && return 0
    kill -0 "$2" 2>/dev/null || return 1
    sleep 0.005
  done
  return 1
}
"$paddy" run "$script" --out timing "${args[@]}" >/dev/null 2>timing.log &
pid=$!
wait_for_checkpoint timing $pid || { echo "the timing run wrote no checkpoint" >&2; exit 1; }
t0="$(now)"
wait $pid || { cat timing.log >&2; echo "the timing run failed" >&2; exit 1; }
span="$(awk -v a="$t0" -v b="$(now)" 'BEGIN{printf "%.4f", b - a}')"
echo "from the first checkpoint to the end: $span s"

resumed=0
for ((k = 0; k < trials; ++k)); do
  out="trial_$k"
  killed=0
  for ((attempt = 0; attempt < 5; ++attempt)); do
    rm -rf "$out"
    "$paddy" run "$script" --out "$out" "${args[@]}" >/dev/null 2>"$out.log" &
    pid=$!
    # Wait for the first checkpoint, then kill without warning at the trial's moment.
    wait_for_checkpoint "$out" $pid || true
    sleep "$(awk -v k=$k -v d="$span" -v a=$attempt 'BEGIN{srand(1000 + k); printf "%.4f", rand() * 0.9 * d / 2 ^ a}')"
    if kill -9 $pid 2>/dev/null; then killed=1; break; fi
    wait $pid || true
    echo "trial $k: the run ended before the kill (attempt $((attempt + 1)); again with half the delay)"
  done
  if [ "$killed" = 1 ]; then
    wait $pid 2>/dev/null || true
    if [ -f "$out/result.json" ]; then echo "trial $k: a killed run left a result.json" >&2; exit 1; fi
    for f in "$out"/*.tmp; do [ -e "$f" ] && rm -f "$f"; done  # a checkpoint being written: never read
    "$paddy" run "$script" --out "$out" "${args[@]}" >/dev/null 2>>"$out.log" \
      || { cat "$out.log" >&2; echo "trial $k: the restarted run failed" >&2; exit 1; }
    taken="$(field "$out/result.json" steps)"
    got="$(field "$out/result.json" hash)"
    echo "trial $k: killed, resumed with $taken of 2000 steps left: $got"
    [ "$got" = "$want" ] || { echo "trial $k: resumed run ended in another state" >&2; exit 1; }
    [ "$taken" -lt 2000 ] || { echo "trial $k: the restart did not resume from the checkpoint" >&2; exit 1; }
    resumed=$((resumed + 1))
  else
    echo "trial $k: the run ended before the kill in every attempt (not counted)"
  fi
done
echo "kill_resume: $resumed of $trials trials killed and resumed to the same state"
[ "$resumed" -ge 1 ] || { echo "no trial was killed mid-run: the run is too short for this machine" >&2; exit 1; }
if [ "$trials" -ge 10 ] && [ $((10 * resumed)) -lt $((9 * trials)) ]; then
  echo "only $resumed of $trials trials were killed mid-run (at least 90 % must be)" >&2; exit 1
fi
