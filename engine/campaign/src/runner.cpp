// Helpers of the campaign executors: job command lines and environment, completion and failure
// records, progress lines, signal handling, and running a helper program (sbatch, squeue).
#include "runner.hpp"

#include <paddy/io/atomic_file.hpp>

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace paddy::campaign::detail {

namespace fs = std::filesystem;
using nlohmann::json;

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

int threadsFor(const RunContext& ctx, const JobRecord& job) {
  return std::max(1, job.spec.threads.value_or(ctx.threads_per_job));
}

std::vector<std::string> jobArgv(const RunContext& ctx, const JobRecord& job, int threads) {
  if (!job.spec.command.empty()) return job.spec.command;
  if (ctx.paddy_executable.empty())
    throw std::runtime_error("campaign: cannot find the paddy executable (set paddy_executable or PADDY_EXECUTABLE)");
  std::vector<std::string> argv{ctx.paddy_executable, "run", fs::absolute(job.spec.script).lexically_normal().string(),
                                "--out", job.dir.string(), "--threads", std::to_string(threads),
                                "--seed", std::to_string(job.spec.seed)};
  for (const auto& [name, value] : job.spec.params) {
    argv.push_back("--set");
    argv.push_back(name + "=" + value);
  }
  return argv;
}

std::vector<std::string> jobEnvironment(const JobRecord& job, int threads, int attempt) {
  std::vector<std::string> env{"PADDY_JOB_DIR=" + job.dir.string(), "PADDY_JOB_KEY=" + job.key,
                               "PADDY_JOB_THREADS=" + std::to_string(threads),
                               "PADDY_JOB_SEED=" + std::to_string(job.spec.seed),
                               "PADDY_JOB_ATTEMPT=" + std::to_string(attempt),
                               "OMP_NUM_THREADS=" + std::to_string(threads)};
  for (const auto& [name, value] : job.spec.params) env.push_back("PADDY_PARAM_" + name + "=" + value);
  return env;
}

bool isComplete(const fs::path& dir) {
  std::ifstream in(dir / "result.json");
  if (!in) return false;
  try {
    const json doc = json::parse(in);
    return doc.is_object() && doc.value("status", "") == "complete";
  } catch (const std::exception&) {
    return false;
  }
}

namespace {

std::string tail(const fs::path& path, std::size_t max_chars) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "";
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  if (s.size() > max_chars) {
    s.erase(0, s.size() - max_chars);
    s.insert(0, "...");
  }
  return s;
}

}  // namespace

void describeFailure(JobRecord& job, int exit_code, const std::string& how) {
  job.exit_code = exit_code;
  std::ifstream in(job.dir / "error.json");
  if (in) {
    try {
      const json doc = json::parse(in);
      if (doc.contains("error") && doc["error"].is_string()) {
        job.error = doc["error"].get<std::string>();
        return;
      }
    } catch (const std::exception&) {
    }
  }
  job.error = how;
  const std::string err = tail(job.dir / "stderr.log", 600);
  if (!err.empty()) job.error += ": " + err;
}

void writeFailedRecord(const JobRecord& job) {
  const json doc = {{"status", "failed"}, {"key", job.key},        {"error", job.error},
                    {"exit_code", job.exit_code}, {"attempts", job.attempts}};
  io::writeFileAtomic(job.dir / "failed.json", doc.dump(2) + "\n");
}

void clearFailedRecord(const JobRecord& job) {
  std::error_code ec;
  fs::remove(job.dir / "failed.json", ec);
}

void clearAttemptLeftovers(const JobRecord& job) {
  std::error_code ec;
  fs::remove(job.dir / "error.json", ec);  // an error.json must belong to this attempt
  io::removeTemporaries(job.dir);
}

void keepAttemptLogs(const JobRecord& job, int attempt) {
  std::error_code ec;
  for (const char* name : {"stdout.log", "stderr.log", "error.json"}) {
    const fs::path from = job.dir / name;
    if (fs::exists(from, ec)) fs::rename(from, job.dir / ("attempt" + std::to_string(attempt) + "." + name), ec);
  }
}

