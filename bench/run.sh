#!/usr/bin/env bash
# bench/run.sh -- Paddy's performance benchmark: the same problem run in Paddy, LAMMPS and
# LIGGGHTS, interleaved; reports particle-steps per second.
#
# Two problems (-p), both 2000 steps of dt = 0.2 T_R, skin 0.4 R, 2 mm mud spheres:
#   column   (default) cohesive (JKR) column collapse: N spheres on a simple cubic lattice
#            released on a floor; bench/column_collapse.lua, bench/lammps/column_collapse.in,
#            bench/liggghts/column_collapse.in.
#   packing  a settled random packing (poured and settled at rest in a box by Paddy once per
#            size, bench/packing_make.lua -> bench/data/packing_N.data, read by all three codes)
#            released on its floor with the side walls gone, with the cohesive law and with
#            plain Hertz-Mindlin (-l); bench/packing.lua, bench/lammps/packing.in,
#            bench/liggghts/packing.in.
# Method and results are in docs/performance.md.
#
# Usage:  bench/run.sh [options]
#   -n "10000 20000 40000"  requested particle counts        (env BENCH_SIZES)
#   -t "1 2"                thread / rank counts             (env BENCH_THREADS)
#   -r 3                    repeats of every case            (env BENCH_REPEATS)
#   -s 2000                 timed steps                      (env BENCH_STEPS)
#   -c "paddy lammps liggghts"  codes to run                 (env BENCH_CODES)
#   -p column|packing       the problem (default column)     (env BENCH_PROBLEM)
#   -l "cohesive cohesionless"  contact laws, packing only   (env BENCH_LAWS; column: cohesive)
#   -o FILE                 result file (default bench/results/latest.json, for packing
#                           bench/results/latest_packing.json)
#   -m                      merge: keep the runs already in FILE and add the new ones
#                           (for measuring in chunks on a shared machine); with -c none it
#                           only rebuilds FILE's summary and tables from the runs in it
#   -B                      do not build Paddy (use build/bin/paddy as it is)
#   -w SECONDS              before each run, wait up to SECONDS for the machine to be quiet
#                           (other processes using < 0.25 CPU over 1 s; env BENCH_WAIT,
#                           default 0 = measure the busy CPUs but do not wait)
#   -h                      this help
# Environment: PADDY_BIN (default build/bin/paddy), BUILD_DIR (default build),
#   LMP (default lmp), LIGGGHTS (default liggghts), MPIRUN (default mpirun), RUN_TIMEOUT
#   (seconds per run, default 900), PACKING_DIR (default bench/data: the packings; a missing
#   bench/data/packing_N.data is made first with
#   $PADDY_BIN run bench/packing_make.lua --set n=N --set data=FILE --threads 1, untimed).
#
# What it does
#   1. Paddy: configures and builds the release build if needed
#      (cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release; cmake --build build).
#      If BUILD_DIR exists with another build type, build-release/ is used instead.
#      Then, per case:
#        $PADDY_BIN run bench/column_collapse.lua --set n=N --set steps=S --threads T --out DIR
#      (packing: bench/packing.lua --set data=bench/data/packing_N.data --set law=LAW ...)
#      ASSUMPTION (for the lead): Paddy writes DIR/result.json containing a numeric key
#        "particle_steps_per_second" = particles x timed steps / wall seconds of the timed run
#      (top level or nested in any object; the first one found is used), and optionally
#      "contacts" and "particles". If the build, the script, the binary or that key is missing,
#      Paddy is skipped with "paddy: not available (<reason>)" and the rest still runs.
#   2. LAMMPS: threads=1 -> `lmp` (one MPI rank, OMP_NUM_THREADS=1). threads=T>1 -> every
#      variant this build supports: `mpirun -np T lmp` (MPI, always) and, if the build has the
#      OPENMP package, `lmp -sf omp -pk omp T` (OpenMP). The summary keeps LAMMPS's best
#      variant per case and names it. (Debian 12's LAMMPS has no OPENMP package.)
#   3. LIGGGHTS: threads=1 -> `liggghts`; T>1 -> `mpirun -np T liggghts` (it has no OpenMP).
#   particle-steps/s of LAMMPS and LIGGGHTS = atoms x steps / "Loop time of" (the timed run
#   only, setup excluded); contacts = overlapping pairs at the last step (compute contact/atom).
#   Cases are interleaved (repeat, size, threads, code) so that load from other users of the
#   machine spreads over all codes; the CPUs busy with other work in the second before each run
#   are recorded ("busy_cpus_before"; see -w to wait for a quiet machine).
#   4. Writes FILE (JSON: every run + a summary with medians + Paddy's ratios to LAMMPS and
#      LIGGGHTS) and prints markdown tables; contacts per sphere = 2 x contacts / particles.
#      A run is flagged "contended" when its processes got < 85 % of the CPU time they could
#      use (cpu_share; over the timed loop where the code reports its loop time, see
#      contended() below) or > 0.5 CPU was busy with other work just before it; a case's median is
#      taken over its uncontended runs when it has any (the table says "contended!" if not).
#
# Needs: bash, python3 (standard library), lmp / liggghts / mpirun for those codes,
#        cmake + ninja + Paddy's dependencies for Paddy.
set -uo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ROOT="$(cd "$HERE/.." && pwd)"

