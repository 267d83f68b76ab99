// Shared by the `paddy doe` fuzz targets: runs the command line on a fuzzed input file. The CLI
// turns every refused input into a message and exit code 2; a crash, leak, UB or an escaping
// exception is a finding, and so is a refusal whose message does not name the file.
#pragma once

#include "fuzz_input_file.hpp"

#include <paddy/doe/cli.hpp>

#include <sstream>
#include <vector>

namespace paddy::fuzz {

inline void runDoe(std::vector<std::string> args, const std::string& input, bool require_file_named) {
  std::ostringstream out, err;
  const int code = paddy::doe::runCli(args, out, err);
  if (code != 0 && require_file_named) requireNamesFile(err.str(), input);
}

}  // namespace paddy::fuzz
