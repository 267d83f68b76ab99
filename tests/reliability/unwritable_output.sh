#!/usr/bin/env bash
# Output that cannot be written (docs/reliability.md, section 3): a file limit (`ulimit -f`: EFBIG;
# a real full disk, ENOSPC, is full_disk.sh), a read-only output directory and an
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
limit_kb=64   # bash counts `ulimit -f` in 1024-byte blocks: the small outputs fit, the big ones do not
test_name=unwritable_output

immutable=""
cleanup() { [ -z "$immutable" ] || chattr -R -i "$immutable" 2>/dev/null || true; }
trap cleanup EXIT
[ -d "$work" ] && { chattr -R -i "$work" 2>/dev/null || true; chmod -R u+w "$work" 2>/dev/null || true; }
rm -rf "$work"
mkdir -p "$work"
cd "$work"
source "$here/output_checks.sh"  # sums, intact, run, expect_failure, write_earlier, each_output_fails

# 0. The limit is real: a program that does not ignore SIGXFSZ is killed by it.
( (ulimit -f "$limit_kb"; exec head -c 200000 /dev/zero > control.bin); echo $? > control.rc ) 2> /dev/null || true
rc=$(cat control.rc)
[ "$rc" -eq $((128 + 25)) ] || fail "head past ulimit -f $limit_kb ended with status $rc, not SIGXFSZ (153)"
echo "control: head past ulimit -f $limit_kb KiB killed by SIGXFSZ, as expected"

# 1. An earlier run's outputs, all small.
write_earlier

# 2. ulimit -f: each output in turn too large, into a copy of the earlier directory.
copy_earlier() { rm -rf "$1"; cp -a earlier "$1"; }
each_output_fails limit "$limit_kb" "File too large" copy_earlier

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