SIZES="${BENCH_SIZES:-10000 20000 40000}"
THREADS="${BENCH_THREADS:-1 2}"
REPEATS="${BENCH_REPEATS:-3}"
STEPS="${BENCH_STEPS:-2000}"
CODES="${BENCH_CODES:-paddy lammps liggghts}"
PROBLEM="${BENCH_PROBLEM:-column}"
LAWS="${BENCH_LAWS:-cohesive cohesionless}"
OUT=""
PACKING_DIR="${PACKING_DIR:-$HERE/data}"
MERGE=0
BUILD=1
BUILD_DIR="${BUILD_DIR:-build}"
PADDY_BIN="${PADDY_BIN:-}"
LMP="${LMP:-lmp}"
LIGGGHTS="${LIGGGHTS:-liggghts}"
MPIRUN="${MPIRUN:-mpirun}"
RUN_TIMEOUT="${RUN_TIMEOUT:-900}"
WAIT="${BENCH_WAIT:-0}"
QUIET=0.25

usage() { sed -n '2,/^set -uo/p' "${BASH_SOURCE[0]}" | sed '$d' | sed 's/^# \{0,1\}//'; }

while getopts "n:t:r:s:c:p:l:o:mBw:h" opt; do
  case "$opt" in
    n) SIZES="$OPTARG" ;;
    t) THREADS="$OPTARG" ;;
    r) REPEATS="$OPTARG" ;;
    s) STEPS="$OPTARG" ;;
    c) CODES="$OPTARG" ;;
    p) PROBLEM="$OPTARG" ;;
    l) LAWS="$OPTARG" ;;
    o) OUT="$OPTARG" ;;
    m) MERGE=1 ;;
    B) BUILD=0 ;;
    w) WAIT="$OPTARG" ;;
    h) usage; exit 0 ;;
    *) usage >&2; exit 2 ;;
  esac
done

command -v python3 >/dev/null || { echo "bench/run.sh: python3 is required" >&2; exit 2; }
case "$PROBLEM" in
  column)  SCRIPT=column_collapse; LAWS=cohesive; OUT="${OUT:-$HERE/results/latest.json}" ;;
  packing) SCRIPT=packing; OUT="${OUT:-$HERE/results/latest_packing.json}"
           for law in $LAWS; do
             [[ $law == cohesive || $law == cohesionless ]] ||
               { echo "bench/run.sh: unknown law '$law' (cohesive, cohesionless)" >&2; exit 2; }
           done ;;
  *) echo "bench/run.sh: unknown problem '$PROBLEM' (column, packing)" >&2; exit 2 ;;
esac
has_code() { [[ " $CODES " == *" $1 "* ]]; }

WORK="$(mktemp -d "${TMPDIR:-/tmp}/paddy-bench.XXXXXX")"
trap 'rm -rf "$WORK"' EXIT
RUNS="$WORK/runs.jsonl"   # one JSON object per run
export BENCH_STEPS_NOW="$STEPS" BENCH_PROBLEM_NOW="$PROBLEM" BENCH_LAW_NOW=cohesive
: > "$RUNS"

