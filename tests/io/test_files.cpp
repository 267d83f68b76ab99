// Atomic files and the progress line format.
#include <paddy/io/atomic_file.hpp>
#include <paddy/io/progress.hpp>
#include <paddy/io/snapshot.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <csignal>
#include <cstdlib>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

TEST_CASE("io: atomic write replaces the file and leaves no temporary", "[io]") {
  const fs::path dir = fs::temp_directory_path() / ("paddy_io_files_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  paddy::io::writeFileAtomic(dir / "sub" / "a.json", "first");
  paddy::io::writeFileAtomic(dir / "sub" / "a.json", "second");
  std::ifstream in(dir / "sub" / "a.json");
  std::stringstream s;
  s << in.rdbuf();
  CHECK(s.str() == "second");
  CHECK(std::distance(fs::directory_iterator(dir / "sub"), fs::directory_iterator()) == 1);

  // A failing producer leaves neither the target nor a temporary.
  CHECK_THROWS(paddy::io::produceFileAtomic(dir / "b.h5", [](const fs::path& tmp) {
    std::ofstream(tmp) << "partial";
    throw std::runtime_error("failed half way");
  }));
  CHECK_FALSE(fs::exists(dir / "b.h5"));
  CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1);  // only sub/
  fs::remove_all(dir);
}

TEST_CASE("io: the temporaries of interrupted atomic writes are recognised and removed", "[io]") {
  using paddy::io::isTemporaryName;
  CHECK(isTemporaryName("result.json.tmp.4242"));
  CHECK(isTemporaryName("snap_000001.h5.tmp.7"));
  CHECK(isTemporaryName("a.tmp.1.tmp.22"));
  CHECK_FALSE(isTemporaryName("result.json"));
  CHECK_FALSE(isTemporaryName("notes.tmp.txt"));
  CHECK_FALSE(isTemporaryName("x.tmp."));
  CHECK_FALSE(isTemporaryName(".tmp.12"));
  CHECK_FALSE(isTemporaryName("x.tmp.12a"));

  const fs::path dir = fs::temp_directory_path() / ("paddy_io_tmps_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  CHECK(paddy::io::removeTemporaries(dir) == 0);  // no directory: nothing
  fs::create_directories(dir / "a" / "b");
  for (const fs::path& p : {dir / "r.json.tmp.1", dir / "a" / "b" / "s.h5.tmp.99", dir / "r.json", dir / "a" / "t.tmp.x"})
    std::ofstream(p) << "x";
  // A temporary the writer itself produced and lost (its process killed) is removed like these.
  CHECK(paddy::io::removeTemporaries(dir) == 2);
  CHECK_FALSE(fs::exists(dir / "r.json.tmp.1"));
  CHECK_FALSE(fs::exists(dir / "a" / "b" / "s.h5.tmp.99"));
  CHECK(fs::exists(dir / "r.json"));
  CHECK(fs::exists(dir / "a" / "t.tmp.x"));
  fs::remove_all(dir);
}

namespace {
std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
// Runs `write` in a child process with PADDY_STOP_WRITING_AT = `at`; returns its pid once it has
// stopped (SIGSTOP) or exited, and whether it stopped.
std::pair<pid_t, bool> childWriting(const char* at, const std::function<void()>& write) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setenv("PADDY_STOP_WRITING_AT", at, 1);
    try {
      write();
    } catch (...) {
      ::_exit(3);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, WUNTRACED);
  return {pid, WIFSTOPPED(status)};
}
int finish(pid_t pid, int signal) {
  ::kill(pid, signal);
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}
}  // namespace

TEST_CASE("io: the write fault point stops a process half way through a write, once", "[io]") {
  // The hook tests/reliability/campaign_kill.sh kills campaigns in (paddy/io/atomic_file.hpp).
  const fs::path dir = fs::temp_directory_path() / ("paddy_io_stop_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string content = "0123456789abcdefghij";

  // A moment in the past: the first write stops with half of its content in the temporary and
  // the target not there; killed there, that is what stays (a reader never sees a partial file).
  auto [pid, stopped] = childWriting("1", [&] { paddy::io::writeFileAtomic(dir / "a.json", content); });
  REQUIRE(stopped);
  const fs::path tmp = dir / ("a.json.tmp." + std::to_string(pid));
  CHECK(slurp(tmp) == content.substr(0, content.size() / 2));
  CHECK_FALSE(fs::exists(dir / "a.json"));
  const int killed = finish(pid, SIGKILL);
  CHECK((WIFSIGNALED(killed) && WTERMSIG(killed) == SIGKILL));
  CHECK(fs::exists(tmp));
  CHECK_FALSE(fs::exists(dir / "a.json"));
  CHECK(paddy::io::removeTemporaries(dir) == 1);

  // Continued instead: the write completes, and the process stops only once (its second write
  // runs through).
  auto [pid2, stopped2] = childWriting("1", [&] {
    paddy::io::writeFileAtomic(dir / "b.json", content);
    paddy::io::writeFileAtomic(dir / "c.json", "second");
  });
  REQUIRE(stopped2);
  const int done = finish(pid2, SIGCONT);
  CHECK((WIFEXITED(done) && WEXITSTATUS(done) == 0));
  CHECK(slurp(dir / "b.json") == content);
  CHECK(slurp(dir / "c.json") == "second");

  // produceFileAtomic (the HDF5 writers) stops with its temporary written, not renamed.
  auto [pid3, stopped3] = childWriting("1", [&] {
    paddy::io::produceFileAtomic(dir / "d.h5", [](const fs::path& t) { std::ofstream(t) << "whole"; });
  });
  REQUIRE(stopped3);
  CHECK(slurp(dir / ("d.h5.tmp." + std::to_string(pid3))) == "whole");
  CHECK_FALSE(fs::exists(dir / "d.h5"));
  finish(pid3, SIGKILL);

  // A moment in the future, or no number: no stop.
  for (const char* at : {"4102444800", "soon", ""}) {
    auto [pid4, stopped4] = childWriting(at, [&] { paddy::io::writeFileAtomic(dir / "e.json", content); });
    CHECK_FALSE(stopped4);
    if (stopped4) finish(pid4, SIGKILL);
    CHECK(slurp(dir / "e.json") == content);
  }
  fs::remove_all(dir);
}

TEST_CASE("io: progress line shows time, percentage, rate and ETA", "[io]") {
  const std::string line = paddy::io::ProgressLine::format(0.25, 1.0, 0.25, 1.5e6, 75);
  CHECK_THAT(line, Catch::Contains("0.25 / 1 s") && Catch::Contains("25.0 %") && Catch::Contains("1.50M") &&
                       Catch::Contains("ETA 1m15s"));
}

TEST_CASE("io: XDMF text for an empty and a one-snapshot series", "[io]") {
  CHECK_THAT(paddy::io::xdmfText({}), Catch::Contains("<Xdmf"));
  const std::string x = paddy::io::xdmfText({{"snap_000000.h5", 0.5, 10}});
  CHECK_THAT(x, Catch::Contains("<Time Value=\"0.5\"/>") && Catch::Contains("NumberOfElements=\"10\"") &&
                    Catch::Contains("Dimensions=\"10 3\"") && Catch::Contains("snap_000000.h5:/particles/radius") &&
                    Catch::Contains("snap_000000.h5:/particles/vertex</DataItem>\n        </Topology>"));
}
