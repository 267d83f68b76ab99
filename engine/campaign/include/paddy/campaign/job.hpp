// A campaign job: one `paddy run` of a script with parameters and a seed, and its content key.
//
// The key is the SHA-256 (hex) of a canonical text naming everything that decides the result:
// the script's content, the content of the Lua modules it requires (found beside the script or
// on the module path), the sorted parameters (name=value), the seed, the code version and, for
// jobs with an explicit command, that command. Threads are not part of the key: they are a
// resource, not an input. Equal keys mean "the same run", so a campaign runs each key once.
// See docs/campaign.md.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace paddy::campaign {

struct JobSpec {
  std::string script;                         // path of the experiment script (.lua)
  std::map<std::string, std::string> params;  // name → value text, passed as --set name=value
  std::uint64_t seed = 1;
  std::optional<int> threads;                 // --threads of this job (default: the executor's)
  // Explicit argv instead of `paddy run ...` (tests, other programs). The child runs in the job
  // directory with PADDY_JOB_DIR, PADDY_JOB_KEY, PADDY_JOB_THREADS, PADDY_JOB_SEED,
  // PADDY_JOB_ATTEMPT and PADDY_PARAM_<name> in its environment, and must write result.json
  // ({"status": "complete", ...}) atomically on success. The script may then be empty.
  std::vector<std::string> command;

  // Parameter setters that print values exactly (numbers with %.17g, so they round-trip).
  JobSpec& set(const std::string& name, double value);
  JobSpec& set(const std::string& name, long long value);
  JobSpec& set(const std::string& name, int value) { return set(name, static_cast<long long>(value)); }
  JobSpec& set(const std::string& name, bool value);
  JobSpec& set(const std::string& name, const std::string& value);
  JobSpec& set(const std::string& name, const char* value) { return set(name, std::string(value)); }
};

// Exact text of a number: integers without a fraction, others with %.17g.
std::string formatNumber(double value);

// SHA-256 (lower-case hex) of bytes / of a file's content. Throws std::runtime_error.
std::string sha256Hex(const std::string& data);
std::string sha256File(const std::filesystem::path& path);

// Lua modules that `script` requires, transitively: module name → resolved file. Modules are
// looked up as <dir>/<a/b>.lua and <dir>/<a/b>/init.lua in the script's directory and then in
// `module_path`; names that resolve to no file (e.g. "paddy") are skipped. The scan is textual
// (require "x", require("x"), require 'x').
std::map<std::string, std::filesystem::path> requiredModules(const std::filesystem::path& script,
                                                             const std::vector<std::filesystem::path>& module_path);

// The canonical text the key is hashed from (kept in job.json for inspection), and the key.
std::string keyMaterial(const JobSpec& spec, const std::string& code_version,
                        const std::vector<std::filesystem::path>& module_path);
std::string jobKey(const JobSpec& spec, const std::string& code_version,
                   const std::vector<std::filesystem::path>& module_path = {});

// "paddy <version> exe:<sha256 of executable> lib:<sha256 of the engine library>"; the parts
// that cannot be read are left out. `executable` may be empty.
std::string defaultCodeVersion(const std::filesystem::path& executable);

}  // namespace paddy::campaign
