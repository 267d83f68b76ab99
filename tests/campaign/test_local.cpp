// Local executor with fake jobs (fake_job.hpp): parallel runs, retry-then-fail, resume after a
// SIGTERM of the runner, and re-running only the jobs a changed parameter affects.
#include "fake_job.hpp"

#include <paddy/campaign/campaign.hpp>

#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;
using namespace paddy::campaign;
using paddy::campaign::test::fakeJob;

namespace {

fs::path tempDir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("paddy_campaign_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  return d;
}

int executions(const fs::path& job_dir) {
  std::ifstream in(job_dir / "executions.log");
  int n = 0;
  for (std::string line; std::getline(in, line);) ++n;
  return n;
}

CampaignOptions options(const fs::path& dir, int parallel, std::ostream* log) {
  CampaignOptions o;
  o.dir = dir;
  o.max_parallel = parallel;
  o.code_version = "test";
  o.log = log;
  return o;
}

bool complete(const fs::path& job_dir) {
  std::ifstream in(job_dir / "result.json");
  if (!in) return false;
  try {
    return nlohmann::json::parse(in).value("status", "") == "complete";
  } catch (...) {
    return false;
  }
}

}  // namespace

TEST_CASE("campaign: jobs run in parallel, results in the campaign directory", "[campaign]") {
  const fs::path dir = tempDir("parallel");
  std::ostringstream log;
  Campaign c(options(dir, 2, &log));
  std::vector<std::string> keys;
  for (int i = 0; i < 4; ++i) keys.push_back(c.submit(fakeJob("job" + std::to_string(i), 0.6)));
  CHECK(c.submit(fakeJob("job0", 0.6)) == keys[0]);  // same job, same key: shared
  CHECK(c.keys().size() == 4);
  CHECK(c.status(keys[0]) == JobStatus::Queued);
  CHECK(fs::exists(dir / "jobs" / keys[0] / "job.json"));
  c.runAll();

  struct Span {
    double start, end;
  };
  std::vector<Span> spans;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    REQUIRE(c.status(keys[i]) == JobStatus::Done);
    const auto r = c.result(keys[i]);
    CHECK(r["results"]["x"] == "job" + std::to_string(i));
    CHECK(executions(c.jobDir(keys[i])) == 1);
    CHECK(fs::exists(c.jobDir(keys[i]) / "stdout.log"));
    CHECK(fs::exists(c.jobDir(keys[i]) / "stderr.log"));
    const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    CHECK(r["results"]["threads"].get<int>() == std::max(1, cores / 2));
    spans.push_back({r["results"]["start"].get<double>(), r["results"]["end"].get<double>()});
  }
  // Largest number of runs at the same time: 2 (never more than max_parallel).
  int most = 0;
  for (const auto& a : spans) {
    int at = 0;
    for (const auto& b : spans) at += (b.start <= a.start && a.start < b.end) ? 1 : 0;
    most = std::max(most, at);
  }
  CHECK(most == 2);
  CHECK(log.str().find("4/4 done") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("campaign: a failing job is retried once, then reported failed", "[campaign]") {
  const fs::path dir = tempDir("retry");
  std::ostringstream log;
  Campaign c(options(dir, 2, &log));
  const auto bad = c.submit(fakeJob("bad", 0.0, "always"));
  const auto flaky = c.submit(fakeJob("flaky", 0.0, "once"));
  const auto good = c.submit(fakeJob("good", 0.0));
  c.runAll();
  CHECK(c.status(good) == JobStatus::Done);
  CHECK(executions(c.jobDir(good)) == 1);
  CHECK(c.status(flaky) == JobStatus::Done);  // second attempt succeeded
  CHECK(executions(c.jobDir(flaky)) == 2);
  CHECK(c.result(flaky)["results"]["execution"] == 2);
  REQUIRE(c.status(bad) == JobStatus::Failed);
  CHECK(executions(c.jobDir(bad)) == 2);
  CHECK(c.record(bad).error == "fake failure 2");  // the message of the last attempt's error.json
  CHECK(c.record(bad).exit_code == 3);
  CHECK_FALSE(fs::exists(c.jobDir(bad) / "result.json"));
  CHECK(fs::exists(c.jobDir(bad) / "failed.json"));
  CHECK(fs::exists(c.jobDir(bad) / "attempt1.stderr.log"));
  CHECK_THROWS(c.result(bad));
  CHECK(log.str().find("failed after 2 attempts: fake failure 2") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("campaign: an attempt starts without the temporaries a killed attempt left", "[campaign]") {
  const fs::path dir = tempDir("leftovers");
  std::ostringstream log;
  Campaign c(options(dir, 1, &log));
  const auto key = c.submit(fakeJob("left", 0.0));
  const fs::path jd = c.jobDir(key);
  // What a process killed in the middle of its atomic writes leaves (<file>.tmp.<pid>), and a
  // stale error.json; beside them files of the job that are not temporaries.
  fs::create_directories(jd / "snapshots");
  for (const fs::path& p : {jd / "result.json.tmp.4242", jd / "snapshots" / "snap_000003.h5.tmp.17", jd / "error.json",
                           jd / "notes.tmp.txt", jd / "snapshots" / "keep.tmp."})
    std::ofstream(p) << "partial";
  c.runAll();
  REQUIRE(c.status(key) == JobStatus::Done);
  CHECK_FALSE(fs::exists(jd / "result.json.tmp.4242"));
  CHECK_FALSE(fs::exists(jd / "snapshots" / "snap_000003.h5.tmp.17"));
  CHECK_FALSE(fs::exists(jd / "error.json"));
  CHECK(fs::exists(jd / "notes.tmp.txt"));         // not of the form <name>.tmp.<digits>
  CHECK(fs::exists(jd / "snapshots" / "keep.tmp."));
  fs::remove_all(dir);
}

TEST_CASE("campaign: a job whose command cannot start is reported failed", "[campaign]") {
  const fs::path dir = tempDir("nostart");
  std::ostringstream log;
  Campaign c(options(dir, 1, &log));
  JobSpec spec;
  spec.command = {"/nonexistent/program"};
  const auto k = c.submit(spec);
  c.runAll();
  REQUIRE(c.status(k) == JobStatus::Failed);
  CHECK(c.record(k).error.find("exit status 127") != std::string::npos);
  fs::remove_all(dir);
}

TEST_CASE("campaign: a changed parameter re-runs only the job it affects", "[campaign]") {
  const fs::path dir = tempDir("changed");
  std::ostringstream log;
  std::vector<std::string> first;
  {
    Campaign c(options(dir, 2, &log));
    for (const char* x : {"a", "b", "c"}) first.push_back(c.submit(fakeJob(x, 0.0)));
    c.runAll();
    for (const auto& k : first) REQUIRE(c.status(k) == JobStatus::Done);
  }
  Campaign c(options(dir, 2, &log));
  const auto a = c.submit(fakeJob("a", 0.0));
  const auto b = c.submit(fakeJob("b", 0.0));
  const auto d = c.submit(fakeJob("d", 0.0));  // was "c"
  CHECK(a == first[0]);
  CHECK(b == first[1]);
  CHECK(d != first[2]);
  CHECK(c.status(a) == JobStatus::Done);  // known done before running
  CHECK(c.record(a).cached);
  c.runAll();
  CHECK(executions(c.jobDir(a)) == 1);
  CHECK(executions(c.jobDir(b)) == 1);
  CHECK(executions(c.jobDir(d)) == 1);
  CHECK(executions(dir / "jobs" / first[2]) == 1);
  CHECK(c.result(d)["results"]["x"] == "d");
  fs::remove_all(dir);
}

TEST_CASE("campaign: a campaign killed with SIGTERM resumes without repeating finished runs", "[campaign]") {
  const char* driver = PADDY_CAMPAIGN_DRIVER;
  const fs::path dir = tempDir("resume");
  const int n = 6;
  auto start = [&]() {
    const pid_t pid = fork();
    if (pid == 0) {
      const std::string d = dir.string();
      execl(driver, driver, d.c_str(), std::to_string(n).c_str(), "0.7", "--parallel", "2", static_cast<char*>(nullptr));
      _exit(127);
    }
    return pid;
  };
  auto countComplete = [&]() {
    int done = 0;
    std::error_code ec;
    if (!fs::exists(dir / "jobs")) return 0;
    for (const auto& e : fs::directory_iterator(dir / "jobs", ec)) done += complete(e.path()) ? 1 : 0;
    return done;
  };

  const pid_t pid = start();
  REQUIRE(pid > 0);
  // Wait until two runs finished and the next ones are under way, then kill the runner.
  const auto t0 = std::chrono::steady_clock::now();
  while (countComplete() < 2 && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(30))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  REQUIRE(kill(pid, SIGTERM) == 0);
  int status = 0;
  REQUIRE(waitpid(pid, &status, 0) == pid);
  CHECK(WIFSIGNALED(status));
  if (WIFSIGNALED(status)) CHECK(WTERMSIG(status) == SIGTERM);
  const int done_at_kill = countComplete();
  CHECK(done_at_kill >= 2);
  CHECK(done_at_kill < n);
  // The killed children are gone: nothing completes afterwards.
  std::this_thread::sleep_for(std::chrono::milliseconds(1200));
  CHECK(countComplete() == done_at_kill);

  std::vector<fs::path> finished_first;
  int started_first = 0;
  for (const auto& e : fs::directory_iterator(dir / "jobs")) {
    if (complete(e.path())) finished_first.push_back(e.path());
    started_first += executions(e.path()) > 0 ? 1 : 0;
  }
  CHECK(started_first > done_at_kill);  // some were killed mid-run

  const pid_t again = start();
  REQUIRE(waitpid(again, &status, 0) == again);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  CHECK(countComplete() == n);
  for (const auto& p : finished_first) CHECK(executions(p) == 1);  // finished runs ran once
  int total = 0;
  for (const auto& e : fs::directory_iterator(dir / "jobs")) total += executions(e.path());
  CHECK(total == n + (started_first - done_at_kill));  // only the killed runs ran again
  fs::remove_all(dir);
}