# MPI as root (containers/CI) needs an explicit opt-in; --bind-to core is Open MPI's default
# for <= 2 ranks, stated so that it is visible.
MPI_FLAGS=()
if "$MPIRUN" --version 2>/dev/null | grep -qi "open mpi"; then
  MPI_FLAGS+=(--bind-to core)
  [[ $(id -u) -eq 0 ]] && MPI_FLAGS+=(--allow-run-as-root)
fi

log() { echo "[bench] $*" >&2; }
# busy_cpus: CPUs in use by other processes, measured over 1 s from /proc/stat (before a run,
# so the benchmark itself is not counted).
busy_cpus() {
  local a b
  a=($(head -1 /proc/stat)); sleep 1; b=($(head -1 /proc/stat))
  python3 -c "
import os
a=[int(x) for x in '${a[*]:1}'.split()]; b=[int(x) for x in '${b[*]:1}'.split()]
d=[y-x for x,y in zip(a,b)]; tot=sum(d); idle=d[3]+d[4]
print(f'{(tot-idle)/tot*os.cpu_count():.2f}' if tot else '0')"
}
# quiet_check: waits (up to $WAIT s) for a quiet machine, then prints the busy CPUs it measured
quiet_check() {
  local busy waited=0
  busy="$(busy_cpus)"
  while [[ $waited -lt $WAIT ]] && python3 -c "import sys; sys.exit(0 if $busy >= $QUIET else 1)"; do
    sleep 4; waited=$((waited + 5)); busy="$(busy_cpus)"
  done
  [[ $waited -gt 0 ]] && log "  waited ${waited}s for a quiet machine (busy CPUs now $busy)"
  echo "$busy"
}

# timed OUTFILE cmd... : runs cmd, writes "wall_seconds cpu_seconds" of it and its children
# (cpu = user + sys of all its processes, MPI ranks included) to OUTFILE; returns its exit code.
timed() {
  python3 -c '
import resource, subprocess, sys, time
t = time.monotonic(); rc = subprocess.call(sys.argv[2:]); w = time.monotonic() - t
r = resource.getrusage(resource.RUSAGE_CHILDREN)
open(sys.argv[1], "w").write("%r %r\n" % (w, r.ru_utime + r.ru_stime)); sys.exit(rc)' "$@"
}

# record CODE VARIANT N T REPEAT STATUS PSPS ATOMS CONTACTS SECONDS BUSY NOTE TIMEFILE
record() {
  python3 - "$@" >> "$RUNS" <<'EOF'
import json, os, sys
code, variant, n, t, rep, status, psps, atoms, contacts, secs, busy, note, tf = sys.argv[1:14]
num = lambda s, f=float: (f(s) if s not in ("", "null", "None") else None)
try:
    wall, cpu = map(float, open(tf).read().split())
except Exception:
    wall = cpu = None
print(json.dumps({"problem": os.environ["BENCH_PROBLEM_NOW"], "law": os.environ["BENCH_LAW_NOW"],
                  "code": code, "variant": variant, "n_requested": int(n), "threads": int(t),
                  "repeat": int(rep), "status": status, "particle_steps_per_second": num(psps),
                  "particles": num(atoms, int), "contacts": num(contacts, int),
                  "loop_seconds": num(secs), "busy_cpus_before": num(busy),
                  "process_wall_seconds": wall, "process_cpu_seconds": cpu,
                  # cpu / (wall x threads) of the whole process (setup included): well below 1
                  # means other processes took CPU time from this run. MPI ranks busy-wait, so
                  # for them it only shows time-sharing, not parallel efficiency.
                  "cpu_share": (cpu / (wall * int(t)) if wall and cpu is not None else None),
                  # single-thread runs only: particle-steps per CPU second of the whole process
                  # (setup included, so a slight underestimate); much less sensitive to other
                  # processes sharing the cores than the wall-clock figure
                  "particle_steps_per_cpu_second": (num(atoms, int) * int(__import__("os").environ["BENCH_STEPS_NOW"]) / cpu
                      if int(t) == 1 and cpu and atoms not in ("", "null", "None") else None),
                  "note": note}))
EOF
}

