#!/usr/bin/env bash
# An HTML report in headless Chromium (CTest clients.*_report, docs/reliability.md): check_page.py
# loads it, every image must load and the console stay free of errors; the screenshot is kept in WORK.
#   check_report.sh REPORT.html WORK MIN_IMAGES
#   check_report.sh --selftest WORK   (a page with a missing image and a console error must fail)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
fail() { echo "check_report: FAIL: $*" >&2; exit 1; }
command -v chromium >/dev/null || fail "chromium is not installed (scripts/install-deps.sh: the clients group)"
if [ "$1" = --selftest ]; then
  work=${2:?}
  rm -rf "$work"; mkdir -p "$work"
  # A 1x1 PNG, a missing one and a script error: the checker must see both faults.
  printf '\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\1\0\0\0\1\10\6\0\0\0\x1f\x15\xc4\x89\0\0\0\rIDATx\x9cc\xf8\xff\xff?\0\5\xfe\2\xfe\xa7\x35\x81\x84\0\0\0\0IEND\xaeB`\x82' > "$work/ok.png"
  cat > "$work/good.html" <<'HTML'
<!DOCTYPE html><html><head><title>good</title></head><body><p>one image</p><img src="ok.png" alt="ok"/></body></html>
HTML
  cat > "$work/bad.html" <<'HTML'
<!DOCTYPE html><html><head><title>bad</title></head><body><img src="ok.png" alt="ok"/>
<img src="figures/missing.png" alt="missing"/><script>console.error("deliberate error")</script></body></html>
HTML
  python3 "$here/check_page.py" "$work/good.html" "$work/good.png" --min-images 1 || fail "a good page failed"
  set +e
  python3 "$here/check_page.py" "$work/bad.html" "$work/bad.png" > "$work/bad.log" 2>&1
  code=$?
  set -e
  cat "$work/bad.log"
  [ "$code" = 1 ] || fail "a broken page gave exit code $code, expected 1"
  grep -q "image did not load: figures/missing.png" "$work/bad.log" || fail "the missing image was not reported"
  grep -q "console error: deliberate error" "$work/bad.log" || fail "the console error was not reported"
  echo "check_report: the checker passes a good page and names both faults of a broken one"
  exit 0
fi
# REPORT may be a directory: every report.html under it is checked.
report=${1:?usage: check_report.sh REPORT.html|DIR WORK MIN_IMAGES}
work=${2:?}
min=${3:-1}
mkdir -p "$work"
if [ -d "$report" ]; then
  mapfile -t pages < <(find "$report" -name report.html | sort)
else
  pages=("$report")
fi
[ "${#pages[@]}" -ge 1 ] && [ -s "${pages[0]}" ] || fail "no report at $report (made by the test this one depends on)"
t0=$(date +%s)
k=0
for page in "${pages[@]}"; do
  k=$((k + 1))
  python3 "$here/check_page.py" "$page" "$work/report_$k.png" --min-images "$min" \
    || fail "$page does not load cleanly in Chromium"
done
echo "check_report: ${#pages[@]} reports in $(( $(date +%s) - t0 )) s; screenshots in $work"
