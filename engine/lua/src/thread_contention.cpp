#include "thread_contention.hpp"

#include <sched.h>

#include <cstdio>
#include <cctype>
#include <cstdlib>
#include <string>

namespace paddy::lua {

std::optional<CpuLoad> currentCpuLoad() {
  double avg[1] = {0.0};
  if (getloadavg(avg, 1) != 1) return std::nullopt;
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) != 0) return std::nullopt;
  return CpuLoad{avg[0], CPU_COUNT(&set)};
}

bool passiveWaitPolicy() {
  const char* v = std::getenv("OMP_WAIT_POLICY");
  if (!v) return false;
  std::string s(v);
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s == "passive";
}

std::string contentionWarning(int threads, const CpuLoad& load, bool passive_wait) {
  if (threads <= 1) return "";
  const double idle = load.cpus - load.load1;
  if (threads <= idle + 0.5) return "";
  char msg[400];
  std::snprintf(msg, sizeof msg,
                "warning: %d threads, but the load average is %.1f on %d CPUs (about %.1f idle): OpenMP "
                "threads on busy cores wait for each other and the run may be many times slower; "
                "use --threads %d%s or run when the machine is free",
                threads, load.load1, load.cpus, idle > 0.0 ? idle : 0.0, idle >= 1.5 ? static_cast<int>(idle + 0.5) : 1,
                passive_wait ? "" : ", start paddy with OMP_WAIT_POLICY=passive (waiting threads then sleep),");
  return msg;
}

}  // namespace paddy::lua