# parse_log LOGFILE -> "psps atoms contacts seconds" (LAMMPS and LIGGGHTS print the same line)
parse_log() {
  python3 - "$1" <<'EOF'
import re, sys
text = open(sys.argv[1], errors="replace").read()
loops = re.findall(r"Loop time of ([0-9.eE+-]+) on \d+ procs for (\d+) steps with (\d+) atoms", text)
done = re.findall(r"BENCH done natoms=(\d+) contacts=([0-9.eE+-]+)", text)
if not loops:
    sys.exit(1)
secs, steps, atoms = float(loops[-1][0]), int(loops[-1][1]), int(loops[-1][2])
contacts = int(float(done[-1][1])) if done else ""
print(atoms * steps / secs if secs > 0 else "", atoms, contacts, secs)
EOF
}

# run_md CODE VARIANT N T REPEAT -- command...   (LAMMPS / LIGGGHTS)
run_md() {
  local code="$1" variant="$2" n="$3" t="$4" rep="$5"; shift 6
  local logf="$WORK/${code}_${variant}_${BENCH_LAW_NOW}_${n}_${t}_${rep}.log" load parsed
  load="$(quiet_check)"
  log "$code ($variant) $PROBLEM/$BENCH_LAW_NOW n=$n threads=$t repeat=$rep: $*"
  ( cd "$WORK" && OMP_NUM_THREADS="$t" timed "$logf.time" timeout --foreground "$RUN_TIMEOUT" "$@" \
      -log "$logf" -screen none > "$logf.out" 2>&1 )
  local rc=$?
  if [[ $rc -eq 0 ]] && parsed="$(parse_log "$logf")"; then
    read -r psps atoms contacts secs <<< "$parsed"
    record "$code" "$variant" "$n" "$t" "$rep" ok "$psps" "$atoms" "$contacts" "$secs" "$load" "" "$logf.time"
    log "  -> $(python3 -c "print(f'{$psps/1e6:.3f} M particle-steps/s, {$secs:.2f} s, contacts $contacts')")"
  else
    local why; why="$(grep -h -m1 -E 'ERROR|rror' "$logf" "$logf.out" 2>/dev/null | head -c 200)"
    record "$code" "$variant" "$n" "$t" "$rep" failed "" "" "" "" "$load" "exit $rc: $why" "$logf.time"
    log "  -> FAILED (exit $rc) $why"
  fi
}

# ---------------------------------------------------------------- Paddy: build and checks
PADDY_OK=0
PADDY_WHY=""
if has_code paddy; then
  if [[ ! -f "$HERE/$SCRIPT.lua" ]]; then
    PADDY_WHY="bench/$SCRIPT.lua is missing"
  else
    if [[ -z "$PADDY_BIN" ]]; then
      cache="$ROOT/$BUILD_DIR/CMakeCache.txt"
      if [[ -f "$cache" ]] && ! grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$cache"; then
        log "$BUILD_DIR/ is not a Release build; using build-release/"
        BUILD_DIR=build-release
      fi
      PADDY_BIN="$ROOT/$BUILD_DIR/bin/paddy"
      if [[ $BUILD -eq 1 ]]; then
        log "building Paddy (Release) in $BUILD_DIR/"
        if { [[ -f "$ROOT/$BUILD_DIR/CMakeCache.txt" ]] ||
             cmake -S "$ROOT" -B "$ROOT/$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=Release \
               > "$WORK/cmake-configure.log" 2>&1; } &&
           cmake --build "$ROOT/$BUILD_DIR" > "$WORK/cmake-build.log" 2>&1; then
          :
        else
          PADDY_WHY="release build failed (see cmake output: rerun cmake --build $BUILD_DIR)"
          tail -n 20 "$WORK"/cmake-*.log >&2 2>/dev/null
        fi
      fi
    fi
    if [[ -z "$PADDY_WHY" ]]; then
      if [[ -x "$PADDY_BIN" ]]; then PADDY_OK=1
      else PADDY_WHY="$PADDY_BIN not found"; fi
    fi
  fi
  [[ $PADDY_OK -eq 1 ]] || echo "paddy: not available ($PADDY_WHY)"
fi

run_paddy() {
  local n="$1" t="$2" rep="$3" dir="$WORK/paddy_${BENCH_LAW_NOW}_${1}_${2}_${3}" load parsed rc
  local sets=(--set "n=$n")
  [[ $PROBLEM == packing ]] && sets=(--set "data=$PACKING_DIR/packing_$n.data" --set "law=$BENCH_LAW_NOW")
  load="$(quiet_check)"
  log "paddy $PROBLEM/$BENCH_LAW_NOW n=$n threads=$t repeat=$rep"
  ( cd "$ROOT" && OMP_NUM_THREADS="$t" timed "$dir.time" timeout --foreground "$RUN_TIMEOUT" "$PADDY_BIN" run \
      "$HERE/$SCRIPT.lua" "${sets[@]}" --set "steps=$STEPS" --threads "$t" --out "$dir" \
      > "$dir.out" 2>&1 )
  rc=$?
  if [[ $rc -eq 0 ]] && parsed="$(python3 - "$dir/result.json" <<'EOF'
import json, sys
def find(obj, key):
    if isinstance(obj, dict):
        if key in obj: return obj[key]
        for v in obj.values():
            r = find(v, key)
            if r is not None: return r
    elif isinstance(obj, list):
        for v in obj:
            r = find(v, key)
            if r is not None: return r
    return None
try:
    res = json.load(open(sys.argv[1]))
except Exception:
    sys.exit(1)
psps = find(res, "particle_steps_per_second")
if not isinstance(psps, (int, float)) or psps <= 0:
    sys.exit(2)
val = lambda k: find(res, k) if isinstance(find(res, k), (int, float)) else ""
print(psps, val("particles"), val("contacts"))
EOF
)"; then
    read -r psps atoms contacts <<< "$parsed"
    record paddy default "$n" "$t" "$rep" ok "$psps" "$atoms" "$contacts" "" "$load" "" "$dir.time"
    log "  -> $(python3 -c "print(f'{$psps/1e6:.3f} M particle-steps/s')")"
    return 0
  fi
  local why="exit $rc"
  [[ $rc -eq 0 ]] && why="no numeric particle_steps_per_second in $dir/result.json"
  record paddy default "$n" "$t" "$rep" failed "" "" "" "" "$load" "$why" "$dir.time"
  echo "paddy: not available ($why; $(tail -n 3 "$dir.out" 2>/dev/null | tr '\n' ' '))"
  return 1
}

