#!/usr/bin/env bash
# End-to-end miniature calibration (CTest calibration.e2e): 40 mm spheres and small designs
# (mini_mud.json), both strategies, the rheometer against a measured torque file.
#   1. start the calibration and kill it (SIGTERM) once a few simulations have finished;
#   2. run it again: it completes, and no finished simulation was run again (their result.json
#      files are untouched);
#   3. run it a third time: nothing runs, and the result is identical;
#   4. the report is well-formed XHTML whose every image exists and is a PNG; the numbers agree
#      (check_calibration.lua).
#   calibration_e2e.sh PADDY SOURCE_DIR WORK_DIR [executor]
set -euo pipefail
paddy=${1:?usage: calibration_e2e.sh PADDY SOURCE_DIR WORK_DIR [local|slurm]}
src=${2:?}
work=${3:?}
executor=${4:-local}
rm -rf "$work"
mkdir -p "$work"
out="$work/out"
args=(run "$src/experiments/calibrate_paddy_mud.lua" --threads 2 --seed 3
      --set "input=$src/tests/calibration/mini_mud.json" --set particle_diameter=0.04
      --set rheometer_particle_diameter=0.02 --set executor="$executor" --set threads_per_job=1
      --set "experiment_params=max_time=1.5,settle_max_time=1.5"
      --set "rheometer_params=speeds_rpm=10;20;40,step_time=0.1,settle_max_time=0.6,insert_time=0.02")
[ "$executor" = slurm ] && args+=(--set strategy=reference --set slurm_poll_interval=1 --set max_parallel=2)
fail() { echo "calibration_e2e: FAIL: $*" >&2; exit 1; }
finished() { find "$out/campaign/jobs" -name result.json -printf '%P %T@\n' 2>/dev/null | sort; }

if [ "$executor" = local ]; then
  # 1. Interrupted part-way.
  "$paddy" "${args[@]}" --out "$out" > "$work/first.log" 2>&1 &
  pid=$!
  for _ in $(seq 1 1200); do
    [ "$(finished | wc -l)" -ge 6 ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  kill -TERM "$pid" 2>/dev/null || fail "the calibration ended before it could be interrupted"
  wait "$pid" && fail "the interrupted calibration exited 0"
  [ -f "$out/result.json" ] && fail "an interrupted calibration left a result.json"
  finished > "$work/before.txt"
  n_before=$(wc -l < "$work/before.txt")
  [ "$n_before" -ge 6 ] || fail "only $n_before simulations had finished before the interruption"
  echo "interrupted after $n_before finished simulations"
fi

# 2. Resume to the end.
"$paddy" "${args[@]}" --out "$out" > "$work/second.log" 2>&1 || { tail -n 40 "$work/second.log"; fail "the calibration failed"; }
finished > "$work/after.txt"
if [ -f "$work/before.txt" ]; then
  missing=$(comm -23 "$work/before.txt" "$work/after.txt")
  [ -z "$missing" ] || fail "finished simulations were run again on resume: $missing"
fi
echo "completed with $(wc -l < "$work/after.txt") simulations"
cp "$out/result.json" "$work/result_first.json"

# 3. Again: nothing runs, same result.
"$paddy" "${args[@]}" --out "$out" > "$work/third.log" 2>&1 || fail "the third run failed"
finished > "$work/again.txt"
cmp -s "$work/after.txt" "$work/again.txt" || fail "a complete calibration ran simulations again"

# 4. The report and the numbers.
xmllint --noout "$out/report.html" || fail "report.html is not well-formed"
n_img=0
for img in $(grep -o '<img src="[^"]*"' "$out/report.html" | sed 's/<img src="//; s/"$//'); do
  [ -s "$out/$img" ] || fail "report image $img is missing"
  [ "$(head -c 4 "$out/$img" | od -An -tx1 | tr -d ' \n')" = 89504e47 ] || fail "report image $img is not a PNG"
  n_img=$((n_img + 1))
done
echo "report: $n_img images"
[ "$n_img" -ge 10 ] || fail "the report has only $n_img images"
for f in calibration.json data/simulations.csv data/screening.csv data/box_behnken.csv; do
  [ -s "$out/$f" ] || fail "missing $f"
done
checks=(--set "dir=$out" --set "same_as=$work/result_first.json")
if [ "$executor" = slurm ]; then
  checks+=(--set strategy=reference)
  # Same seeds and thread count as the local case: the reference procedure must agree exactly.
  local_result="$(dirname "$work")/e2e/result_first.json"
  # (only when that result is newer than the code and scripts that made this one)
  if [ -f "$local_result" ] && [ -z "$(find "$paddy" "$src/experiments" "$src/tests/calibration" -newer "$local_result" -print -quit)" ]; then
    checks+=(--set "same_reference_as=$local_result")
    echo "comparing with $local_result"
  else
    echo "no up-to-date local result to compare with (run calibration.e2e first)"
  fi
fi
"$paddy" run "$src/tests/calibration/check_calibration.lua" "${checks[@]}" --out "$work/check" || fail "check_calibration.lua"
echo "calibration_e2e ($executor): ok"
