// Fuzz target: `paddy doe analyze DATA.csv` (CSV reading, coding, regression and ANOVA of the data).
#include "fuzz_doe_cli.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = paddy::fuzz::writeInput("runs.csv", data, size);
  paddy::fuzz::runDoe({"doe", "analyze", path, "--factors", "A,B", "--responses", "y", "--model", "2fi"}, path, false);
  return 0;
}