# ---------------------------------------------------------------- LAMMPS / LIGGGHTS checks
LMP_OK=0; LIG_OK=0; LMP_OMP=0
if has_code lammps; then
  if command -v "$LMP" >/dev/null; then
    LMP_OK=1
    (cd "$WORK" && "$LMP" -h 2>/dev/null) | sed -n '/Installed packages/,/List of individual/p' | grep -qw OPENMP \
      && LMP_OMP=1
  else echo "lammps: not available ($LMP not found; apt-get install lammps)"; fi
fi
if has_code liggghts; then
  if command -v "$LIGGGHTS" >/dev/null; then LIG_OK=1
  else echo "liggghts: not available ($LIGGGHTS not found; apt-get install liggghts)"; fi
fi
HAVE_MPI=0; command -v "$MPIRUN" >/dev/null && HAVE_MPI=1

# ---------------------------------------------------------------- packing: the settled packings
# Made once per size by Paddy (untimed, one thread: deterministic) and kept in $PACKING_DIR.
if [[ $PROBLEM == packing ]]; then
  maker="${PADDY_BIN:-$ROOT/$BUILD_DIR/bin/paddy}"
  sizes_ok=""
  for n in $SIZES; do
    f="$PACKING_DIR/packing_$n.data"
    if [[ ! -s "$f" ]]; then
      log "making the settled packing of $n spheres: $f (untimed)"
      mkdir -p "$PACKING_DIR"
      ( cd "$ROOT" && "$maker" run "$HERE/packing_make.lua" --set "n=$n" --set "data=$f.tmp" \
          --threads 1 --out "$WORK/make_$n" > "$WORK/make_$n.out" 2>&1 ) && mv "$f.tmp" "$f" ||
        { log "  -> FAILED: $(tail -n 2 "$WORK/make_$n.out" | tr '\n' ' ')"; continue; }
      log "  -> $(tail -n 1 "$WORK/make_$n.out")"
    fi
    sizes_ok="$sizes_ok $n"
  done
  SIZES="$sizes_ok"
  [[ -n "${SIZES// /}" ]] || { echo "bench/run.sh: no settled packing available" >&2; exit 1; }
fi

