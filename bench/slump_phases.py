#!/usr/bin/env python3
"""bench/slump_phases.py -- wall time per phase of the slump experiment (experiments/slump.lua).

Runs `paddy run bench/slump_phases.lua` (slump.lua unchanged, with a marker line on stderr around
every sim:run, strike-off and measurement call), timestamps the markers as they arrive and splits
the run into phases:
  setup          start of the process -> first sim:run (materials, cone, poured fill placement)
  settle         the first sim:run: the pour falls and settles inside the fixed cone
  strike_off     strike-off, fill-structure measurement, initial slump (between the two runs)
  lift_and_rest  the second sim:run: cone lift and the pile coming to rest
  final          after the last run: slump, slump-flow image, profile, pictures, result.json
Inside the two runs the time spent in measurement callbacks (measure_slump, measure_slump_flow)
is reported separately ("callbacks_in_runs"). The thread counts are interleaved (repeat, threads)
so that load from other users spreads over all of them; medians and ranges are printed.

Variants (-V NAME=ARGS, repeatable) time several settings of the same binary in one interleaved
run (repeat, variant, threads; the variants' order reversed every other repeat), e.g. a rule on and
off. Before each run the CPUs busy with other work are measured (bench/quiet_machine.py) and the
run waits up to -w seconds for a quiet machine; a run is flagged "contended" when more than 0.5 CPU
was busy before it or it got less than 85 % of the CPU its threads could use, and the medians are
taken over the uncontended runs when there are any.

Usage (from the repository root):
  bench/slump_phases.py [-t "1 2"] [-r 3] [-w 60] [-o bench/results/slump_phases.json] [-b build/bin/paddy]
                        [-V "old=--set free_rest_window=0" -V "new="]
                        [-V "before=--binary /path/old/paddy" -V "after="]   (a variant may run another build)
                        [-- --set name=value ...]   (slump.lua's parameters for every run, e.g. max_time)
"""
import argparse, json, os, resource, shlex, statistics, subprocess, sys, tempfile, time, datetime, platform

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import quiet_machine  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("-t", "--threads", default="1 2")
ap.add_argument("-r", "--repeats", type=int, default=3)
ap.add_argument("-o", "--out", default="bench/results/slump_phases.json")
ap.add_argument("-b", "--binary", default=os.environ.get("PADDY_BIN", "build/bin/paddy"))
ap.add_argument("--label", default="", help="free text stored with the runs (e.g. the commit)")
ap.add_argument("-w", "--wait", type=float, default=0, help="wait up to this many seconds for a quiet machine before each run")
ap.add_argument("-V", "--variant", action="append", default=[],
                help="NAME=ARGS: a variant timed in the same interleaved run (ARGS: more paddy run arguments)")
ap.add_argument("extra", nargs="*", help="arguments passed to paddy run after --")
a = ap.parse_args()

PHASES = ["setup", "settle", "strike_off", "lift_and_rest", "final"]


def variants():
    out = []
    for v in a.variant:
        name, sep, args = v.partition("=")
        if not sep or not name.strip():
            raise SystemExit(f"--variant: '{v}' is not NAME=ARGS (e.g. old=--set free_rest_window=0)")
        if name in [known for known, _, _ in out]:
            raise SystemExit(f"--variant: '{name}' given twice")
        args = shlex.split(args)
        binary = a.binary
        if args[:1] == ["--binary"]:  # a variant may run another build: NAME=--binary PATH ARGS
            if len(args) < 2:
                raise SystemExit(f"--variant: '{v}': --binary needs a path")
            binary, args = args[1], args[2:]
            if not os.access(binary, os.X_OK):
                raise SystemExit(f"--variant: '{v}': {binary} is not an executable file")
        out.append((name.strip(), args, binary))
    return out or [("", [], a.binary)]


