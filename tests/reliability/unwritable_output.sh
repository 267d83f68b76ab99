#!/usr/bin/env bash
# Output that cannot be written (docs/reliability.md, section 3): a file limit (`ulimit -f`, the
# same failure as a full disk: EFBIG instead of ENOSPC), a read-only output directory and an
# output path whose parent is a regular file. Each run must exit non-zero (not be killed by
# SIGXFSZ) with an error naming the file and the cause; earlier files stay byte-identical; no
# file is left half-written under its real name (every JSON parses, every HDF5 file opens) and no
# temporary file is left behind. A campaign whose jobs cannot write their output reports them
# failed with that message and keeps its state files parseable.
#   unwritable_output.sh PADDY SOURCE_DIR WORK_DIR
#
# Read-only directory: the tests run as root in CI, and root ignores the permission bits, so the
# directory is made immutable (`chattr -R +i`), which binds root too; where chattr is refused
# (no CAP_LINUX_IMMUTABLE, a filesystem without the flag) a non-root user falls back to
# `chmod a-w`, and root skips this part, saying so. The limit and the regular-file parent work
# everywhere.
set -euo pipefail
paddy=${1:?usage: unwritable_output.sh PADDY SOURCE_DIR WORK_DIR}
src=${2:?}
work=${3:?}
here="$src/tests/reliability"
script="$here/write_outputs.lua"
limit_kb=64   # bash counts `ulimit -f` in 1024-byte blocks: the small outputs fit, the big ones do not
fail() { echo "unwritable_output: FAIL: $*" >&2; exit 1; }

immutable=""
cleanup() { [ -z "$immutable" ] || chattr -R -i "$immutable" 2>/dev/null || true; }
trap cleanup EXIT
[ -d "$work" ] && { chattr -R -i "$work" 2>/dev/null || true; chmod -R u+w "$work" 2>/dev/null || true; }
rm -rf "$work"
mkdir -p "$work"
cd "$work"

# Digests of every file under a directory (path and MD5), sorted.
sums() { (cd "$1" && find . -type f -print0 | sort -z | xargs -0 -r md5sum); }
# Every JSON file under $1 parses and every HDF5 file opens; no temporary file is left.
intact() {
  local dir=$1 list="" f
  while IFS= read -r f; do list+="$f;"; done < <(find "$dir" -name '*.json' -type f)
  if [ -n "$list" ]; then
    "$paddy" run "$here/check_json.lua" --out "$work/check" --set "files=$list" > /dev/null 2> "$work/check.log" \
      || { cat "$work/check.log" >&2; fail "$dir: a JSON file does not parse"; }
  fi
  while IFS= read -r f; do
    h5ls -r "$f" > /dev/null 2>&1 || fail "$f does not open as HDF5"
  done < <(find "$dir" -name '*.h5' -type f)
  if [ -f "$dir/snapshots/particles.xmf" ]; then
    for f in $(grep -o 'snap_[0-9]*\.h5' "$dir/snapshots/particles.xmf" | sort -u); do
      [ -f "$dir/snapshots/$f" ] || fail "particles.xmf refers to the missing $f"
    done
  fi
  local left
  left=$(find "$dir" -name '*.tmp*')
  [ -z "$left" ] || fail "temporary files left behind: $left"
}
# run NAME LIMIT_KB ARGS...: paddy run with an optional file limit; sets rc, output in NAME.err
run() {
  local name=$1 lim=$2
  shift 2
  rc=0
  if [ "$lim" = none ]; then
    "$paddy" run "$@" > "$name.out" 2> "$name.err" || rc=$?
  else
    (ulimit -f "$lim"; exec "$paddy" run "$@") > "$name.out" 2> "$name.err" || rc=$?
  fi
}
# expect_failure NAME FILE CAUSE: the run failed by itself, naming FILE and CAUSE.
expect_failure() {
  local name=$1 file=$2 cause=$3
  [ "$rc" -ne 0 ] || fail "$name: exit status 0 although $file could not be written"
  [ "$rc" -lt 128 ] || fail "$name: paddy was killed by signal $((rc - 128)) instead of reporting the error"
  local line
  line=$(grep '^paddy: error' "$name.err" | grep -F -- "$file" | head -n 1 || true)
  [[ "$line" == *"$file"* ]] || { cat "$name.err" >&2; fail "$name: the error does not name $file"; }
  [[ "$line" == *"$cause"* ]] || { cat "$name.err" >&2; fail "$name: the error does not give the cause '$cause'"; }
  echo "$name: exit $rc: ${line:0:220}"
}

# 0. The limit is real: a program that does not ignore SIGXFSZ is killed by it.
( (ulimit -f "$limit_kb"; exec head -c 200000 /dev/zero > control.bin); echo $? > control.rc ) 2> /dev/null || true
rc=$(cat control.rc)
[ "$rc" -eq $((128 + 25)) ] || fail "head past ulimit -f $limit_kb ended with status $rc, not SIGXFSZ (153)"
echo "control: head past ulimit -f $limit_kb KiB killed by SIGXFSZ, as expected"