# md_args CODE N -> the input arguments of LAMMPS / LIGGGHTS for the problem (into ARGS)
md_args() {
  if [[ $PROBLEM == packing ]]; then
    ARGS=(-in "$HERE/$1/packing.in" -var data "$PACKING_DIR/packing_$2.data" -var law "$BENCH_LAW_NOW"
          -var steps "$STEPS")
  else
    ARGS=(-in "$HERE/$1/column_collapse.in" -var n "$2" -var steps "$STEPS")
  fi
}

# ---------------------------------------------------------------- the matrix, interleaved
for rep in $(seq 1 "$REPEATS"); do
  for n in $SIZES; do
    for t in $THREADS; do
      for law in $LAWS; do
        export BENCH_LAW_NOW="$law"
        if [[ $PADDY_OK -eq 1 ]]; then run_paddy "$n" "$t" "$rep" || PADDY_OK=0; fi
        if [[ $LMP_OK -eq 1 ]]; then
          md_args lammps "$n"; args=("${ARGS[@]}")
          if [[ $t -eq 1 ]]; then
            run_md lammps serial "$n" 1 "$rep" -- "$LMP" "${args[@]}"
          else
            [[ $HAVE_MPI -eq 1 ]] &&
              run_md lammps "mpi$t" "$n" "$t" "$rep" -- "$MPIRUN" "${MPI_FLAGS[@]}" -np "$t" "$LMP" "${args[@]}"
            [[ $LMP_OMP -eq 1 ]] &&
              run_md lammps "omp$t" "$n" "$t" "$rep" -- "$LMP" -sf omp -pk omp "$t" "${args[@]}"
          fi
        fi
        if [[ $LIG_OK -eq 1 ]]; then
          md_args liggghts "$n"; args=("${ARGS[@]}")
          if [[ $t -eq 1 ]]; then
            run_md liggghts serial "$n" 1 "$rep" -- "$LIGGGHTS" "${args[@]}"
          elif [[ $HAVE_MPI -eq 1 ]]; then
            run_md liggghts "mpi$t" "$n" "$t" "$rep" -- "$MPIRUN" "${MPI_FLAGS[@]}" -np "$t" "$LIGGGHTS" "${args[@]}"
          fi
        fi
      done
    done
  done
done

# ---------------------------------------------------------------- summary: JSON + markdown
mkdir -p "$(dirname "$OUT")"
python3 - "$RUNS" "$OUT" "$MERGE" "$STEPS" "$WORK" "$PROBLEM" <<'EOF'
import json, os, platform, statistics, subprocess, sys, datetime
runs_file, out, merge, steps = sys.argv[1], sys.argv[2], sys.argv[3] == "1", int(sys.argv[4])
work, problem = sys.argv[5], sys.argv[6]
runs = [json.loads(l) for l in open(runs_file) if l.strip()]
now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")
for r in runs:
    r["time"] = now
    r["steps"] = steps
if merge and os.path.exists(out):
    try:
        old = json.load(open(out)).get("runs", [])
        # a run with the same steps count is comparable; keep everything else as history
        runs = old + runs
    except Exception as e:
        print(f"[bench] could not merge {out}: {e}", file=sys.stderr)
for r in runs:  # runs recorded before the packing case existed
    r.setdefault("problem", "column")
    r.setdefault("law", "cohesive")

def cpu_model():
    try:
        for l in open("/proc/cpuinfo"):
            if l.startswith("model name"):
                return l.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()

def version(cmd):
    try:  # in a scratch directory: `liggghts -h` writes log.liggghts into the current one
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=20, cwd=work)
        for l in (p.stdout + p.stderr).splitlines():
            if l.strip():
                return l.strip()
    except Exception:
        return None

# A run is "contended" when other processes shared its CPUs: it got less than 85 % of the CPU
# time it could have used, or more than 0.5 CPU was busy just before it started. (Lowering the
# benchmark's nice value does not help on a kernel with autogroup scheduling: every session
# competes as one group.) Where the code reports its timed loop's wall time (LAMMPS, LIGGGHTS),
# the share is taken over the loop: process CPU / (threads x loop seconds), at most 1. Their
# processes sleep through about 2.7 s of MPI start-up (measured on an idle machine: process wall
# minus loop 2.7-2.8 s, process CPU minus loop 0.4 s), which the whole process's share counted as
# lost to other processes. The loop share includes the set-up's CPU, so it can miss a contention
# smaller than set-up CPU / loop time (about 0.4 s / loop seconds).
def judged_cpu_share(r):
    loop, cpu, t = r.get("loop_seconds"), r.get("process_cpu_seconds"), r.get("threads")
    if loop and cpu is not None and t:
        return min(1.0, cpu / (loop * t))
    return r.get("cpu_share")
