// Fuzz target: `paddy run --set name=value` (engine/lua/src/parameters.cpp) against parameters of
// every kind (number with range, integer, choice, boolean, free text). The input is split into
// assignments at newlines, each parsed as `paddy run` parses the command line (parseAssignment).
#include "fuzz_script.hpp"

#include <paddy/errors.hpp>

namespace {
const char* const kScript = R"(
local P = paddy.parameters{
  speed = {default = 0.05, unit = "m/s", min = 0, max = 1, description = "a number"},
  count = {default = 3, type = "integer", min = 1, max = 10, description = "an integer"},
  mode = {default = "a", choices = {"a", "b"}, description = "a choice"},
  flag = {default = true, description = "a boolean"},
  label = {default = "x", description = "free text"},
}
paddy.result{speed = P.speed, count = P.count, mode = P.mode, flag = P.flag, label = P.label}
)";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::pair<std::string, std::string>> sets;
  std::size_t start = 0;
  while (start <= text.size() && sets.size() < 8) {
    const auto end = std::min(text.find('\n', start), text.size());
    try {
      sets.push_back(paddy::lua::parseAssignment(text.substr(start, end - start)));
    } catch (const paddy::InputError&) {
      return 0;  // `paddy run` reports it as a usage error before running anything
    }
    start = end + 1;
  }
  paddy::fuzz::runFixedScript("set", kScript, std::move(sets));
  return 0;
}
