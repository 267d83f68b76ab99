// Helpers shared by the geometry tests.
#pragma once

#include <paddy/geometry.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace paddy::test {

// A fresh temporary directory per call (removed by the caller's TempDir destructor).
struct TempDir {
  std::filesystem::path path;
  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "paddy_geom_XXXXXX").string();
    path = mkdtemp(tmpl.data());
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  std::string file(const std::string& name) const { return (path / name).string(); }
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(file(name), std::ios::binary) << text;
    return file(name);
  }
};

inline std::string sourceDir() {
  const char* s = std::getenv("PADDY_SOURCE_DIR");
  return s ? s : PADDY_TEST_SOURCE_DIR;
}

}  // namespace paddy::test
