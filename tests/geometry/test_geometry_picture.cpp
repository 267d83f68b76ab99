// Part pictures (writePicture, used by paddy_mesh_export): a hostile directory name, file name
// and title reach gnuplot and the shell only as quoted text. No command in them runs, nothing is
// written outside the image directory, and the PNG arrives whole with no scratch files left.
#include "test_util.hpp"

#include <paddy/geometry/parts.hpp>
#include <paddy/geometry/picture.hpp>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace paddy;
using namespace paddy::geometry;
namespace fs = std::filesystem;

namespace {
// Every regular file below `root`, as paths relative to it.
std::vector<std::string> filesBelow(const fs::path& root) {
  std::vector<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file()) out.push_back(fs::relative(e.path(), root).string());
  return out;
}

// Changes the working directory for the scope, so that a canary `touch` with a relative path
// would land in the test's directory.
struct WorkingDirectory {
  fs::path before = fs::current_path();
  explicit WorkingDirectory(const fs::path& p) { fs::current_path(p); }
  ~WorkingDirectory() {
    std::error_code ec;
    fs::current_path(before, ec);
  }
};
}  // namespace

TEST_CASE("geometry part picture: quotes, $(...), backticks and line breaks in names and title run nothing") {
  test::TempDir dir;
  WorkingDirectory cwd(dir.path);
  const fs::path images = dir.path / "img '$(touch CANARY_DIR)' `touch CANARY_TICK`; \"q\"";
  fs::create_directories(images);
  const std::string png = (images / "cone 'x' $(touch CANARY_FILE).png").string();

  PictureOptions o;
  o.title = "it's a \"cone\" `touch CANARY_TITLE_TICK` $(touch CANARY_TITLE_DOLLAR)\n"
            "system 'touch CANARY_NEWLINE'\r\n! touch CANARY_BANG";
  o.width = 320;
  o.height = 240;
  const bool written = writePicture(buildSlumpCone(), png, o);

  // No command ran: no canary anywhere under the test directory (checked before anything else,
  // so a run that both fails and runs a command shows the command).
  std::string listing, canaries;
  const std::vector<std::string> files = filesBelow(dir.path);
  for (const std::string& f : files) {
    listing += "\n  " + f;
    if (fs::path(f).filename().string().rfind("CANARY", 0) == 0) canaries += " " + f;
  }
  INFO("files written:" << listing);
  CHECK(canaries.empty());
  REQUIRE(written);

  // The PNG is there, whole (signature and the IEND chunk at its end).
  std::ifstream in(png, std::ios::binary);
  REQUIRE(in);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() > 1000);
  CHECK(bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  CHECK(bytes.compare(bytes.size() - 8, 4, "IEND") == 0);

  // Only the PNG: no .gp / .dat / .tmp left.
  REQUIRE(files.size() == 1);
  CHECK(fs::path(files.front()).filename() == fs::path(png).filename());
}

TEST_CASE("geometry part picture into a directory that does not exist: false, and no PNG") {
  test::TempDir dir;
  const std::string png = dir.file("missing 'dir'/cone.png");
  CHECK_FALSE(writePicture(buildSlumpCone(), png));
  CHECK_FALSE(fs::exists(png));
  CHECK(filesBelow(dir.path).empty());
}
