// Atomic file output: write to "<path>.tmp.<pid>" in the same directory, then rename over the
// target, so a reader (or a crash) never sees a half-written file.
#pragma once

#include <filesystem>
#include <functional>
#include <string_view>

namespace paddy::io {

// Writes `content` to `path` atomically; creates parent directories. Throws std::runtime_error
// naming the file on failure (the temporary is removed).
void writeFileAtomic(const std::filesystem::path& path, std::string_view content);

// Calls `write(tmp_path)` to produce the file under a temporary name, then renames it to `path`.
// Used for files written by libraries that want a path (HDF5).
void produceFileAtomic(const std::filesystem::path& path,
                       const std::function<void(const std::filesystem::path&)>& write);

}  // namespace paddy::io
