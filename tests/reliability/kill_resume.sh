#!/usr/bin/env bash
# kill -9 of a single simulation, then a restart: it resumes from the last periodic checkpoint of
# sim:run and ends in the same state hash as an uninterrupted run (docs/reliability.md).
#   kill_resume.sh PADDY WORK TRIALS
# Trial k kills the run at a moment k·37 ms after its first checkpoint appeared.
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

resumed=0
for ((k = 0; k < trials; ++k)); do
  out="trial_$k"
  "$paddy" run "$script" --out "$out" "${args[@]}" >/dev/null 2>"$out.log" &
  pid=$!
  # Wait for the first checkpoint (k·37 ms later), then kill without warning.
  for ((i = 0; i < 6000; ++i)); do
    [ -f "$out/pile.h5" ] && break
    kill -0 $pid 2>/dev/null || break
    sleep 0.01
  done
  sleep "$(awk -v k=$k 'BEGIN{printf "%.3f", 0.037 * k}')"
  if kill -9 $pid 2>/dev/null; then
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
    wait $pid || true
    echo "trial $k: the run ended before the kill (not counted)"
  fi
done
echo "kill_resume: $resumed of $trials trials killed and resumed to the same state"
[ "$resumed" -ge 1 ] || { echo "no trial was killed mid-run: the run is too short for this machine" >&2; exit 1; }
