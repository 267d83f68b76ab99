// A warning for a simulation asked to run on more OpenMP threads than the machine has idle cores.
// OpenMP threads meet at a barrier after every parallel loop; when another process holds one of
// their cores, the others wait for it at each of the thousands of barriers per second, and a run
// measured here became 10-15 times slower (docs/experiments.md, "Run times"). One thread per
// run, several runs at once, uses a shared machine far better. Where the threads sleep instead
// of spinning while they wait (OMP_WAIT_POLICY=passive, read by the OpenMP runtime at start-up)
// the loss is far smaller: a 2-thread 40 mm slump on a loaded machine took 1.6-2.1 s instead of
// 109-168 s (docs/performance.md, bench/results/2026-12-03_omp_wait_policy_40mm.txt).
#pragma once

#include <optional>
#include <string>

namespace paddy::lua {

struct CpuLoad {
  double load1 = 0.0;  // 1-minute load average (runnable processes)
  int cpus = 1;        // CPUs this process may run on
};

// The machine's load now (getloadavg, sched_getaffinity); nullopt if it cannot be read.
std::optional<CpuLoad> currentCpuLoad();

// "" when `threads` fit the idle cores (cpus − load1, with half a core of slack), else a one-line
// warning that names the figures and the remedies (fewer threads; OMP_WAIT_POLICY=passive unless
// `passive_wait` says it is set already).
std::string contentionWarning(int threads, const CpuLoad& load, bool passive_wait = false);
// True when the environment asks the OpenMP runtime for passive waiting (OMP_WAIT_POLICY=passive,
// any case).
bool passiveWaitPolicy();

}  // namespace paddy::lua