def one_run(threads, rep, variant):
    out = tempfile.mkdtemp(prefix=f"slump_t{threads}_r{rep}_")
    cmd = [variant[2], "run", "bench/slump_phases.lua", "--threads", str(threads), "--out", out,
           "--set", "progress=false"] + a.extra + variant[1]
    busy = quiet_machine.wait_for_quiet(a.wait)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    p = subprocess.Popen(cmd, stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True)
    marks, depth = [], 0  # (time, begin/end, name, depth, cpu seconds of the process so far)
    tick = os.sysconf("SC_CLK_TCK")
    def cpu_now():  # user + system CPU seconds of paddy so far, all threads (/proc/PID/stat)
        try:
            f = open(f"/proc/{p.pid}/stat").read().rsplit(")", 1)[1].split()
            return (int(f[11]) + int(f[12])) / tick
        except (OSError, IndexError, ValueError):
            return None
    for line in p.stderr:
        now = time.monotonic() - t0
        parts = line.split()
        if len(parts) == 3 and parts[0] == "PHASE":
            if parts[1] == "end":
                depth -= 1
            marks.append((now, parts[1], parts[2], depth, cpu_now()))
            if parts[1] == "begin":
                depth += 1
        elif line.strip():
            sys.stderr.write("  | " + line)
    rc = p.wait()
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    if rc != 0:
        raise SystemExit(f"paddy failed (exit {rc}): {' '.join(cmd)}")
    run_spans, cpu_spans = [], []
    for k, m in enumerate(marks):
        if m[2] == "run" and m[1] == "begin" and m[3] == 0:
            end = next(e for e in marks[k + 1:] if e[2] == "run" and e[1] == "end" and e[3] == 0)
            run_spans.append((m[0], end[0]))
            cpu_spans.append((m[4], end[4]))
    if len(run_spans) != 2:
        raise SystemExit(f"expected 2 top-level sim:run calls, found {len(run_spans)}")
    (s0, s1), (l0, l1) = run_spans
    (c0, c1), (d0, d1) = cpu_spans
    nested = 0.0
    open_at = None
    for m in marks:
        if m[3] == 1 and m[2].startswith("measure"):
            if m[1] == "begin":
                open_at = m[0]
            elif open_at is not None:
                nested += m[0] - open_at
                open_at = None
    res = json.load(open(os.path.join(out, "result.json")))
    meta = res.get("metadata", res)
    phases = {"setup": s0, "settle": s1 - s0, "strike_off": l0 - s1, "lift_and_rest": l1 - l0, "final": wall - l1}
    # CPU seconds per phase (all threads): far less sensitive than wall time to other users of the
    # machine. "final" runs to the end of the process (gnuplot, a child of paddy, is not counted).
    cpu_phases = None
    if None not in (c0, c1, d0, d1):
        cpu_phases = {"setup": c0, "settle": c1 - c0, "strike_off": d0 - c1, "lift_and_rest": d1 - d0, "final": cpu - d1}
    def find(obj, key):
        if isinstance(obj, dict):
            if key in obj:
                return obj[key]
            for v in obj.values():
                r = find(v, key)
                if r is not None:
                    return r
        return None
    share = cpu / (wall * min(threads, os.cpu_count()))
    return {"variant": variant[0], "variant_args": variant[1], "binary": variant[2], "threads": threads, "repeat": rep,
            "busy_cpus_before": busy, "contended": busy > quiet_machine.LIMIT or share < 0.85,
            "wall_s": wall, "cpu_s": cpu, "cpu_share": share,
            "phases_s": phases, "cpu_phases_s": cpu_phases, "callbacks_in_runs_s": nested,
            "particles": find(res, "particles"), "steps": find(res, "steps"),
            "simulated_time_s": find(res, "simulated_time"), "run_wall_time_s": find(res, "run_wall_time"),
            "particle_steps_per_second": find(res, "particle_steps_per_second"),
            "final_state_hash": find(res, "final_state_hash"),
            "slump_mm": find(res, "slump_mm"), "slump_flow_mm": find(res, "slump_flow_mm"),
            "settle_time_s": find(res, "settle_time_s"), "rest_time_s": find(res, "rest_time_s"),
            "load_before": os.getloadavg()[0], "out": out}


