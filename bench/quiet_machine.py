"""bench/quiet_machine.py -- is the machine quiet enough to time something?

Shared by the timing harnesses of bench/ (campaign_layout.py, slump_phases.py): the CPUs busy with
other work, measured over one second from /proc/stat, and a wait of up to `max_wait` seconds for
them to fall below `limit` (0.5 CPU by default). A timing taken while more was busy, or whose
process got less than its share of the CPU, is flagged "contended" by the harness.
"""
import os, sys, time

LIMIT = 0.5  # busy CPUs above which the machine is not quiet


def cpu_times():
    with open("/proc/stat") as f:
        v = [int(x) for x in f.readline().split()[1:]]
    idle = v[3] + v[4]
    return sum(v), idle


def busy_cpus():
    """CPUs in use by other processes, measured over one second."""
    t0, i0 = cpu_times()
    time.sleep(1.0)
    t1, i1 = cpu_times()
    total = t1 - t0
    return 0.0 if total <= 0 else (1.0 - (i1 - i0) / total) * os.cpu_count()


def wait_for_quiet(max_wait, limit=LIMIT):
    """Busy CPUs after waiting up to max_wait seconds for them to fall to `limit` or below."""
    busy, waited = busy_cpus(), 0.0
    while waited < max_wait and busy > limit:
        time.sleep(4.0)
        waited += 5.0
        busy = busy_cpus()
    if waited > 0:
        print(f"  waited {waited:.0f} s for a quiet machine (busy CPUs now {busy:.2f})", file=sys.stderr)
    return busy
