// Shared by the fuzz targets: the input bytes as a file (the parsers under test read paths), and
// the rule every parser of outside input must keep: a refused input raises the project's error
// type with a message that names the file; anything else (another exception, a crash, a leak,
// undefined behaviour) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace paddy::fuzz {

// A per-process scratch directory (libFuzzer may run several processes side by side), removed
// with everything in it when the process exits.
struct ScratchDir {
  std::filesystem::path path;
  ScratchDir() : path(std::filesystem::temp_directory_path() / ("paddy_fuzz_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
};

inline const std::filesystem::path& scratchDir() {
  static const ScratchDir dir;
  return dir.path;
}

inline std::string writeInput(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const auto path = (scratchDir() / name).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(reinterpret_cast<const char*>(data),
                                                               static_cast<std::streamsize>(size));
  return path;
}

// Aborts (a finding) when an error message does not name the file it is about.
inline void requireNamesFile(const std::string& message, const std::string& file) {
  if (message.find(file) == std::string::npos) {
    std::fprintf(stderr, "error message does not name the file '%s': %s\n", file.c_str(), message.c_str());
    std::abort();
  }
}

}  // namespace paddy::fuzz
