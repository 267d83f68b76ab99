# Shared by the scripts of output that cannot be written (sourced, not run): unwritable_output.sh
# (`ulimit -f`, read-only directory, regular file as parent, campaign) and full_disk.sh (a real
# full filesystem). They run write_outputs.lua, which writes each kind of output Paddy produces,
# and check after a failed write that the run reported it naming the file and the cause, that
# every earlier file is byte-identical, and that nothing half-written or temporary is left.
# The sourcing script sets: paddy (the executable), here (tests/reliability), work (the work
# directory, current directory) and test_name (prefix of the failure messages).

script="$here/write_outputs.lua"
fail() { echo "$test_name: FAIL: $*" >&2; exit 1; }

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

# run NAME LIMIT_KB ARGS...: paddy run with an optional file limit ("none"); sets rc, output in
# NAME.out and NAME.err.
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
  # The user sees paddy's one error line, not HDF5's own dump of its error stack.
  ! grep -q 'HDF5-DIAG' "$name.err" || { cat "$name.err" >&2; fail "$name: HDF5 printed its error stack"; }
  echo "$name: exit $rc: ${line:0:220}"
}

# An earlier run's outputs, all small, in $work/earlier.
write_earlier() {
  run earlier none "$script" --out earlier --threads 1 --set label=earlier
  [ "$rc" -eq 0 ] || { cat earlier.err >&2; fail "the earlier run failed"; }
  local f
  for f in result.json data.json table.csv state.h5 snapshots/snap_000000.h5 snapshots/particles.xmf; do
    [ -s "earlier/$f" ] || fail "the earlier run did not write $f"
  done
}

# each_output_fails PREFIX LIMIT CAUSE PREPARE: each output in turn (snapshot, checkpoint, JSON,
# CSV, result.json) made too large for where it goes. `PREPARE DIR` makes DIR a copy of
# $work/earlier (on the filesystem under test); the run (under `ulimit -f LIMIT`, or "none") must
# fail naming the file and CAUSE, leave every earlier file byte-identical, leave no result.json,
# put the error into error.json (unless result.json itself failed), and leave every JSON and
# HDF5 file whole and no temporary. result.json and snapshots/ are cleared by design when a run
# starts (an earlier run's outcome or snapshot series must never pass for this run's).
each_output_fails() {
  local prefix=$1 lim=$2 cause=$3 prepare=$4 case what file d
  for case in "snapshot snapshots/snap_000000.h5" "checkpoint state.h5" "json data.json" "csv table.csv" \
              "result result.json"; do
    set -- $case
    what=$1 file=$2 d="d_${prefix}_$what"
    "$prepare" "$d"
    sums "$d" | grep -v -e ' ./result.json$' -e ' ./snapshots/' > "before_$d.txt"
    run "${prefix}_$what" "$lim" "$script" --out "$d" --threads 1 --set outputs="$what" --set big=1 --set label=later
    expect_failure "${prefix}_$what" "$d/$file" "$cause"
    sums "$d" | grep -v -e ' ./result.json$' -e ' ./snapshots/' -e ' ./error.json$' > "after_$d.txt"
    cmp -s "before_$d.txt" "after_$d.txt" || { diff "before_$d.txt" "after_$d.txt" >&2; fail "${prefix}_$what: an earlier file changed"; }
    [ ! -e "$d/result.json" ] || fail "${prefix}_$what: a failed run left a result.json"
    [ "$what" = result ] || grep -q "$cause" "$d/error.json" || fail "${prefix}_$what: error.json does not hold the error"
    intact "$d"
  done
}