def contended(r):
    share, busy = judged_cpu_share(r), r.get("busy_cpus_before")
    return (share is not None and share < 0.85) or (busy is not None and busy > 0.5)
for r in runs:
    r["contended"] = contended(r)
ok = [r for r in runs if r["status"] == "ok" and r["particle_steps_per_second"]]
groups = {}
for r in ok:
    groups.setdefault((r["problem"], r["law"], r["code"], r["variant"], r["n_requested"], r["threads"],
                       r["steps"]), []).append(r)
summary_all = []
for (prob, law, code, variant, n, t, st), rs_all in sorted(groups.items()):
    # the median is taken over the uncontended runs when there are any
    clean = [r for r in rs_all if not r["contended"]]
    rs = clean or rs_all
    v = [r["particle_steps_per_second"] for r in rs]
    c = [r["contacts"] for r in rs if r["contacts"] is not None]
    z = [2.0 * r["contacts"] / r["particles"] for r in rs if r["contacts"] is not None and r["particles"]]
    summary_all.append({"problem": prob, "law": law,
                        "code": code, "variant": variant, "n_requested": n, "threads": t,
                        "steps": st, "particles": rs[0]["particles"], "runs": len(v),
                        "contended": not clean, "runs_discarded_as_contended": len(rs_all) - len(v),
                        "median_particle_steps_per_second": statistics.median(v),
                        "min": min(v), "max": max(v),
                        "spread_percent": 100.0 * (max(v) - min(v)) / statistics.median(v),
                        "contacts_median": statistics.median(c) if c else None,
                        "contacts_per_sphere_median": statistics.median(z) if z else None,
                        "cpu_seconds_rate_median": statistics.median(
                            [r.get("particle_steps_per_cpu_second") for r in rs
                             if r.get("particle_steps_per_cpu_second")] or [0]) or None,
                        # the share the contention rule used (over the loop where known)
                        "cpu_share_median": statistics.median(
                            [judged_cpu_share(r) for r in rs if judged_cpu_share(r) is not None] or [0]),
                        "busy_cpus_before_median": statistics.median(
                            [r.get("busy_cpus_before") for r in rs
                             if r.get("busy_cpus_before") is not None] or [0])})
# best variant per (code, n, threads, steps): the one with the highest median
best = {}
for s in summary_all:
    k = (s["problem"], s["law"], s["code"], s["n_requested"], s["threads"], s["steps"])
    if k not in best or s["median_particle_steps_per_second"] > best[k]["median_particle_steps_per_second"]:
        best[k] = s
summary = [best[k] for k in sorted(best)]

# Paddy's speed over LAMMPS's and LIGGGHTS's (each code's best variant), ratio of the medians;
# "range" = the lowest and highest ratio of single runs (min/max and max/min).
ratios = []
for k in sorted({(s["problem"], s["law"], s["n_requested"], s["threads"], s["steps"]) for s in summary}):
    by = {s["code"]: s for s in summary
          if (s["problem"], s["law"], s["n_requested"], s["threads"], s["steps"]) == k}
    if "paddy" not in by:
        continue
    p = by["paddy"]
    row = {"problem": k[0], "law": k[1], "n_requested": k[2], "threads": k[3], "steps": k[4],
           "particles": p["particles"], "contended": p["contended"]}
    for other in ("lammps", "liggghts"):
        if other in by:
            o = by[other]
            row[f"paddy_over_{other}"] = p["median_particle_steps_per_second"] / o["median_particle_steps_per_second"]
            row[f"paddy_over_{other}_range"] = [p["min"] / o["max"], p["max"] / o["min"]]
            row["contended"] = row["contended"] or o["contended"]
            # one thread: also the ratio of particle-steps per CPU second (whole process, setup
            # included), much less sensitive to other processes sharing the cores
            if p["cpu_seconds_rate_median"] and o["cpu_seconds_rate_median"]:
                row[f"paddy_over_{other}_per_cpu_second"] = (p["cpu_seconds_rate_median"]
                                                             / o["cpu_seconds_rate_median"])
    ratios.append(row)