std::string shellQuote(const std::string& arg) {
  if (!arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=/.,:@%") == std::string::npos)
    return arg;
  std::string out = "'";
  for (char ch : arg) {
    if (ch == '\'')
      out += "'\\''";
    else
      out += ch;
  }
  return out + "'";
}

std::string shellJoin(const std::vector<std::string>& argv) {
  std::string out;
  for (const auto& a : argv) {
    if (!out.empty()) out += ' ';
    out += shellQuote(a);
  }
  return out;
}

// ---- progress ------------------------------------------------------------------------------

namespace {

std::string duration(double s) {
  char buf[32];
  const long t = static_cast<long>(s + 0.5);
  if (t >= 3600)
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t / 60) % 60);
  else if (t >= 60)
    std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  else
    std::snprintf(buf, sizeof buf, "%lds", t);
  return buf;
}

}  // namespace

Progress::Progress(std::ostream& log, bool enabled, double interval, int total, int already_done, int parallel)
    : log_(log), enabled_(enabled), interval_(interval), total_(total), cached_(already_done), parallel_(std::max(1, parallel)) {}

void Progress::finished(double seconds) {
  sum_ += seconds;
  ++count_;
}

void Progress::update(int done, int running, int failed, int queued, const std::vector<double>& running_elapsed, bool force) {
  if (!enabled_) return;
  std::ostringstream s;
  s << "campaign: " << (done + cached_) << "/" << total_ << " done";
  if (cached_) s << " (" << cached_ << " earlier)";
  s << ", " << running << " running, " << failed << " failed, " << queued << " queued";
  const std::string state = s.str();
  const bool changed = state != last_;
  if (!force && !changed && secondsSince(last_time_) < interval_) return;
  if (count_ > 0) {
    // Work left: the queued runs at the mean duration, plus what the running ones still need.
    const double mean = sum_ / count_;
    double left = queued * mean;
    for (double e : running_elapsed) left += std::max(0.0, mean - e);
    s << ", about " << duration(left / std::max(1, std::min(parallel_, running + queued))) << " left (mean run "
      << duration(mean) << ")";
  }
  log_ << s.str() << std::endl;
  last_ = state;
  last_time_ = std::chrono::steady_clock::now();
}

void Progress::final(int done, int failed) {
  if (!enabled_) return;
  log_ << "campaign: finished, " << (done + cached_) << "/" << total_ << " done, " << failed << " failed"
       << std::endl;
}

// ---- signals -------------------------------------------------------------------------------

namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void onSignal(int sig) { g_signal = sig; }

}  // namespace

SignalGuard::SignalGuard() {
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = 0;
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
}

SignalGuard::~SignalGuard() { restore(); }

void SignalGuard::restore() {
  if (restored_) return;
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  restored_ = true;
}

int SignalGuard::pending() const { return g_signal; }

void SignalGuard::rethrow() {
  const int sig = g_signal ? static_cast<int>(g_signal) : SIGTERM;
  restore();
  g_signal = 0;
  std::raise(sig);
  throw Interrupted(sig);  // the earlier handler returned
}

// ---- helper programs -----------------------------------------------------------------------

CommandOutput runCapture(const std::vector<std::string>& argv) {
  CommandOutput result;
  int out_pipe[2], err_pipe[2];
  if (pipe2(out_pipe, O_CLOEXEC) != 0) return result;
  if (pipe2(err_pipe, O_CLOEXEC) != 0) {
    close(out_pipe[0]);
    close(out_pipe[1]);
    return result;
  }
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    dup2(out_pipe[1], 1);
    dup2(err_pipe[1], 2);
    const int devnull = open("/dev/null", O_RDONLY);
    if (devnull >= 0) dup2(devnull, 0);
    execvp(args[0], args.data());
    const char msg[] = "cannot execute program\n";
    (void)!write(2, msg, sizeof msg - 1);
    _exit(127);
  }
  close(out_pipe[1]);
  close(err_pipe[1]);
  if (pid < 0) {
    close(out_pipe[0]);
    close(err_pipe[0]);
    result.err = std::strerror(errno);
    return result;
  }
  pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
  std::string* sinks[2] = {&result.out, &result.err};
  int open_fds = 2;
  char buf[4096];
  while (open_fds > 0) {
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < 2; ++i) {
      if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t n = read(fds[i].fd, buf, sizeof buf);
      if (n > 0) {
        sinks[i]->append(buf, static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        close(fds[i].fd);
        fds[i].fd = -1;
        --open_fds;
      }
    }
  }
  for (auto& f : fds)
    if (f.fd >= 0) close(f.fd);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return result;
}

}  // namespace paddy::campaign::detail
