// Local executor: up to max_parallel child processes at once, each `paddy run ... --threads k`
// in its own process group with stdout/stderr in the job directory. A signal to the runner
// (SIGINT/SIGTERM) kills every child group before the runner itself stops; children also get
// SIGTERM if the runner dies (PR_SET_PDEATHSIG).
#include "runner.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <deque>
#include <thread>

extern char** environ;

namespace paddy::campaign::detail {

namespace fs = std::filesystem;

namespace {

struct Child {
  JobRecord* job;
  pid_t pid;
  std::chrono::steady_clock::time_point start;
  int attempt;
};

// Starts the job's process; returns its pid, or -1 with `error` set.
pid_t spawnJob(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env, const fs::path& dir,
               std::string& error) {
  const int out = open((dir / "stdout.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int err = open((dir / "stderr.log").c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (out < 0 || err < 0) {
    error = "cannot open the log files in " + dir.string() + ": " + std::strerror(errno);
    if (out >= 0) close(out);
    if (err >= 0) close(err);
    return -1;
  }
  // Everything the child needs is prepared before fork (only async-signal-safe calls after it).
  std::vector<std::string> env_store;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('='));
    bool overridden = false;
    for (const auto& x : extra_env) overridden = overridden || x.compare(0, name.size() + 1, name + "=") == 0;
    if (!overridden) env_store.push_back(entry);
  }
  env_store.insert(env_store.end(), extra_env.begin(), extra_env.end());
  std::vector<char*> envp, args;
  for (auto& e : env_store) envp.push_back(e.data());
  envp.push_back(nullptr);
  std::vector<std::string> argv_store(argv);
  for (auto& a : argv_store) args.push_back(a.data());
  args.push_back(nullptr);
  const std::string cwd = dir.string();
  const pid_t parent = getpid();

  const pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(128 + SIGTERM);  // the runner is already gone
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(SIGINT, &dfl, nullptr);
    sigaction(SIGTERM, &dfl, nullptr);
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    const int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, 0);
    dup2(out, 1);
    dup2(err, 2);
    if (chdir(cwd.c_str()) != 0) _exit(126);
    execvpe(args[0], args.data(), envp.data());
    const char msg[] = "campaign: cannot execute the job command\n";
    (void)!write(2, msg, sizeof msg - 1);
    _exit(127);
  }
  close(out);
  close(err);
  if (pid < 0) {
    error = std::string("fork failed: ") + std::strerror(errno);
    return -1;
  }
  setpgid(pid, pid);  // also here, so a kill right after fork reaches the group
  return pid;
}

// Ends every child: SIGTERM to each group, SIGKILL to those still alive after `grace` seconds.
void killAll(std::vector<Child>& running, double grace) {
  for (const Child& c : running) kill(-c.pid, SIGTERM);
  const auto start = std::chrono::steady_clock::now();
  std::vector<bool> reaped(running.size(), false);
  std::size_t left = running.size();
  while (left > 0) {
    for (std::size_t i = 0; i < running.size(); ++i) {
      if (reaped[i]) continue;
      int status = 0;
      if (waitpid(running[i].pid, &status, WNOHANG) == running[i].pid) {
        reaped[i] = true;
        --left;
        kill(-running[i].pid, SIGKILL);  // grandchildren the job left behind
      }
    }
    if (left == 0) break;
    if (secondsSince(start) > grace) {
      for (std::size_t i = 0; i < running.size(); ++i)
        if (!reaped[i]) kill(-running[i].pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  running.clear();
}

std::string exitText(int status) {
  if (WIFEXITED(status)) return "exit status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return std::string("killed by signal ") + std::to_string(WTERMSIG(status));
  return "ended abnormally";
}

}  // namespace

void runLocal(RunContext& ctx, SignalGuard& signals) {
  const CampaignOptions& opt = ctx.options;
  std::deque<JobRecord*> queue(ctx.jobs.begin(), ctx.jobs.end());
  std::vector<Child> running;
  int done = 0, failed = 0;
  const int total = static_cast<int>(ctx.jobs.size()) + ctx.already_done;
  Progress progress(ctx.log, opt.progress, opt.progress_interval, total, ctx.already_done, ctx.max_parallel);

  auto finish = [&](JobRecord& job, int attempt, bool complete, int code, const std::string& how) {
    if (complete) {
      job.status = JobStatus::Done;
      job.error.clear();
      clearFailedRecord(job);
      progress.finished(job.duration);
      ++done;
      return;
    }
    describeFailure(job, code, how);
    if (job.attempts < opt.max_attempts) {
      ctx.log << "campaign: job " << job.key.substr(0, 12) << " failed (attempt " << attempt << "): " << job.error
              << "; retrying" << std::endl;
      keepAttemptLogs(job, attempt);
      job.status = JobStatus::Queued;
      queue.push_front(&job);
    } else {
      job.status = JobStatus::Failed;
      writeFailedRecord(job);
      ctx.log << "campaign: job " << job.key.substr(0, 12) << " failed after " << job.attempts
              << " attempts: " << job.error << std::endl;
      ++failed;
    }
  };

  while (!queue.empty() || !running.empty()) {
    if (signals.pending()) {
      ctx.log << "campaign: interrupted, stopping " << running.size() << " running job(s)" << std::endl;
      for (Child& c : running) c.job->status = JobStatus::Queued;
      killAll(running, 5.0);
      signals.rethrow();
    }
    for (std::size_t i = 0; i < running.size();) {
      int status = 0;
      const pid_t r = waitpid(running[i].pid, &status, WNOHANG);
      if (r != running[i].pid) {
        ++i;
        continue;
      }
      Child c = running[i];
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
      kill(-c.pid, SIGKILL);  // nothing of a finished job may linger
      c.job->duration = secondsSince(c.start);
      const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
      finish(*c.job, c.attempt, isComplete(c.job->dir), code, "job command " + exitText(status) + " without a complete result.json");
    }
    while (static_cast<int>(running.size()) < ctx.max_parallel && !queue.empty()) {
      JobRecord& job = *queue.front();
      queue.pop_front();
      const int threads = threadsFor(ctx, job);
      const int attempt = ++job.attempts;
      clearAttemptLeftovers(job);
      std::string error;
      pid_t pid = -1;
      try {
        pid = spawnJob(jobArgv(ctx, job, threads), jobEnvironment(job, threads, attempt), job.dir, error);
      } catch (const std::exception& e) {
        error = e.what();
      }
      if (pid < 0) {
        job.attempts = opt.max_attempts;  // cannot start: retrying would not help
        finish(job, attempt, false, -1, error);
        continue;
      }
      job.status = JobStatus::Running;
      running.push_back({&job, pid, std::chrono::steady_clock::now(), attempt});
    }
    std::vector<double> elapsed;
    for (const Child& c : running) elapsed.push_back(secondsSince(c.start));
    progress.update(done, static_cast<int>(running.size()), failed, static_cast<int>(queue.size()), elapsed);
    if (!running.empty()) std::this_thread::sleep_for(std::chrono::duration<double>(opt.poll_interval));
  }
  progress.final(done, failed);
}

}  // namespace paddy::campaign::detail
