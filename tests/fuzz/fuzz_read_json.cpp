// Fuzz target: paddy.read_json (engine/lua/src/lua_json.cpp), the JSON reader of Lua experiments
// (calibration targets, measured curves, calibration and discovery inputs), and paddy.result
// writing what it read back out as JSON.
#include "fuzz_script.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = paddy::fuzz::writeInput("input.json", data, size);
  const auto r = paddy::fuzz::runFixedScript("read_json",
      "paddy.result{value = paddy.read_json(" + std::string("[==[") + path + "]==]" + ")}\n");
  if (r.code != paddy::lua::kExitOk) paddy::fuzz::requireNamesFile(r.err, path);
  return 0;
}
