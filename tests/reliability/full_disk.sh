#!/usr/bin/env bash
# A real full disk (docs/reliability.md, section 3): each output Paddy writes (HDF5 snapshot,
# checkpoint, JSON file, CSV file, result.json) in turn made larger than the free space of a small
# filesystem holding an earlier run's outputs. The write fails with ENOSPC; the run must exit
# non-zero with an error naming the file and "No space left on device", every earlier file must
# stay byte-identical, nothing half-written may be left under a real name and no temporary may
# be left (the checks shared with unwritable_output.sh: output_checks.sh).
#   full_disk.sh PADDY SOURCE_DIR WORK_DIR
#
# The small filesystem is a tmpfs of a size set per case, mounted in a private mount namespace
# so it cannot outlive the test: `unshare --mount --map-root-user` (a user namespace: works
# without root where the kernel allows it), else as root `unshare --mount`, else as root a mount
# in the current namespace, unmounted on exit. When none works the test is reported as not run
# (exit 77, ctest SKIP_RETURN_CODE) with each method's error printed: it never passes silently.
set -euo pipefail
paddy=${1:?usage: full_disk.sh PADDY SOURCE_DIR WORK_DIR}
src=${2:?}
work=${3:?}
here="$src/tests/reliability"
test_name=full_disk
free_kb=96   # free space left beside the earlier outputs: the small outputs fit, the big ones (160 kB or more) do not

if [ -z "${PADDY_FULL_DISK_METHOD:-}" ]; then
  # Which way of mounting a small filesystem works here: tried on a probe directory.
  rm -rf "$work"
  mkdir -p "$work/probe"
  probe="mount -t tmpfs -o size=64k tmpfs '$work/probe' && ! head -c 100000 /dev/zero > '$work/probe/x' 2> /dev/null"
  errors=""
  for method in userns rootns host; do
    case $method in
      userns) cmd=(unshare --mount --map-root-user) ;;
      rootns) [ "$(id -u)" -eq 0 ] || { errors+=" unshare --mount: not root;"; continue; }; cmd=(unshare --mount) ;;
      host) [ "$(id -u)" -eq 0 ] || { errors+=" mount: not root;"; continue; }; cmd=() ;;
    esac
    if [ "$method" = host ]; then
      if out=$(sh -c "$probe" 2>&1); then umount "$work/probe"; echo "full_disk: small filesystems by mount (root, this namespace)"
        PADDY_FULL_DISK_METHOD=$method exec bash "$0" "$@"; fi
      umount "$work/probe" 2> /dev/null || true
    elif out=$("${cmd[@]}" sh -c "$probe" 2>&1); then
      echo "full_disk: small filesystems by ${cmd[*]} + mount -t tmpfs"
      PADDY_FULL_DISK_METHOD=$method exec "${cmd[@]}" bash "$0" "$@"
    fi
    errors+=" ${cmd[*]:-mount}: ${out:-a 64 KiB tmpfs took 100 kB without ENOSPC};"
  done
  echo "full_disk: NOT RUN: no small filesystem could be mounted here:$errors" >&2
  exit 77
fi

mounts=()
cleanup() { local m; for m in "${mounts[@]}"; do umount "$m" 2> /dev/null || true; done; }
[ "$PADDY_FULL_DISK_METHOD" = host ] && trap cleanup EXIT
# small_fs DIR KB: a tmpfs of KB KiB at DIR.
small_fs() {
  mkdir -p "$1"
  mount -t tmpfs -o "size=$2k" tmpfs "$1" || fail "cannot mount a $2 KiB tmpfs at $1"
  mounts+=("$1")
}

rm -rf "$work"
mkdir -p "$work"
cd "$work"
source "$here/output_checks.sh"  # sums, intact, run, expect_failure, write_earlier, each_output_fails

# 0. The disk is really full: a plain write into a small filesystem fails with ENOSPC.
small_fs control 64
if head -c 200000 /dev/zero > control/fill.bin 2> control.err; then fail "200 kB fitted into a 64 KiB tmpfs"; fi
grep -q "No space left on device" control.err || { cat control.err >&2; fail "the control write did not fail with ENOSPC"; }
echo "control: 200 kB into a 64 KiB tmpfs: $(cat control.err)"

# 1. An earlier run's outputs, all small (on the ordinary filesystem).
write_earlier
used_kb=$(du -sk earlier | cut -f1)

# 2. Each output in turn too large for a filesystem holding a copy of the earlier outputs and
#    $free_kb KiB more.
copy_to_small_fs() { small_fs "$1" $((used_kb + free_kb)); cp -a earlier/. "$1/"; }
each_output_fails full none "No space left on device" copy_to_small_fs
echo "full_disk: ok ($PADDY_FULL_DISK_METHOD)"