def main():
    threads = [int(t) for t in a.threads.split()]
    vs = variants()
    runs = []
    for rep in range(1, a.repeats + 1):
        for v in (vs if rep % 2 == 1 else vs[::-1]):
            for t in threads:
                print(f"[slump_phases] {('variant=' + v[0] + ' ') if v[0] else ''}threads={t} repeat={rep}",
                      file=sys.stderr, flush=True)
                r = one_run(t, rep, v)
                runs.append(r)
                print(f"[slump_phases]   wall {r['wall_s']:.1f} s, cpu share {r['cpu_share']:.2f}, busy before "
                      f"{r['busy_cpus_before']:.2f}{' CONTENDED' if r['contended'] else ''}, "
                      + ", ".join(f"{k} {v:.1f}" for k, v in r["phases_s"].items()), file=sys.stderr, flush=True)
    summary = []
    for vname, t in [(v[0], t) for v in vs for t in threads]:
        group = [r for r in runs if r["threads"] == t and r["variant"] == vname]
        rs = [r for r in group if not r["contended"]] or group
        def stat(vals):
            return {"median": statistics.median(vals), "min": min(vals), "max": max(vals)}
        summary.append({"variant": vname, "threads": t, "runs": len(rs), "contended_left_out": len(group) - len(rs),
                        "wall_s": stat([r["wall_s"] for r in rs]),
                        "phases_s": {p: stat([r["phases_s"][p] for r in rs]) for p in PHASES},
                        "cpu_phases_s": {p: stat([r["cpu_phases_s"][p] for r in rs if r["cpu_phases_s"]] or [float("nan")])
                                         for p in PHASES},
                        "cpu_s": stat([r["cpu_s"] for r in rs]),
                        "callbacks_in_runs_s": stat([r["callbacks_in_runs_s"] for r in rs]),
                        "particle_steps_per_second": stat([r["particle_steps_per_second"] for r in rs]),
                        "cpu_share": stat([r["cpu_share"] for r in rs]),
                        "simulated_time_s": stat([r["simulated_time_s"] for r in rs]),
                        "slump_mm": sorted({r["slump_mm"] for r in rs}),
                        "slump_flow_mm": sorted({r["slump_flow_mm"] for r in rs}),
                        "state_hashes": sorted({r["final_state_hash"] for r in rs})})
    doc = {"benchmark": "slump experiment, wall time per phase (bench/slump_phases.py)",
           "generated": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ"),
           "label": a.label, "arguments": a.extra, "variants": [{"name": n, "arguments": v, "binary": b} for n, v, b in vs],
           "wait_s": a.wait, "host": {"logical_cpus": os.cpu_count(), "kernel": platform.release()},
           "summary": summary, "runs": runs}
    os.makedirs(os.path.dirname(a.out) or ".", exist_ok=True)
    json.dump(doc, open(a.out, "w"), indent=1)
    print("| variant | threads | runs | wall s (min-max) | " + " | ".join(PHASES) + " | callbacks in runs | M particle-steps/s |")
    print("|---|---:|---:|---|" + "---:|" * (len(PHASES) + 2))
    for s in summary:
        f = lambda st: f"{st['median']:.1f} ({st['min']:.1f}-{st['max']:.1f})"
        print(f"| {s['variant']} | {s['threads']} | {s['runs']} | {f(s['wall_s'])} | " + " | ".join(f(s["phases_s"][p]) for p in PHASES)
              + f" | {f(s['callbacks_in_runs_s'])} | {s['particle_steps_per_second']['median']/1e6:.3f} |")
    print()
    print("CPU seconds (all threads) per phase, median (min-max):")
    print("| variant | threads | cpu s | " + " | ".join(PHASES) + " |")
    print("|---|---:|---|" + "---:|" * len(PHASES))
    for s in summary:
        f = lambda st: f"{st['median']:.1f} ({st['min']:.1f}-{st['max']:.1f})"
        print(f"| {s['variant']} | {s['threads']} | {f(s['cpu_s'])} | " + " | ".join(f(s["cpu_phases_s"][p]) for p in PHASES) + " |")
    print(f"written: {a.out}")


main()
