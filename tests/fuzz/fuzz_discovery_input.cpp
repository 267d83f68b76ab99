// Fuzz target: the discovery input file (experiments/lib/discovery/input.lua, read through
// paddy.read_json and checked in Lua). A refused file must end as an input error naming the file;
// a Lua runtime error (exit code 1) on a malformed file is a finding.
#include "fuzz_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = paddy::fuzz::writeInput("discovery.json", data, size);
  const auto r = paddy::fuzz::runFixedScript("discovery_input",
      "local input = require('lib.discovery.input').read([==[" + path + "]==])\n"
      "paddy.result{path = input.path}\n");
  if (r.code != paddy::lua::kExitOk) paddy::fuzz::requireNamesFile(r.err, path);
  return 0;
}
