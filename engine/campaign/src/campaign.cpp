// Campaign: job registry (keys, job.json, resume from result.json), choice of executor, and the
// split of cores between concurrent jobs.
#include "runner.hpp"

#include <paddy/io/atomic_file.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <thread>

namespace paddy::campaign {

namespace fs = std::filesystem;
using nlohmann::json;

const char* statusName(JobStatus status) {
  switch (status) {
    case JobStatus::Queued: return "queued";
    case JobStatus::Running: return "running";
    case JobStatus::Done: return "done";
    case JobStatus::Failed: return "failed";
  }
  return "unknown";
}

namespace {

// The paddy executable: the option, else this process when it is `paddy`, else $PADDY_EXECUTABLE.
std::string findPaddy(const std::string& configured) {
  if (!configured.empty()) return fs::absolute(configured).string();
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && self.filename() == "paddy") return self.string();
  if (const char* env = std::getenv("PADDY_EXECUTABLE"); env && *env) return fs::absolute(env).string();
  return "";
}

std::string nowText() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::tm tm{};
  gmtime_r(&t, &tm);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

Campaign::Campaign(CampaignOptions options) : options_(std::move(options)) {
  if (options_.dir.empty()) throw std::invalid_argument("campaign: dir must be given");
  if (options_.executor != "local" && options_.executor != "slurm")
    throw std::invalid_argument("campaign: executor must be \"local\" or \"slurm\", not \"" + options_.executor + "\"");
  if (options_.max_attempts < 1) options_.max_attempts = 1;
  options_.dir = fs::absolute(options_.dir).lexically_normal();
  options_.paddy_executable = findPaddy(options_.paddy_executable);
  fs::create_directories(options_.dir / "jobs");
  code_version_ = options_.code_version.empty() ? defaultCodeVersion(options_.paddy_executable) : options_.code_version;
}

Campaign::~Campaign() = default;

fs::path Campaign::jobDir(const std::string& key) const { return options_.dir / "jobs" / key; }

std::string Campaign::submit(const JobSpec& spec_in) {
  JobSpec spec = spec_in;
  if (spec.script.empty() && spec.command.empty()) throw std::invalid_argument("campaign: a job needs a script (or a command)");
  if (!spec.script.empty()) {
    std::error_code ec;
    if (!fs::is_regular_file(spec.script, ec)) throw std::invalid_argument("campaign: cannot read script '" + spec.script + "'");
    spec.script = fs::absolute(spec.script).lexically_normal().string();
  }
  const std::string material = keyMaterial(spec, code_version_, options_.module_path);
  const std::string key = sha256Hex(material);
  order_.push_back(key);
  if (jobs_.count(key)) return key;

  JobRecord rec;
  rec.key = key;
  rec.spec = spec;
  rec.dir = jobDir(key);
  fs::create_directories(rec.dir);
  if (detail::isComplete(rec.dir)) {
    rec.status = JobStatus::Done;
    rec.cached = true;
  }
  // job.json describes the job (for people and tools); it never marks the job done.
  if (!fs::exists(rec.dir / "job.json")) {
    json doc = {{"key", key},
                {"script", spec.script},
                {"params", spec.params},
                {"seed", spec.seed},
                {"code_version", code_version_},
                {"key_material", material},
                {"submitted", nowText()}};
    if (!spec.command.empty()) doc["command"] = spec.command;
    if (spec.threads) doc["threads"] = *spec.threads;
    io::writeFileAtomic(rec.dir / "job.json", doc.dump(2) + "\n");
  }
  jobs_.emplace(key, std::move(rec));
  return key;
}

void Campaign::runAll() {
  std::ostream& log = options_.log ? *options_.log : std::cerr;
  std::vector<JobRecord*> todo;
  int cached = 0;
  for (const auto& key : keys()) {
    JobRecord& job = jobs_.at(key);
    if (job.status == JobStatus::Done) {
      ++cached;
      continue;
    }
    if (detail::isComplete(job.dir)) {  // finished meanwhile (e.g. by another runner)
      job.status = JobStatus::Done;
      job.cached = true;
      ++cached;
      continue;
    }
    job.status = JobStatus::Queued;
    job.attempts = 0;
    job.error.clear();
    todo.push_back(&job);
  }
  if (options_.progress && cached > 0)
    log << "campaign: " << cached << " job(s) already done in " << options_.dir.string() << std::endl;
  if (todo.empty()) return;

  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int n = static_cast<int>(todo.size());
  detail::RunContext ctx{options_, todo, options_.paddy_executable, 1, 1, cached, log};
  if (options_.executor == "local") {
    int parallel = options_.max_parallel;
    if (parallel <= 0) parallel = options_.threads_per_job > 0 ? std::max(1, cores / options_.threads_per_job) : cores;
    ctx.max_parallel = std::max(1, std::min(parallel, n));
    ctx.threads_per_job = options_.threads_per_job > 0 ? options_.threads_per_job : std::max(1, cores / ctx.max_parallel);
  } else {
    ctx.max_parallel = std::max(0, options_.max_parallel);
    ctx.threads_per_job = options_.slurm.cpus_per_task > 0 ? options_.slurm.cpus_per_task
                                                           : std::max(1, options_.threads_per_job);
  }
  detail::SignalGuard signals;
  if (options_.executor == "local")
    detail::runLocal(ctx, signals);
  else
    detail::runSlurm(ctx, signals);
}

JobStatus Campaign::status(const std::string& key) const { return record(key).status; }

const JobRecord& Campaign::record(const std::string& key) const {
  auto it = jobs_.find(key);
  if (it == jobs_.end()) throw std::out_of_range("campaign: unknown job key '" + key + "'");
  return it->second;
}

json Campaign::result(const std::string& key) const {
  const JobRecord& job = record(key);
  if (job.status != JobStatus::Done)
    throw std::runtime_error("campaign: job " + key + " is " + statusName(job.status) +
                             (job.error.empty() ? std::string() : ": " + job.error));
  std::ifstream in(job.dir / "result.json");
  return json::parse(in);
}

std::vector<std::string> Campaign::keys() const {
  std::vector<std::string> out;
  for (const auto& k : order_)
    if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  return out;
}

}  // namespace paddy::campaign
