// Fuzz target: mesh import (STL ASCII and binary, OBJ, OFF; plugins/geometry/src/mesh_io.cpp).
// The first input byte picks the file extension, the rest is the file.
#include "fuzz_input_file.hpp"

#include <paddy/errors.hpp>
#include <paddy/geometry/mesh_io.hpp>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  static const char* const kExtensions[] = {".stl", ".obj", ".off"};
  const std::string path = paddy::fuzz::writeInput(std::string("mesh") + kExtensions[data[0] % 3], data + 1, size - 1);
  try {
    paddy::geometry::readMesh(path);
  } catch (const paddy::InputError& e) {
    paddy::fuzz::requireNamesFile(e.what(), path);
  }
  return 0;
}
