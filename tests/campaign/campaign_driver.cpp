// Runs a small campaign of fake jobs (fake_job.hpp) in its own process, so tests can kill it
// mid-way (resume test) or run it through Slurm (slurm_local.sh).
//
//   campaign_driver DIR N SLEEP [--executor local|slurm] [--parallel P] [--fail-once K]
//                   [--fail-always K] [--partition NAME] [--poll S]
// Job i has x = "job<i>". Prints one line per job "<key> <status> <executions>" and exits 0
// when every job is done, 1 when some failed (the expected failures included), 2 on bad usage.
#include "fake_job.hpp"

#include <paddy/campaign/campaign.hpp>

#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  using namespace paddy::campaign;
  if (argc < 4) {
    std::cerr << "usage: campaign_driver DIR N SLEEP [options]\n";
    return 2;
  }
  CampaignOptions o;
  o.dir = argv[1];
  const int n = std::stoi(argv[2]);
  const double sleep_s = std::stod(argv[3]);
  int fail_once = -1, fail_always = -1;
  o.max_parallel = 2;
  o.progress_interval = 2.0;
  o.code_version = "test";
  o.slurm.poll_interval = 1.0;
  for (int i = 4; i + 1 < argc; i += 2) {
    const std::string opt = argv[i], val = argv[i + 1];
    if (opt == "--executor") o.executor = val;
    else if (opt == "--parallel") o.max_parallel = std::stoi(val);
    else if (opt == "--fail-once") fail_once = std::stoi(val);
    else if (opt == "--fail-always") fail_always = std::stoi(val);
    else if (opt == "--partition") o.slurm.partition = val;
    else if (opt == "--poll") o.slurm.poll_interval = std::stod(val);
    else {
      std::cerr << "unknown option " << opt << "\n";
      return 2;
    }
  }
  try {
    Campaign c(o);
    std::vector<std::string> keys;
    for (int i = 0; i < n; ++i) {
      const std::string fail = i == fail_once ? "once" : i == fail_always ? "always" : "never";
      keys.push_back(c.submit(test::fakeJob("job" + std::to_string(i), sleep_s, fail)));
    }
    c.runAll();
    bool all_done = true;
    for (const auto& k : keys) {
      std::ifstream log(c.jobDir(k) / "executions.log");
      int runs = 0;
      for (std::string line; std::getline(log, line);) ++runs;
      std::cout << k << " " << statusName(c.status(k)) << " " << runs;
      if (c.status(k) == JobStatus::Failed) std::cout << " error: " << c.record(k).error;
      std::cout << "\n";
      all_done = all_done && c.status(k) == JobStatus::Done;
    }
    return all_done ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "campaign_driver: " << e.what() << "\n";
    return 3;
  }
}
