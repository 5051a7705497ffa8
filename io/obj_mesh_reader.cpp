// io/obj_mesh_reader.cpp — OBJ meshes (see mesh_readers.h): tinyobjloader parses the faces; our
// own pass first checks every vertex's numbers, because tinyobjloader 2.0.0rc10 reads `nan`,
// `inf`, `abc` or `1,5` as 0 (or 1) without an error or a warning (measured), so a NaN vertex
// would silently move to the origin.
#include <tiny_obj_loader.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "io/mesh_readers.h"

namespace fluidsound::io {
namespace {

/// tinyobjloader stores a face's corner count in an unsigned char.
constexpr std::size_t kMaxFaceCorners = 255;

std::string lineLocation(std::size_t line) { return "line " + std::to_string(line); }

bool isBlank(char c) { return c == ' ' || c == '\t'; }

/// The blank-separated words of a line (as tinyobjloader splits them: spaces and tabs).
std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

/// A coordinate: the whole word is a decimal number (an optional leading '+' allowed), finite and
/// within float range (the mesh stores floats).
bool isFloatCoordinate(std::string_view word) {
  if (!word.empty() && word.front() == '+') word.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  return error == std::errc{} && end == word.data() + word.size() && std::isfinite(value) &&
         std::abs(value) <= std::numeric_limits<float>::max();
}

/// A face corner `v`, `v/vt`, `v//vn` or `v/vt/vn`: each index that is given is an integer
/// within ±(2³¹ − 1), which tinyobjloader stores in an int (a larger one wraps around to
/// another vertex, silently).
bool isFaceCorner(std::string_view word) {
  std::size_t part = 0;
  while (true) {
    const std::size_t slash = word.find('/');
    const std::string_view index = word.substr(0, slash);
    if (!index.empty() || part == 0) {
      std::int64_t value = 0;
      const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), value);
      if (error != std::errc{} || end != index.data() + index.size() ||
          value > std::numeric_limits<std::int32_t>::max() ||
          value < -std::numeric_limits<std::int32_t>::max())
        return false;
    }
    if (slash == std::string_view::npos) return true;
    if (++part > 2) return false;
    word.remove_prefix(slash + 1);
  }
}

/// What our pass learns: the vertex count and, per face in file order, its line and text.
struct ObjOutline {
  std::size_t vertices = 0;
  std::vector<std::size_t> faceLines;
  std::vector<std::string_view> faceTexts;
};

/// Checks the `v` and `f` statements, line by line (lines end in \n, \r\n or \r, as in
/// tinyobjloader, so the line numbers agree with its messages).
ObjOutline outline(std::string_view text, const MeshErrorReporter& report) {
  ObjOutline result;
  std::size_t lineNumber = 0;
  std::size_t i = 0;
  while (i < text.size()) {
    const std::size_t start = i;
    while (i < text.size() && text[i] != '\n' && text[i] != '\r') ++i;
    const std::string_view line = text.substr(start, i - start);
    if (i < text.size() && text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
    ++i;
    ++lineNumber;

    const std::vector<std::string_view> w = words(line);
    if (w.empty()) continue;
    if (w[0] == "v") {
      const std::string expected =
          "a vertex \"v x y z\" of 3 finite numbers within float range (|x| <= 3.4e38)";
      if (w.size() < 4) report.fail(lineLocation(lineNumber), expected, quotedExcerpt(line));
      for (std::size_t c = 1; c <= 3; ++c) {
        if (!isFloatCoordinate(w[c])) {
          report.fail(lineLocation(lineNumber), expected,
                      quotedExcerpt(w[c]) + " in " + quotedExcerpt(line));
        }
      }
      ++result.vertices;
    } else if (w[0] == "f") {
      if (w.size() < 4 || w.size() > kMaxFaceCorners + 1) {
        report.fail(lineLocation(lineNumber), "a face \"f\" of 3 to 255 vertices",
                    quotedExcerpt(line) + " (" + std::to_string(w.size() - 1) + " vertices)");
      }
      for (std::size_t c = 1; c < w.size() && w[c].front() != '#'; ++c) {  // up to a comment
        if (!isFaceCorner(w[c])) {
          report.fail(
              lineLocation(lineNumber),
              "a face corner \"v\", \"v/vt\", \"v//vn\" or \"v/vt/vn\" of integer indices within "
              "+-2147483647",
              quotedExcerpt(w[c]) + " in " + quotedExcerpt(line));
        }
      }
      result.faceLines.push_back(lineNumber);
      result.faceTexts.push_back(line);
    }
  }
  return result;
}

/// tinyobjloader's message on one line, without its trailing newline and stray punctuation.
std::string tidyMessage(std::string message) {
  for (char& c : message) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!message.empty() && (message.back() == ' ' || message.back() == '.')) message.pop_back();
  return message;
}

}  // namespace

sim::TriangleMesh parseObjMesh(const std::string& text, const MeshErrorReporter& report) {
  const ObjOutline checked = outline(text, report);

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // we split polygons ourselves, after checking every index
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From a string: `mtllib` lines are ignored, no other file is opened.
  if (!reader.ParseFromString(text, "", config)) {
    report.fail("", "a valid OBJ file", quotedExcerpt(tidyMessage(reader.Error())));
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();

  sim::TriangleMesh mesh;
  const std::size_t vertexCount = attrib.vertices.size() / 3;
  if (vertexCount != checked.vertices) {
    report.fail("", "a valid OBJ file",
                std::to_string(checked.vertices) + " vertex lines, of which the OBJ parser read " +
                    std::to_string(vertexCount));
  }
  if (vertexCount > std::numeric_limits<std::uint32_t>::max()) {
    report.fail("", "at most 4294967295 vertices", std::to_string(vertexCount));
  }
  mesh.vertices.resize(vertexCount);
  for (std::size_t v = 0; v < vertexCount; ++v)
    for (int a = 0; a < 3; ++a) mesh.vertices[v][a] = attrib.vertices[3 * v + a];

  std::size_t face = 0;  // in file order: shapes keep the order of their faces
  std::vector<std::uint32_t> polygon;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t corner = 0;
    for (const unsigned char cornerCount : shape.mesh.num_face_vertices) {
      polygon.resize(cornerCount);
      for (std::size_t c = 0; c < cornerCount; ++c) {
        const int index = shape.mesh.indices[corner + c].vertex_index;
        if (index < 0 || static_cast<std::size_t>(index) >= vertexCount) {
          report.fail(face < checked.faceLines.size() ? lineLocation(checked.faceLines[face]) : "",
                      "vertex indices from 1 to " + std::to_string(vertexCount) +
                          " (the file has " + std::to_string(vertexCount) + " vertices)",
                      face < checked.faceTexts.size() ? quotedExcerpt(checked.faceTexts[face])
                                                      : "index " + std::to_string(index + 1));
        }
        polygon[c] = static_cast<std::uint32_t>(index);
      }
      for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
        mesh.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
      corner += cornerCount;
      ++face;
    }
  }
  if (face != checked.faceLines.size()) {
    report.fail("", "a valid OBJ file",
                std::to_string(checked.faceLines.size()) +
                    " face lines, of which the OBJ parser read " + std::to_string(face));
  }
  return mesh;
}

}  // namespace fluidsound::io
