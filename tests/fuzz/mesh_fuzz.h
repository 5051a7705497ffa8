// tests/fuzz/mesh_fuzz.h — the body of the OBJ and PLY harnesses (obj_mesh_fuzz.cpp,
// ply_mesh_fuzz.cpp): readMeshFile on the fuzz input, then requireClosedMesh on what it returns.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "io/input_error.h"
#include "io/mesh_file.h"
#include "tests/fuzz/fuzz_input.h"

namespace fluidsound::fuzz {

/// @brief What readMeshFile promises of a mesh it returns (io/mesh_file.h): at least one triangle,
///        finite vertices, every index in range; a broken promise stops the run as a crash.
inline void requireValidMesh(const sim::TriangleMesh& mesh) {
  if (mesh.triangles.empty()) fail("a mesh without triangles");
  for (const auto& vertex : mesh.vertices)
    for (const float coordinate : vertex)
      if (!std::isfinite(coordinate)) fail("a vertex that is not finite");
  for (const auto& triangle : mesh.triangles)
    for (const std::uint32_t index : triangle)
      if (index >= mesh.vertices.size())
        fail("a vertex index out of range: " + std::to_string(index));
}

/// @brief One fuzz input read as the mesh file `input`: a valid mesh (closed or refused as open
///        with a one-line error) or a one-line io::InputError.
inline void readMeshInput(const InputFile& input, const std::uint8_t* data, std::size_t size) {
  const std::filesystem::path& path = input.write(data, size);
  try {
    const sim::TriangleMesh mesh = io::readMeshFile(path);
    requireValidMesh(mesh);
    (void)io::requireClosedMesh(mesh, path);
  } catch (const io::InputError& error) {
    requireOneLineNaming(error, path.string());
  } catch (const io::OutputError& error) {
    requireOneLineNaming(error, path.string());
  }
}

}  // namespace fluidsound::fuzz
