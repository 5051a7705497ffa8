// io/mesh_file.cpp — the checks every mesh file gets, whatever its format, and the closed-mesh
// requirement (see mesh_file.h); the formats themselves are in obj_ and ply_mesh_reader.cpp.
#include "io/mesh_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <system_error>
#include <vector>

#include "io/input_error.h"
#include "io/json_validation.h"
#include "io/mesh_readers.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

enum class MeshFormat { Obj, Ply, Unknown };

MeshFormat formatOf(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".obj") return MeshFormat::Obj;
  if (extension == ".ply") return MeshFormat::Ply;
  return MeshFormat::Unknown;
}

/// How the format numbers its vertices in faces: OBJ from 1, PLY from 0.
std::uint32_t firstVertexNumber(const fs::path& path) {
  return formatOf(path) == MeshFormat::Obj ? 1 : 0;
}

/// An OBJ file is text: a NUL or other control byte (tab, line and page breaks aside) means
/// binary data, which tinyobjloader would skip line by line without a word.
void requireText(std::string_view text, const MeshErrorReporter& report) {
  std::size_t line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\n') ++line;
    if (c < 0x20 && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f') {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02x", c);
      report.fail("line " + std::to_string(line), "an OBJ text file",
                  std::string("the control byte ") + hex + " (binary data)");
    }
  }
}

std::string readWholeFile(const fs::path& path, const MeshErrorReporter& report) {
  const std::string expected = "a readable mesh file (OBJ or PLY)";
  if (const std::string kind = nonRegularInput(path); !kind.empty()) report.fail("", expected, kind);
  std::ifstream in(path, std::ios::binary);
  if (!in) report.fail("", expected, std::generic_category().message(errno));
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) report.fail("", expected, "a read error");
  return bytes;
}

/// "1 edge", "4 edges"; `many` for irregular plurals ("vertices").
std::string counted(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string edgeText(const MeshEdge& edge, std::uint32_t first) {
  return "vertices " + std::to_string(edge[0] + first) + " and " + std::to_string(edge[1] + first);
}

}  // namespace

void MeshErrorReporter::fail(const std::string& location, const std::string& expected,
                             const std::string& found) const {
  if (reference_.jsonPath.empty()) throw InputError(path_.string(), location, expected, found);
  const std::string where = path_.string() + (location.empty() ? "" : ", " + location);
  throw InputError(reference_.sceneFile, reference_.jsonPath, expected, found + " (" + where + ")");
}

std::string quotedExcerpt(std::string_view text) {
  constexpr std::size_t kMaxBytes = 60;
  std::string out = "\"";
  for (std::size_t i = 0; i < std::min(text.size(), kMaxBytes); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    out += (c < 0x20 || c >= 0x7f) ? '?' : static_cast<char>(c);
  }
  if (text.size() > kMaxBytes) out += "...";
  return out + "\"";
}

std::string numberText(double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return error == std::errc{} ? std::string(buffer, end) : "?";
}

std::string pointText(double x, double y, double z) {
  std::string text = "(";
  text += numberText(x);
  text += ", ";
  text += numberText(y);
  text += ", ";
  text += numberText(z);
  text += ")";
  return text;
}

sim::TriangleMesh readMeshFile(const fs::path& path, const MeshReference& reference) {
  const MeshErrorReporter report(path, reference);
  const std::string bytes = readWholeFile(path, report);
  const MeshFormat format = formatOf(path);
  if (format == MeshFormat::Unknown) {
    report.fail("", "a mesh file named *.obj or *.ply",
                path.extension().empty() ? std::string("no extension")
                                         : quotedExcerpt(path.extension().string()));
  }
  if (bytes.empty()) report.fail("", "a mesh with at least one triangle", "an empty file");

  sim::TriangleMesh mesh;
  if (format == MeshFormat::Obj) {
    requireText(bytes, report);
    mesh = parseObjMesh(bytes, report);
  } else {
    mesh = parsePlyMesh(bytes, report);
  }

  // The parsers check as they read, with the file's own locations; these hold for both formats.
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const auto& p = mesh.vertices[v];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      report.fail("vertex " + std::to_string(v + firstVertexNumber(path)),
                  "finite coordinates x, y, z", pointText(p[0], p[1], p[2]));
  }
  if (mesh.triangles.empty()) {
    report.fail("", "a mesh with at least one triangle",
                "no faces (" + counted(mesh.vertices.size(), "vertex", "vertices") + ")");
  }
  return mesh;
}

MeshClosedness requireClosedMesh(const sim::TriangleMesh& mesh, const fs::path& path,
                                      const MeshReference& reference) {
  const MeshClosedness closedness = meshClosedness(mesh);
  if (closedness.closed()) return closedness;

  const std::uint32_t first = firstVertexNumber(path);
  std::vector<std::string> problems;
  if (closedness.boundaryEdges > 0)
    problems.push_back(counted(closedness.boundaryEdges, "boundary edge", "boundary edges") +
                       " (holes; the first between " +
                       edgeText(closedness.firstBoundaryEdge, first) + ")");
  if (closedness.nonManifoldEdges > 0)
    problems.push_back(counted(closedness.nonManifoldEdges, "edge", "edges") +
                       " shared by 3 or more triangles (the first between " +
                       edgeText(closedness.firstNonManifoldEdge, first) + ")");
  if (closedness.misorientedEdges > 0)
    problems.push_back(counted(closedness.misorientedEdges, "edge", "edges") +
                       " where two triangles disagree in orientation (the first between " +
                       edgeText(closedness.firstMisorientedEdge, first) + ")");
  std::string found;
  for (std::size_t i = 0; i < problems.size(); ++i) {
    if (i > 0) found += (i + 1 == problems.size()) ? " and " : ", ";
    found += problems[i];
  }
  MeshErrorReporter(path, reference)
      .fail("",
            "a closed triangle mesh (every edge shared by exactly two triangles that run along it "
            "in opposite directions)",
            found);
}

}  // namespace fluidsound::io
