#!/usr/bin/env bash
# Hostile text through the calibration and discovery inputs into their HTML reports
# (hostile_reports.lua does the inputs and the pages' text; docs/reliability.md, section 4).
# Here: the output directory's own name is hostile too (quotes, $(...), backticks, markup,
# non-ASCII: it reaches the gnuplot scripts and shell commands of the figures); both reports are
# well-formed XHTML (xmllint) whose every image exists; no command ran (the canary file is never
# created) and nothing was written outside the output directory.
#   hostile_reports.sh PADDY SOURCE_DIR WORK_DIR
set -euo pipefail
source "$(dirname "$0")/hostile_setup.sh"  # paddy, src, work (entered), fail, canary
# (a command in the name would run in the working directory, $work: `touch CANARY` makes $canary)
out="$work/out '\$(touch CANARY)' \`touch CANARY\` \"q\" é <b>&amp;"
outside() { find "$work" -path "$out" -prune -o -print | sort; }
outside > before.txt
"$paddy" run "$src/tests/reliability/hostile_reports.lua" --out "$out" --set "canary=$canary" > run.log 2>&1 \
  || { cat run.log >&2; fail "hostile_reports.lua failed"; }
cat run.log
outside | grep -v -e '/run.log$' -e '/after.txt$' > after.txt
grep -v -e '/run.log$' -e '/after.txt$' before.txt | cmp -s - after.txt \
  || { diff <(grep -v -e '/run.log$' -e '/after.txt$' before.txt) after.txt >&2; fail "files were written outside the output directory"; }
[ ! -e "$canary" ] || fail "a command ran: $canary exists"
[ -z "$(find / -xdev -maxdepth 1 -name CANARY 2> /dev/null)" ] || fail "a command ran: /CANARY exists"
for page in calibration_report.html discovery_report.html; do
  check_page "$out" "$page"
  echo "$page: well-formed, $images images present"
done
echo "hostile_reports: ok"
