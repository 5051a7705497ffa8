// tests/fuzz/ply_mesh_fuzz.cpp — libFuzzer harness of the PLY reader (io/mesh_file.h readMeshFile
// on a `.ply` file, then requireClosedMesh): see mesh_fuzz.h.
#include <cstddef>
#include <cstdint>

#include "tests/fuzz/mesh_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fluidsound::fuzz::InputFile input("fuzz.ply");
  fluidsound::fuzz::readMeshInput(input, data, size);
  return 0;
}