# 1. An earlier run's outputs, all small.
run earlier none "$script" --out earlier --threads 1 --set label=earlier
[ "$rc" -eq 0 ] || { cat earlier.err >&2; fail "the earlier run failed"; }
for f in result.json data.json table.csv state.h5 snapshots/snap_000000.h5 snapshots/particles.xmf; do
  [ -s "earlier/$f" ] || fail "the earlier run did not write $f"
done

# 2. ulimit -f: each output in turn too large, into a copy of the earlier directory.
#    result.json and snapshots/ are cleared by design when a run starts (an earlier run's outcome
#    or snapshot series must never pass for this run's); every other file must be untouched.
for case in "snapshot snapshots/snap_000000.h5" "checkpoint state.h5" "json data.json" "csv table.csv" \
            "result result.json"; do
  set -- $case
  what=$1 file=$2
  rm -rf "d_$what"
  cp -a earlier "d_$what"
  sums "d_$what" | grep -v -e ' ./result.json$' -e ' ./snapshots/' > "before_$what.txt"
  run "limit_$what" "$limit_kb" "$script" --out "d_$what" --threads 1 --set outputs="$what" --set big=1 --set label=later
  expect_failure "limit_$what" "d_$what/$file" "File too large"
  sums "d_$what" | grep -v -e ' ./result.json$' -e ' ./snapshots/' -e ' ./error.json$' > "after_$what.txt"
  cmp -s "before_$what.txt" "after_$what.txt" || { diff "before_$what.txt" "after_$what.txt" >&2; fail "limit_$what: an earlier file changed"; }
  [ ! -e "d_$what/result.json" ] || fail "limit_$what: a failed run left a result.json"
  [ "$what" = result ] || grep -q 'File too large' "d_$what/error.json" || fail "limit_$what: error.json does not hold the error"
  intact "d_$what"
done

# 3. The output directory's parent is a regular file.
echo "not a directory" > plain_file
run parent_file none "$script" --out plain_file/out --threads 1
expect_failure parent_file "plain_file/out" "Not a directory"
[ "$(cat plain_file)" = "not a directory" ] || fail "the regular file was changed"

# 4. A read-only output directory holding an earlier run's outputs: nothing may change at all.
rm -rf ro
cp -a earlier ro
sums ro > before_ro.txt
method=""
if chattr -R +i ro 2> /dev/null; then
  immutable="$work/ro"
  if touch ro/probe 2> /dev/null; then rm -f ro/probe; chattr -R -i ro; immutable=""; else method="chattr +i"; fi
fi
if [ -z "$method" ] && [ "$(id -u)" -ne 0 ]; then
  chmod -R a-w ro
  method="chmod a-w"
fi
if [ -n "$method" ]; then
  run readonly none "$script" --out ro --threads 1 --set label=later
  cause="Operation not permitted"
  [ "$method" = "chmod a-w" ] && cause="Permission denied"
  expect_failure readonly "ro/snapshots/snap_000000.h5" "$cause"  # the first file the script writes
  sums ro > after_ro.txt
  cmp -s before_ro.txt after_ro.txt || { diff before_ro.txt after_ro.txt >&2; fail "readonly: a file in the read-only directory changed"; }
  intact ro
  echo "read-only directory ($method): every earlier file byte-identical, result.json included"
  cleanup
  immutable=""
  chmod -R u+w ro
else
  echo "read-only directory: SKIPPED (chattr +i refused and running as root, which ignores permission bits)"
fi

# 5. A campaign whose jobs cannot write their output (local executor, same limit).
rm -rf camp
run campaign "$limit_kb" "$here/campaign_unwritable.lua" --out camp --threads 2
[ "$rc" -eq 0 ] || { cat campaign.err >&2; fail "the campaign driver failed (exit $rc)"; }
cat campaign.out
grep -q '^small_json: done$' campaign.out || fail "campaign: a job that fits the limit did not complete"
grep -q '^small_all: done$' campaign.out || fail "campaign: a job that fits the limit did not complete"
grep -q "^big_json: failed: .*data.json.*File too large" campaign.out || fail "campaign: the big JSON job is not reported failed with its file and cause"
grep -q "^big_snapshot: failed: .*snap_000000.h5.*File too large" campaign.out \
  || fail "campaign: the big snapshot job is not reported failed with its file and cause"
n_failed=$(find camp/campaign/jobs -name failed.json | wc -l)
[ "$n_failed" -eq 2 ] || fail "campaign: $n_failed failed.json records instead of 2"
intact camp
# Without the limit the same campaign completes: the failed jobs run again, the done ones do not.
sums camp/campaign | grep ' ./jobs/.*/result.json$' | sort > camp_done_before.txt
run campaign_again none "$here/campaign_unwritable.lua" --out camp --threads 2
[ "$rc" -eq 0 ] || { cat campaign_again.err >&2; fail "the campaign failed without the limit"; }
[ "$(grep -c ': done$' campaign_again.out)" -eq 4 ] || { cat campaign_again.out >&2; fail "campaign: not every job completed without the limit"; }
sums camp/campaign | grep ' ./jobs/.*/result.json$' | sort > camp_done_after.txt
[ -z "$(comm -23 camp_done_before.txt camp_done_after.txt)" ] || fail "campaign: a job done before was run again"
intact camp
echo "unwritable_output: ok"
