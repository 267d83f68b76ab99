// Fuzz target: the discovery input of `paddy doe diagnose INPUT.json` (doe/src/discovery_json.cpp).
#include "fuzz_doe_cli.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = paddy::fuzz::writeInput("discovery.json", data, size);
  paddy::fuzz::runDoe({"doe", "diagnose", path}, path, false);
  return 0;
}
