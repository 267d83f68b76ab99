// Campaign: runs many simulation jobs, locally in parallel or as a Slurm job array, and keeps
// their results under <dir>/jobs/<key>/ so that an interrupted campaign resumes without
// repeating finished runs.
//
//   paddy::campaign::Campaign c({.dir = "calib", .max_parallel = 2});
//   auto k = c.submit(JobSpec{.script = "slump.lua", .seed = 3}.set("restitution", 0.13));
//   c.runAll();                       // blocks; finished jobs are skipped, failures retried once
//   if (c.status(k) == JobStatus::Done) use(c.result(k)["results"]["slump"]);
//
// A job is done when <dir>/jobs/<key>/result.json exists with "status": "complete"; nothing
// else makes a job done. See docs/campaign.md.
#pragma once

#include <paddy/campaign/job.hpp>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <iosfwd>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace paddy::campaign {

enum class JobStatus { Queued, Running, Done, Failed };
const char* statusName(JobStatus status);  // "queued", "running", "done", "failed"

struct SlurmOptions {
  std::string partition;                // -p (empty: the cluster's default)
  std::string time;                     // --time, e.g. "00:30:00" (empty: partition default)
  int cpus_per_task = 0;                // --cpus-per-task (0: threads_per_job, else 1)
  std::vector<std::string> extra_args;  // more sbatch arguments, e.g. {"--mem=4G"}
  double poll_interval = 5.0;           // seconds between squeue polls
  std::string sbatch = "sbatch", squeue = "squeue", sacct = "sacct", scancel = "scancel";
};

struct CampaignOptions {
  std::filesystem::path dir;        // campaign directory (created); must be shared for Slurm
  std::string executor = "local";   // "local" or "slurm"
  int max_parallel = 0;             // jobs at once (0: local = cores / threads_per_job or cores;
                                    // slurm = no limit)
  int threads_per_job = 0;          // --threads of each job (0: cores / concurrent jobs)
  int max_attempts = 2;             // a failed run is retried once
  std::string paddy_executable;     // "" = this process if it is `paddy`, else $PADDY_EXECUTABLE
  std::string code_version;         // "" = defaultCodeVersion(paddy_executable)
  std::vector<std::filesystem::path> module_path;  // more directories for require() lookup
  bool progress = true;             // campaign progress on `log`
  double progress_interval = 10.0;  // seconds between progress lines while nothing changes
  double poll_interval = 0.05;      // local executor: seconds between child polls
  std::ostream* log = nullptr;      // progress and messages (nullptr = std::cerr)
  SlurmOptions slurm;
};

// Thrown by runAll() when SIGINT/SIGTERM arrived and the signal's previous handler returned.
struct Interrupted : std::runtime_error {
  explicit Interrupted(int sig) : std::runtime_error("campaign interrupted by signal " + std::to_string(sig)), signal(sig) {}
  int signal;
};

struct JobRecord {
  std::string key;
  JobSpec spec;
  std::filesystem::path dir;  // <campaign>/jobs/<key>
  JobStatus status = JobStatus::Queued;
  int attempts = 0;           // runs started by this Campaign object
  int exit_code = 0;          // of the last failed attempt
  std::string error;          // why it failed (from error.json, else exit status and stderr tail)
  double duration = 0.0;      // seconds of the last attempt (0 if not run here)
  bool cached = false;        // done before this Campaign ran it (resume)
};

class Campaign {
 public:
  explicit Campaign(CampaignOptions options);
  ~Campaign();
  Campaign(const Campaign&) = delete;
  Campaign& operator=(const Campaign&) = delete;

  // Registers a job and writes its job.json; returns its key. Submitting a job with the key of
  // an earlier one returns that key again (the run is shared).
  std::string submit(const JobSpec& spec);
  // Runs every submitted job that is not done; returns when each is done or failed. On SIGINT
  // or SIGTERM the children are killed, then the signal is re-raised with its earlier handler.
  void runAll();

  JobStatus status(const std::string& key) const;
  const JobRecord& record(const std::string& key) const;
  nlohmann::json result(const std::string& key) const;  // result.json; throws unless done
  std::vector<std::string> keys() const;                // distinct keys, in submission order
  const CampaignOptions& options() const { return options_; }
  const std::string& codeVersion() const { return code_version_; }
  std::filesystem::path jobDir(const std::string& key) const;

 private:
  CampaignOptions options_;
  std::string code_version_;
  std::vector<std::string> order_;
  std::map<std::string, JobRecord> jobs_;
};

}  // namespace paddy::campaign
