// Fuzz target: the fit file of `paddy doe optimize FIT.json` (doe/src/report_json.cpp fitFromJson).
#include "fuzz_doe_cli.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = paddy::fuzz::writeInput("fit.json", data, size);
  paddy::fuzz::runDoe({"doe", "optimize", path, "--goal", "y=max", "--starts", "2", "--solutions", "1"}, path, false);
  return 0;
}
