// Internals of the campaign runner shared by the executors (private to engine/campaign/src):
// the command line of a job, completion checks, failure records, progress, signal handling.
#pragma once

#include <paddy/campaign/campaign.hpp>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace paddy::campaign::detail {

// What an executor needs to run a set of jobs.
struct RunContext {
  const CampaignOptions& options;
  std::vector<JobRecord*> jobs;    // the jobs to run (none done), in submission order
  std::string paddy_executable;    // resolved; may be empty if every job has a command
  int threads_per_job = 1;         // default --threads
  int max_parallel = 1;            // local: jobs at once; slurm: array throttle (0 = none)
  int already_done = 0;            // jobs of the campaign done before this run (progress)
  std::ostream& log;
};

// argv of one attempt: the spec's command, or `paddy run SCRIPT --out DIR --threads K --seed S
// --set name=value ...`.
std::vector<std::string> jobArgv(const RunContext& ctx, const JobRecord& job, int threads);
// Extra environment of the child ("NAME=value").
std::vector<std::string> jobEnvironment(const JobRecord& job, int threads, int attempt);
int threadsFor(const RunContext& ctx, const JobRecord& job);

// True when dir/result.json exists, parses, and has "status": "complete".
bool isComplete(const std::filesystem::path& dir);
// Fills job.error from error.json (else the exit status and the tail of stderr.log).
void describeFailure(JobRecord& job, int exit_code, const std::string& how);
// Writes/removes <jobdir>/failed.json (the runner's own record; never makes a job look done).
void writeFailedRecord(const JobRecord& job);
void clearFailedRecord(const JobRecord& job);
// Moves stdout.log/stderr.log of a failed attempt aside (attempt<N>.stdout.log ...).
void keepAttemptLogs(const JobRecord& job, int attempt);
// Before an attempt starts: removes what an earlier attempt, or a killed campaign's job, left in
// the job directory that must not be taken for this attempt's: error.json and the temporaries of
// interrupted atomic writes ("<file>.tmp.<pid>", paddy/io/atomic_file.hpp). No process writes to
// the directory then (the job is not running anywhere).
void clearAttemptLeftovers(const JobRecord& job);

// "a b 'c d'" for messages and batch scripts (POSIX shell single quoting).
std::string shellQuote(const std::string& arg);
std::string shellJoin(const std::vector<std::string>& argv);

// Campaign progress: done / running / failed / queued and the time left from the mean run time.
class Progress {
 public:
  Progress(std::ostream& log, bool enabled, double interval, int total, int already_done, int parallel);
  void update(int done, int running, int failed, int queued, const std::vector<double>& running_elapsed, bool force = false);
  void finished(double seconds);  // a run took `seconds`
  void final(int done, int failed);

 private:
  std::ostream& log_;
  bool enabled_;
  double interval_;
  int total_, cached_, parallel_;
  double sum_ = 0.0;
  int count_ = 0;
  std::string last_;
  std::chrono::steady_clock::time_point last_time_{};
};

// Installs SIGINT/SIGTERM handlers for the lifetime of the object; pending() tells which
// signal arrived (0 = none). rethrow() restores the old handlers and re-raises the signal;
// if the old handler returns, throws Interrupted.
class SignalGuard {
 public:
  SignalGuard();
  ~SignalGuard();
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;
  int pending() const;
  [[noreturn]] void rethrow();

 private:
  struct sigaction old_int_{}, old_term_{};
  bool restored_ = false;
  void restore();
};

// Runs a program to completion, capturing stdout (and stderr, appended) — for sbatch/squeue.
struct CommandOutput {
  int exit_code = -1;
  std::string out, err;
};
CommandOutput runCapture(const std::vector<std::string>& argv);

void runLocal(RunContext& ctx, SignalGuard& signals);
void runSlurm(RunContext& ctx, SignalGuard& signals);

double secondsSince(std::chrono::steady_clock::time_point t);

}  // namespace paddy::campaign::detail
