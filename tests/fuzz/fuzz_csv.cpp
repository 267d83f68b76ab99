// Fuzz target: the CSV reader of `paddy doe` (doe/src/csv.cpp), every column read as numbers.
#include "fuzz_input_file.hpp"

#include <paddy/doe/csv.hpp>
#include <paddy/doe/error.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = paddy::fuzz::writeInput("table.csv", data, size);
  try {
    const auto table = paddy::doe::readCsv(path);
    for (const auto& c : table.columns) {
      try {
        table.numeric(c);
      } catch (const paddy::doe::DoeError& e) {
        paddy::fuzz::requireNamesFile(e.what(), path);
      }
    }
  } catch (const paddy::doe::DoeError& e) {
    paddy::fuzz::requireNamesFile(e.what(), path);
  }
  return 0;
}