doc = {
    "benchmark": {"column": "cohesive column collapse",
                  "packing": "settled random packing released, cohesive and cohesionless"}[problem]
                 + " (bench/run.sh -p " + problem + ", docs/performance.md)",
    "generated": now,
    "metric": "particle_steps_per_second = particles x timed steps / wall seconds of the timed run",
    "host": {"cpu": cpu_model(), "logical_cpus": os.cpu_count(), "kernel": platform.release()},
    "versions": {"lammps": version(["sh", "-c", "lmp -h | sed -n 2p"]),
                 "liggghts": version(["sh", "-c", "liggghts -h | head -1"])},
    "summary": summary,
    "ratios": ratios,
    "summary_all_variants": summary_all,
    "runs": runs,
}
with open(out, "w") as f:
    json.dump(doc, f, indent=1)
    f.write("\n")

title = {"column": "Column collapse", "packing": "Settled packing released"}[problem]
now_rows = [s for s in summary if s["steps"] == steps and s["problem"] == problem]
print()
print(f"{title}, {steps} steps; particle-steps/s, median of repeats (min-max); "
      f"host {doc['host']['cpu']}, {doc['host']['logical_cpus']} CPUs. Medians use only runs with "
      f"the CPUs to themselves when there are any ('contended!' = none had). "
      f"Contacts/sphere = 2 x overlapping pairs / particles at the last step.")
print()
print("| law | code | variant | N | threads | M particle-steps/s | min-max | runs | contacts | contacts/sphere | busy CPUs before | CPU share | M p-steps per CPU-s |")
print("|---|---|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|")
for s in now_rows:
    print(f"| {s['law']} | {s['code']} | {s['variant']} | {s['particles']} | {s['threads']} | "
          f"{s['median_particle_steps_per_second']/1e6:.2f} | "
          f"{s['min']/1e6:.2f}-{s['max']/1e6:.2f} | {s['runs']}{' (contended!)' if s['contended'] else ''} | "
          f"{'' if s['contacts_median'] is None else int(s['contacts_median'])} | "
          f"{'' if s['contacts_per_sphere_median'] is None else format(s['contacts_per_sphere_median'], '.2f')} | "
          f"{s['busy_cpus_before_median']:.2f} | {s['cpu_share_median']:.2f} | "
          f"{'' if not s['cpu_seconds_rate_median'] else format(s['cpu_seconds_rate_median']/1e6, '.2f')} |")
now_ratios = [r for r in ratios if r["steps"] == steps and r["problem"] == problem]
if now_ratios:
    fmt = lambda r, o: (f"{r[f'paddy_over_{o}']:.2f} ({r[f'paddy_over_{o}_range'][0]:.2f}-"
                        f"{r[f'paddy_over_{o}_range'][1]:.2f})" if f"paddy_over_{o}" in r else "")
    print()
    print("Paddy / other code, ratio of medians (lowest-highest ratio of single runs):")
    print()
    cpu = lambda r, o: (f"{r[f'paddy_over_{o}_per_cpu_second']:.2f}"
                        if f"paddy_over_{o}_per_cpu_second" in r else "")
    print("| law | N | threads | Paddy / LAMMPS | Paddy / LIGGGHTS | per CPU-s: Paddy / LAMMPS | Paddy / LIGGGHTS |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for r in now_ratios:
        print(f"| {r['law']} | {r['particles']} | {r['threads']} | {fmt(r, 'lammps')} | {fmt(r, 'liggghts')} | "
              f"{cpu(r, 'lammps')} | {cpu(r, 'liggghts')} |" + (" contended!" if r["contended"] else ""))
others = [s for s in summary_all if s not in summary and s["steps"] == steps and s["problem"] == problem]
if others:
    print()
    print("Other variants (not the best of their code): " + "; ".join(
        f"{s['code']} {s['variant']} {s['law']} N={s['particles']} T={s['threads']}: "
        f"{s['median_particle_steps_per_second']/1e6:.2f} M" for s in others))
failed = [r for r in runs if r["status"] != "ok" and r["steps"] == steps and r["problem"] == problem]
if failed:
    print()
    print("Failed runs: " + "; ".join(f"{r['code']} {r['variant']} {r['law']} N={r['n_requested']} "
                                      f"T={r['threads']}: {r['note']}" for r in failed))
print()
print(f"written: {out}")
EOF
