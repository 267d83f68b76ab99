// A stand-in for `paddy run` used by the campaign tests: a /bin/sh command that logs each
// execution (executions.log), sleeps PADDY_PARAM_sleep seconds, then either fails (writes
// error.json, exit 3) or writes result.json atomically with its start/end times and thread count.
//
// Parameters: sleep (seconds), x (copied to the result), fail ("always", "once" = only on the
// first execution, anything else = never).
#pragma once

#include <paddy/campaign/job.hpp>

#include <string>

namespace paddy::campaign::test {

inline const char* kFakeJobScript = R"sh(
set -u
cd "$PADDY_JOB_DIR"
echo "run $$" >> executions.log
n=$(wc -l < executions.log)
start=$(date +%s.%N)
sleep "${PADDY_PARAM_sleep:-0}"
end=$(date +%s.%N)
fail="${PADDY_PARAM_fail:-never}"
if [ "$fail" = always ] || { [ "$fail" = once ] && [ "$n" -eq 1 ]; }; then
  printf '{"status":"failed","error":"fake failure %s"}\n' "$n" > error.json.tmp && mv error.json.tmp error.json
  echo "fake job failed" >&2
  exit 3
fi
printf '{"status":"complete","results":{"x":"%s","start":%s,"end":%s,"threads":%s,"execution":%s}}\n' \
  "${PADDY_PARAM_x:-}" "$start" "$end" "$PADDY_JOB_THREADS" "$n" > result.json.tmp
mv result.json.tmp result.json
)sh";

inline JobSpec fakeJob(const std::string& x, double sleep_s, const std::string& fail = "never", std::uint64_t seed = 1) {
  JobSpec spec;
  spec.command = {"/bin/sh", "-c", kFakeJobScript};
  spec.seed = seed;
  spec.set("x", x).set("sleep", sleep_s).set("fail", fail);
  return spec;
}

}  // namespace paddy::campaign::test
