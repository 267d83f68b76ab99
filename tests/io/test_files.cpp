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
