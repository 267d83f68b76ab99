#!/usr/bin/env python3
"""bench/campaign_layout.py -- which campaign layout (runs at once x threads per run) finishes a
batch of slump runs soonest on this machine.

A calibration is batches of independent slump runs; a campaign runs them `max_parallel` at a time
with `threads_per_job` threads each (docs/campaign.md: by default cores / threads_per_job runs of
one thread). This times the same batch (bench/campaign_layout.lua: `jobs` runs of the main job's
experiment, seeds 1..jobs, pictures and snapshots off) under each layout, interleaved
(repeat, layout; the order reversed every other repeat) so that load from other users spreads over
all of them. Before each batch it measures the CPUs busy with other work over one second
(/proc/stat) and waits up to -w seconds for a quiet machine; a batch is flagged "contended" when
more than 0.5 CPU was busy before it or its processes got less than 85 % of the CPU time the layout
could use. Medians (over the uncontended batches when there are any) and ranges are printed and
written with every batch to the JSON file.

Usage (from the repository root):
  bench/campaign_layout.py [-l "2x1 1x2"] [-j 4] [-r 3] [-w 60] [-d 0.01]
                           [-o bench/results/campaign_layout.json] [-b build/bin/paddy]
"""
import argparse, datetime, json, os, platform, resource, statistics, subprocess, sys, tempfile, time, glob, shutil

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import quiet_machine  # noqa: E402

ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
ap.add_argument("-l", "--layouts", default="2x1 1x2", help="layouts 'RUNSxTHREADS', space separated")
ap.add_argument("-j", "--jobs", type=int, default=4, help="slump runs per batch")
ap.add_argument("-r", "--repeats", type=int, default=3)
ap.add_argument("-w", "--wait", type=float, default=0, help="wait up to this many seconds for a quiet machine")
ap.add_argument("-d", "--diameter", type=float, default=0.01, help="particle diameter [m]")
ap.add_argument("-o", "--out", default="bench/results/campaign_layout.json")
ap.add_argument("-b", "--binary", default=os.environ.get("PADDY_BIN", "build/bin/paddy"))
ap.add_argument("--label", default="", help="free text stored with the batches (e.g. the commit)")
a = ap.parse_args()


def layouts():
    out = []
    for word in a.layouts.split():
        try:
            runs, threads = (int(x) for x in word.lower().split("x"))
        except ValueError:
            raise SystemExit(f"--layouts: '{word}' is not RUNSxTHREADS (e.g. 2x1)")
        if runs < 1 or threads < 1:
            raise SystemExit(f"--layouts: '{word}': both numbers must be at least 1")
        out.append((runs, threads))
    if not out:
        raise SystemExit("--layouts is empty")
    return out


def quiet_check():
    return quiet_machine.wait_for_quiet(a.wait)


def one_batch(runs, threads, rep):
    out = tempfile.mkdtemp(prefix=f"layout_{runs}x{threads}_r{rep}_")
    cmd = [a.binary, "run", "bench/campaign_layout.lua", "--out", out, "--set", f"jobs={a.jobs}",
           "--set", f"max_parallel={runs}", "--set", f"threads_per_job={threads}",
           "--set", f"particle_diameter={a.diameter}"]
    busy = quiet_check()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    p = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    wall = time.monotonic() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        sys.stderr.write(p.stderr)
        raise SystemExit(f"paddy failed (exit {p.returncode}): {' '.join(cmd)}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    usable = min(runs * threads, os.cpu_count()) * wall
    jobs = []
    for f in sorted(glob.glob(os.path.join(out, "campaign", "jobs", "*", "result.json"))):
        with open(f) as fh:
            doc = json.load(fh)
        md, res = doc.get("metadata", {}), doc.get("results", {})
        jobs.append({"seed": md.get("seed"), "threads": md.get("threads"), "wall_time": md.get("wall_time"),
                     "particles": md.get("particles"), "slump_mm": res.get("slump_mm"),
                     "slump_flow_mm": res.get("slump_flow_mm")})
    if len(jobs) != a.jobs:
        raise SystemExit(f"expected {a.jobs} job results in {out}/campaign/jobs, found {len(jobs)}")
    shutil.rmtree(out, ignore_errors=True)
    share = cpu / usable if usable > 0 else None
    return {"layout": f"{runs}x{threads}", "max_parallel": runs, "threads_per_job": threads, "repeat": rep,
            "wall_s": wall, "cpu_s": cpu, "cpu_share": share, "busy_cpus_before": busy,
            "contended": busy > quiet_machine.LIMIT or (share is not None and share < 0.85),
            "jobs_per_hour": a.jobs / wall * 3600.0, "jobs": jobs}


def main():
    lays = layouts()
    batches = []
    for rep in range(a.repeats):
        order = lays if rep % 2 == 0 else list(reversed(lays))
        for runs, threads in order:
            print(f"repeat {rep + 1}/{a.repeats}: {a.jobs} runs as {runs} at once x {threads} thread(s)", file=sys.stderr)
            b = one_batch(runs, threads, rep)
            print(f"  {b['wall_s']:.1f} s wall, {b['cpu_s']:.1f} CPU s, busy before {b['busy_cpus_before']:.2f}"
                  f"{' (contended)' if b['contended'] else ''}", file=sys.stderr)
            batches.append(b)
    summary = []
    for runs, threads in lays:
        name = f"{runs}x{threads}"
        all_b = [b for b in batches if b["layout"] == name]
        clean = [b for b in all_b if not b["contended"]]
        use = clean or all_b
        walls = [b["wall_s"] for b in use]
        summary.append({"layout": name, "max_parallel": runs, "threads_per_job": threads, "batches": len(all_b),
                        "uncontended": len(clean), "median_wall_s": statistics.median(walls),
                        "min_wall_s": min(walls), "max_wall_s": max(walls),
                        "median_jobs_per_hour": a.jobs / statistics.median(walls) * 3600.0,
                        "median_job_wall_s": statistics.median([j["wall_time"] for b in use for j in b["jobs"]])})
    best = min(summary, key=lambda s: s["median_wall_s"])
    for s in summary:
        s["relative_to_fastest"] = s["median_wall_s"] / best["median_wall_s"]
    doc = {"tool": "bench/campaign_layout.py", "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
           "label": a.label, "machine": {"cpus": os.cpu_count(), "platform": platform.platform()},
           "jobs_per_batch": a.jobs, "particle_diameter": a.diameter, "repeats": a.repeats,
           "fastest": best["layout"], "summary": summary, "batches": batches}
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    tmp = a.out + ".tmp"
    with open(tmp, "w") as f:
        json.dump(doc, f, indent=1)
    os.replace(tmp, a.out)
    print(f"{'layout':>7} {'batches':>7} {'clean':>5} {'median s':>9} {'range s':>15} {'runs/h':>7} {'run s':>6} {'x fastest':>9}")
    for s in summary:
        print(f"{s['layout']:>7} {s['batches']:>7} {s['uncontended']:>5} {s['median_wall_s']:9.1f} "
              f"{s['min_wall_s']:7.1f}-{s['max_wall_s']:<7.1f} {s['median_jobs_per_hour']:7.1f} "
              f"{s['median_job_wall_s']:6.1f} {s['relative_to_fastest']:9.3f}")
    print(f"fastest: {best['layout']} (written to {a.out})")


main()
