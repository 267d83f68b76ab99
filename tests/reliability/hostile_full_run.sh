#!/usr/bin/env bash
# Hostile text through a full calibration and a full discovery run (docs/reliability.md,
# section 4), not only their report layers (hostile_reports.sh): the inputs of
# hostile_full_inputs.lua (descriptions and factor units holding quotes, $(...), backticks, ;,
# a line break and a command, ../, markup, non-ASCII), kept in a directory with a hostile name,
# run by experiments/calibrate_paddy_mud.lua and experiments/discover.lua in their smallest
# configurations into output directories with hostile names. Checked:
#   * an input with a hostile name (a response, an experiment) is refused before any simulation,
#     the error naming the file;
#   * both runs complete; no command ran (no file named CANARY anywhere: the strings would make
#     the absolute canary path, the directory names a CANARY in the working directory); nothing
#     was written outside the output directories;
#   * each report.html is well-formed (xmllint), every image it shows exists, the hostile markup
#     appears escaped and never as a tag or an attribute, and the rest of the description
#     (quotes, $(...), backticks, non-ASCII) appears as given.
#   hostile_full_run.sh PADDY SOURCE_DIR WORK_DIR
set -euo pipefail
source "$(dirname "$0")/hostile_setup.sh"  # paddy, src, work (entered), fail, canary
name="'\$(touch CANARY)' \`touch CANARY\` \"q\"; é <b>&amp;"
inputs="$work/inputs $name"
cal_out="$work/calibration $name"
disc_out="$work/discovery $name"
"$paddy" run "$src/tests/reliability/hostile_full_inputs.lua" --out "$inputs" --set "canary=$canary" > inputs.log 2>&1 \
  || { cat inputs.log >&2; fail "hostile_full_inputs.lua failed"; }
outside() {
  find "$work" \( -path "$cal_out" -o -path "$disc_out" -o -path "$inputs" -o -name '*.log' -o -path "$work/before.txt" \
    -o -path "$work/after.txt" \) -prune -o -print | sort
}
outside > before.txt
no_canary() {
  local found
  found=$( { find / -xdev -maxdepth 1 -name CANARY; find "$work" -name CANARY; } 2> /dev/null || true)
  [ -z "$found" ] || fail "$1: a command ran: $found"
}
small=(--threads 2 --seed 3 --set particle_diameter=0.04 --set "experiment_params=max_time=1.5,settle_max_time=1.5")

# 1. Hostile names are refused before anything runs.
# expect_refused SCRIPT INPUT OUT WHAT: exit 2 naming INPUT, and no campaign started.
expect_refused() {
  local rc=0
  "$paddy" run "$src/experiments/$1" "${small[@]}" --set "input=$inputs/$2" --out "$work/$3" > "$3.log" 2>&1 || rc=$?
  [ "$rc" -eq 2 ] || { cat "$3.log" >&2; fail "$4: exit $rc, not 2"; }
  grep -qF "$inputs/$2" "$3.log" || { cat "$3.log" >&2; fail "the refusal does not name the file"; }
  [ ! -d "$work/$3/campaign" ] || fail "a simulation was started for a refused input ($4)"
}
expect_refused calibrate_paddy_mud.lua calibration_bad_name.json refused_cal "a calibration input with a hostile response name"
expect_refused discover.lua discovery_bad_name.json refused_disc "a discovery input with a hostile experiment name"
rm -rf "$work/refused_cal" "$work/refused_disc"
no_canary "refused inputs"
echo "hostile names: both inputs refused (exit 2), naming the file, before any simulation"

# 2. The full runs.
start=$(date +%s)
"$paddy" run "$src/experiments/calibrate_paddy_mud.lua" "${small[@]}" --set "input=$inputs/calibration.json" \
  --set strategy=surrogate --set threads_per_job=1 --out "$cal_out" > calibration.log 2>&1 \
  || { tail -n 40 calibration.log >&2; fail "the calibration failed"; }
echo "calibration: done in $(( $(date +%s) - start )) s"
start=$(date +%s)
"$paddy" run "$src/experiments/discover.lua" "${small[@]}" --set "input=$inputs/discovery.json" \
  --set threads_per_job=1 --out "$disc_out" > discovery.log 2>&1 \
  || { tail -n 40 discovery.log >&2; fail "the discovery run failed"; }
echo "discovery: done in $(( $(date +%s) - start )) s"
no_canary "full runs"
outside > after.txt
cmp -s before.txt after.txt || { diff before.txt after.txt >&2; fail "files were written outside the output directories"; }

# 3. The reports.
description=$(cat "$inputs/description.txt")
for out in "$cal_out" "$disc_out"; do
  page="$out/report.html"
  check_page "$out" report.html
  [ "$images" -ge 1 ] || fail "$page shows no image"
  grep -qF '&lt;script&gt;alert(1)&lt;/script&gt;' "$page" || fail "$page: the description's markup does not appear escaped"
  ! grep -qF '<script>' "$page" || fail "$page: a <script> tag came from the text"
  ! grep -qiE '<[^>]* on(mouseover|click)=' "$page" || fail "$page: an attribute came from the text"
  # The parts without markup appear as given (an XHTML page may escape quotes as entities).
  unescaped=$(sed 's/&quot;/"/g; s/&#39;/'"'"'/g; s/&#x27;/'"'"'/g; s/&#34;/"/g' "$page")
  for part in "\$(touch $canary)" "\`touch $canary\`" "a'; touch $canary; echo '" "../../../etc/passwd" "é ñ 日本"; do
    [[ "$unescaped" == *"$part"* ]] || fail "$page: the description's text '$part' does not appear as given"
  done
  echo "$page: well-formed, $images images, the hostile text escaped"
done
[[ "$description" == hostile:* ]] || fail "description.txt does not hold the description"
echo "hostile_full_run: ok"
