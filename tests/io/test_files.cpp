// Atomic files and the progress line format.
#include <paddy/io/atomic_file.hpp>
#include <paddy/io/progress.hpp>
#include <paddy/io/snapshot.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
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
