// Atomic file output (tmp + rename), see paddy/io/atomic_file.hpp.
#include <paddy/io/atomic_file.hpp>

#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unistd.h>

namespace paddy::io {

namespace fs = std::filesystem;

namespace {

fs::path temporaryFor(const fs::path& path) {
  return fs::path(path.string() + ".tmp." + std::to_string(::getpid()));
}

void ensureParent(const fs::path& path) {
  if (path.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec) throw std::runtime_error("cannot create directory '" + path.parent_path().string() + "': " + ec.message());
  }
}

}  // namespace

void produceFileAtomic(const fs::path& path, const std::function<void(const fs::path&)>& write) {
  ensureParent(path);
  const fs::path tmp = temporaryFor(path);
  try {
    write(tmp);
  } catch (...) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw;
  }
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw std::runtime_error("cannot rename '" + tmp.string() + "' to '" + path.string() + "': " + ec.message());
  }
}

void writeFileAtomic(const fs::path& path, std::string_view content) {
  produceFileAtomic(path, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error("cannot open '" + tmp.string() + "' for writing");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) throw std::runtime_error("cannot write '" + tmp.string() + "'");
  });
}

}  // namespace paddy::io
