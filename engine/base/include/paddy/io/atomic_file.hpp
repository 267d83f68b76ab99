// Atomic file output: write to "<path>.tmp.<pid>" in the same directory, then rename over the
// target, so a reader (or a crash) never sees a half-written file.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string_view>

namespace paddy::io {

// Writes `content` to `path` atomically; creates parent directories. Throws std::runtime_error
// naming the file on failure (the temporary is removed).
//
// Test hook (tests/reliability/campaign_kill.sh, kill moment "write"): with PADDY_STOP_WRITING_AT
// = a Unix time in seconds in the environment, a process stops itself (SIGSTOP) in the first
// atomic write it begins at or after that moment, once: writeFileAtomic with half of the content
// in the temporary, produceFileAtomic with the temporary written but not yet renamed. The test
// then kills it with SIGKILL there, i.e. while a file is being written. Unset, empty or not a
// number: no effect.
void writeFileAtomic(const std::filesystem::path& path, std::string_view content);

// Calls `write(tmp_path)` to produce the file under a temporary name, then renames it to `path`.
// Used for files written by libraries that want a path (HDF5).
void produceFileAtomic(const std::filesystem::path& path,
                       const std::function<void(const std::filesystem::path&)>& write);

// True for a name of the form "<name>.tmp.<digits>": a temporary of the writers above.
bool isTemporaryName(std::string_view filename);

// Removes every temporary ("<name>.tmp.<pid>") under `dir`, recursively, and returns how many.
// For a directory no process writes to at the moment: a campaign job's directory before its next
// attempt starts, where the temporaries are what an earlier, killed attempt left behind. A
// missing directory removes nothing.
std::size_t removeTemporaries(const std::filesystem::path& dir);

}  // namespace paddy::io
