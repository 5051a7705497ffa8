// io/mesh_readers.h — internal to io/mesh_file.cpp: the OBJ and PLY parsers behind readMeshFile
// and the one way they report a problem (an InputError in mesh_file.h's two forms).
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include "io/mesh_file.h"
#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::io {

/// Turns a problem at one place of a mesh file into an InputError (see readMeshFile).
class MeshErrorReporter {
 public:
  MeshErrorReporter(std::filesystem::path path, MeshReference reference)
      : path_(std::move(path)), reference_(std::move(reference)) {}

  /// @param location  `line 4`, `vertex 3`, `face 2`, or empty for the whole file
  /// @throws InputError always
  [[noreturn]] void fail(const std::string& location, const std::string& expected,
                         const std::string& found) const;

 private:
  std::filesystem::path path_;
  MeshReference reference_;
};

/// Text quoted for a message: cut after 60 bytes (marked "..."), bytes outside printable ASCII
/// shown as '?', so a binary file's garbage stays short and readable.
std::string quotedExcerpt(std::string_view text);

/// A number for a message: the shortest text that reads back to the same double (`nan`, `inf`).
std::string numberText(double value);

/// A point for a message: `(x, y, z)` with numberText.
std::string pointText(double x, double y, double z);

/// @brief Parses OBJ text (see readMeshFile): vertices and fan-triangulated faces.
/// @throws InputError (through `report`) for a vertex line without 3 finite numbers within float
///         range, a face of fewer than 3 or more than 255 vertices, an index out of range, or any
///         error of tinyobjloader
sim::TriangleMesh parseObjMesh(const std::string& text, const MeshErrorReporter& report);

/// @brief Parses a PLY file's bytes (see readMeshFile): vertices and fan-triangulated faces.
/// @throws InputError (through `report`) for a malformed header, a value that does not parse,
///         a file that ends before the declared elements, a face of fewer than 3 vertices, an
///         index out of range, or a coordinate that is not finite as a float
sim::TriangleMesh parsePlyMesh(std::string_view bytes, const MeshErrorReporter& report);

}  // namespace fluidsound::io
