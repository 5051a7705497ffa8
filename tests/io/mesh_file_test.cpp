// tests/io/mesh_file_test.cpp — OBJ and PLY meshes written by the test are read back with their
// counts and coordinates; closed and open meshes are told apart; every bad file is one InputError
// naming the mesh (or the scene field that named it), the place in the file and what was expected.
#include "io/mesh_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <string>

#include "io/input_error.h"
#include "support/input_error_expectations.h"
#include "support/temp_folder.h"
#include "support/test_meshes.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;
using test::ExpectedAt;
using test::PlyEncoding;

/// A unit cube as an OBJ file would have it: quads, 1-based indices, a normal and a group.
constexpr const char* kCubeObj = R"(# unit cube, quads, counter-clockwise seen from outside
o cube
v 0 0 0
v 1 0 0
v 0 1 0
v 1 1 0
v 0 0 1
v 1 0 1
v 0 1 1
v 1 1 1
vn 0 0 -1
g sides
f 1 5 7 3
f 2 4 8 6
f 1//1 2//1 6//1 5//1
f 3 7 8 4
g caps
f 1 3 4 2
f 5 6 8 7
)";

/// The error that reading `path` throws (a test failure if none).
InputError readError(const fs::path& path, const MeshReference& reference = {}) {
  return test::inputErrorOf([&](const std::string&) { readMeshFile(path, reference); },
                            path.string());
}

fs::path write(const test::TempFolder& folder, const std::string& name, const std::string& text) {
  const fs::path path = folder.path() / name;
  test::writeFile(path, text);
  return path;
}

// ---- reading ---------------------------------------------------------------------------------

TEST(MeshFile, CubeObjWithQuadsReadsAsEightVerticesAndTwelveTriangles) {
  // Claim: six quads become twelve triangles over the file's eight vertices, in file order; the
  // cube is closed and encloses 1 m³. Reference: the file itself. Tolerance: the volume is a
  // sum of 12 products of small integers in double, exact.
  const test::TempFolder folder;
  const sim::TriangleMesh mesh = readMeshFile(write(folder, "cube.obj", kCubeObj));
  ASSERT_EQ(mesh.vertices.size(), 8u);
  ASSERT_EQ(mesh.triangles.size(), 12u);
  EXPECT_EQ(mesh.vertices[7], (std::array<float, 3>{1, 1, 1}));
  // Fan of "f 1 5 7 3" (0-based 0 4 6 2).
  EXPECT_EQ(mesh.triangles[0], (std::array<std::uint32_t, 3>{0, 4, 6}));
  EXPECT_EQ(mesh.triangles[1], (std::array<std::uint32_t, 3>{0, 6, 2}));
  EXPECT_EQ(mesh, test::boxMesh({0, 0, 0}, {1, 1, 1}));
  const MeshClosedness closedness = requireClosedMesh(mesh, folder.path() / "cube.obj");
  EXPECT_TRUE(closedness.closed());
  EXPECT_EQ(closedness.edges, 18u);  // 12 cube edges + 6 quad diagonals
  EXPECT_DOUBLE_EQ(closedness.signedVolume, 1.0);
}

TEST(MeshFile, ObjFaceFormsAndNegativeIndicesNameTheSameVertices) {
  // Claim: `i`, `i/t`, `i//n`, `i/t/n` and negative (relative) indices all name vertex i, and
  // `#` comments, `vt`, `vn`, `s`, `usemtl` and `mtllib` (not opened) are ignored.
  const test::TempFolder folder;
  const std::string text =
      "mtllib missing.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv +0 0 1.0e0\nvt 0 0\nvn 0 0 1\ns off\n"
      "usemtl none\nf 1 2 3\nf 1/1 3/1 4/1\nf 1//1 4//1 2//1\nf -3/1/1 -1/1/1 -2/1/1\n";
  const sim::TriangleMesh mesh = readMeshFile(write(folder, "tet.OBJ", text));
  const sim::TriangleMesh expected{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                                   {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}}};
  EXPECT_EQ(mesh, expected);
}

TEST(MeshFile, PlyAsciiLittleAndBigEndianGiveTheObjMesh) {
  // Claim: the same mesh written as OBJ and as PLY in all three encodings reads back identical
  // (vertices bit for bit: 9 significant digits or raw floats; triangles in order), skipping
  // the extra vertex property, the extra element and the header's comment, with \r\n lines.
  const test::TempFolder folder;
  const sim::TriangleMesh sphere = test::icosphere(2);
  const sim::TriangleMesh fromObj = readMeshFile(write(folder, "s.obj", test::objText(sphere)));
  EXPECT_EQ(fromObj, sphere);
  for (const PlyEncoding encoding :
       {PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian}) {
    const fs::path path = write(folder, "s.ply", test::plyText(sphere, encoding));
    EXPECT_EQ(readMeshFile(path), sphere) << "encoding " << static_cast<int>(encoding);
  }
}

TEST(MeshFile, PlyWithDoublesQuadsAndVertexIndexReadsAsTriangles) {
  // Claim: double coordinates, a `vertex_index` list with a ushort count, int8 extra property
  // before x, and quads split into fans all read as the plain cube.
  const test::TempFolder folder;
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 8\nproperty char flag\nproperty double x\n"
      "property double y\nproperty double z\nelement face 6\n"
      "property list ushort uint vertex_index\nend_header\n"
      "-1 0 0 0\n1 1 0 0\n0 0 1 0\n0 1 1 0\n0 0 0 1\n0 1 0 1\n0 0 1 1\n0 1 1 1\n"
      "4 0 4 6 2\n4 1 3 7 5\n4 0 1 5 4\n4 2 6 7 3\n4 0 2 3 1\n4 4 5 7 6\n";
  const sim::TriangleMesh mesh = readMeshFile(write(folder, "cube.ply", text));
  EXPECT_EQ(mesh, test::boxMesh({0, 0, 0}, {1, 1, 1}));
}

TEST(MeshFile, IcosphereIsClosedAndEnclosesNearlyTheBallVolume) {
  // Claim: the icosphere of 3 subdivisions (642 vertices, 1280 triangles) is closed, oriented
  // outward, and its volume is below the ball's 4π/3 by less than its faceting allows.
  // Reference: a polyhedron inscribed in the unit sphere whose faces are all at least d_min
  // from the centre holds the ball of radius d_min, so 4π/3·d_min³ < V < 4π/3.
  const test::TempFolder folder;
  const sim::TriangleMesh mesh =
      readMeshFile(write(folder, "ball.obj", test::objText(test::icosphere(3))));
  EXPECT_EQ(mesh.vertices.size(), 642u);
  EXPECT_EQ(mesh.triangles.size(), 1280u);
  const MeshClosedness closedness = requireClosedMesh(mesh, folder.path() / "ball.obj");
  double dMin = 1.0;
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    const auto& b = mesh.vertices[t[1]];
    const auto& c = mesh.vertices[t[2]];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                         u[0] * w[1] - u[1] * w[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    dMin = std::min(dMin, (n[0] * a[0] + n[1] * a[1] + n[2] * a[2]) / length);
  }
  const double ball = 4.0 / 3.0 * std::numbers::pi;
  EXPECT_GT(closedness.signedVolume, ball * dMin * dMin * dMin);
  EXPECT_LT(closedness.signedVolume, ball);
}

// ---- closed-ness -----------------------------------------------------------------------------

TEST(MeshFile, OpenBoxIsRejectedNamingItsHole) {
  // Claim: a cube without its +z face (2 triangles) has the 4 rim edges of that face as
  // boundary edges; the message counts them and names the first (vertices 5 and 6, 1-based:
  // file vertices (0,0,1) and (1,0,1)).
  const test::TempFolder folder;
  sim::TriangleMesh box = test::boxMesh({0, 0, 0}, {1, 1, 1});
  box.triangles.resize(10);  // the last two triangles are the +z face
  const fs::path path = write(folder, "open.obj", test::objText(box));
  const sim::TriangleMesh mesh = readMeshFile(path);
  const MeshClosedness closedness = meshClosedness(mesh);
  EXPECT_EQ(closedness.boundaryEdges, 4u);
  EXPECT_EQ(closedness.nonManifoldEdges, 0u);
  EXPECT_EQ(closedness.misorientedEdges, 0u);
  EXPECT_FALSE(closedness.closed());
  try {
    requireClosedMesh(mesh, path);
    ADD_FAILURE() << "an open box was accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() +
                  ": expected a closed triangle mesh (every edge shared by exactly two triangles "
                  "that run along it in opposite directions), found 4 boundary edges (holes; the "
                  "first between vertices 5 and 6)");
  }
}

TEST(MeshFile, ClosedMeshErrorInASceneNamesTheSceneField) {
  // Claim: with a scene reference the message starts with the scene file and JSON path and
  // ends with the mesh file; PLY vertices are counted from 0. A flipped triangle makes its
  // three edges misoriented (each run the same way by both of its triangles).
  const test::TempFolder folder;
  sim::TriangleMesh box = test::boxMesh({0, 0, 0}, {1, 1, 1});
  std::swap(box.triangles[0][1], box.triangles[0][2]);
  const fs::path path = write(folder, "flip.ply", test::plyText(box, PlyEncoding::Ascii));
  const MeshReference reference{"tank.json", "solids[2].mesh"};
  try {
    requireClosedMesh(readMeshFile(path, reference), path, reference);
    ADD_FAILURE() << "a flipped triangle was accepted";
  } catch (const InputError& error) {
    test::expectInputError(error, "tank.json", "solids[2].mesh", "a closed triangle mesh",
                           ExpectedAt::RightAfterHead);
    EXPECT_TRUE(std::string(error.what())
                    .ends_with("found 3 edges where two triangles disagree in orientation (the "
                               "first between vertices 0 and 4) (" +
                               path.string() + ")"))
        << error.what();
  }
}

// ---- bad files -------------------------------------------------------------------------------

TEST(MeshFile, MissingFileFolderAndUnknownExtensionAreNamed) {
  const test::TempFolder folder;
  const fs::path missing = folder.path() / "nothing.obj";
  EXPECT_EQ(std::string(readError(missing).what()),
            missing.string() + ": expected a readable mesh file (OBJ or PLY), found no such file");
  fs::create_directory(folder.path() / "dir.obj");
  test::expectInputError(readError(folder.path() / "dir.obj"), (folder.path() / "dir.obj").string(),
                         "", "a readable mesh file (OBJ or PLY), found a folder",
                         ExpectedAt::RightAfterHead);
  const fs::path stl = write(folder, "glass.stl", "solid glass\n");
  test::expectInputError(readError(stl), stl.string(), "",
                         "a mesh file named *.obj or *.ply, found \".stl\"",
                         ExpectedAt::RightAfterHead);
}

TEST(MeshFile, MissingFileInASceneNamesTheSceneField) {
  const test::TempFolder folder;
  const fs::path missing = folder.path() / "pool.obj";
  const InputError error = readError(missing, {"scenes/tank.json", "liquid[0].mesh"});
  EXPECT_EQ(std::string(error.what()),
            "scenes/tank.json: liquid[0].mesh: expected a readable mesh file (OBJ or PLY), found "
            "no such file (" +
                missing.string() + ")");
}

TEST(MeshFile, EmptyFilesAreRejected) {
  const test::TempFolder folder;
  for (const char* name : {"empty.obj", "empty.ply"}) {
    const fs::path path = write(folder, name, "");
    test::expectInputError(readError(path), path.string(), "",
                           "a mesh with at least one triangle, found an empty file",
                           ExpectedAt::RightAfterHead);
  }
}

TEST(MeshFile, GarbledFilesAreRejected) {
  const test::TempFolder folder;
  // Binary bytes in an OBJ: tinyobjloader would skip them; we name the first control byte.
  const fs::path binary = write(folder, "binary.obj",
                                std::string("v 0 0 0\n\x7f"
                                            "ELF\x02\x01\x01",
                                            15));
  test::expectInputError(readError(binary), binary.string(), "line 2",
                         "an OBJ text file, found the control byte 0x02 (binary data)",
                         ExpectedAt::RightAfterHead);
  // Text without a single face.
  const fs::path prose = write(folder, "prose.obj", "this is not a mesh\nnor is this\n");
  test::expectInputError(readError(prose), prose.string(), "",
                         "a mesh with at least one triangle, found no faces (0 vertices)",
                         ExpectedAt::RightAfterHead);
  // A PLY without its magic line.
  const fs::path ply = write(folder, "garbled.ply", "garbage garbage\n");
  test::expectInputError(readError(ply), ply.string(), "",
                         "a PLY file starting with the line \"ply\", found \"garbage garbage\"",
                         ExpectedAt::RightAfterHead);
}

TEST(MeshFile, ObjVertexThatIsNotThreeFiniteNumbersIsNamedWithItsLine) {
  // tinyobjloader reads all of these as 0 (or drops the z) without a word; we reject each.
  const test::TempFolder folder;
  for (const char* bad : {"nan", "-inf", "1e39", "abc", "1,5"}) {
    const fs::path path =
        write(folder, "bad.obj", std::string("v 0 0 0\nv 1 0 0\nv ") + bad + " 1 0\nf 1 2 3\n");
    test::expectInputError(readError(path), path.string(), "line 3",
                           "a vertex \"v x y z\" of 3 finite numbers within float range "
                           "(|x| <= 3.4e38), found \"" +
                               std::string(bad) + "\" in \"v " + bad + " 1 0\"",
                           ExpectedAt::RightAfterHead);
  }
  const fs::path two = write(folder, "two.obj", "v 0 0 0\nv 1 0\nf 1 2 1\n");
  test::expectInputError(readError(two), two.string(), "line 2", "found \"v 1 0\"",
                         ExpectedAt::Anywhere);
}

TEST(MeshFile, NanVertexInAPlyIsNamed) {
  // Claim: a NaN coordinate, whatever the encoding, is an error naming the vertex (from 0).
  const test::TempFolder folder;
  sim::TriangleMesh mesh = test::boxMesh({0, 0, 0}, {1, 1, 1});
  mesh.vertices[3][1] = std::nanf("");
  for (const PlyEncoding encoding : {PlyEncoding::Ascii, PlyEncoding::BinaryBigEndian}) {
    const fs::path path = write(folder, "nan.ply", test::plyText(mesh, encoding));
    test::expectInputError(
        readError(path), path.string(), "vertex 3",
        "finite coordinates x, y, z within float range (|x| <= 3.4e38), found (1, nan, 0)",
        ExpectedAt::RightAfterHead);
  }
}

TEST(MeshFile, IndexOutOfRangeIsNamedWithItsFace) {
  const test::TempFolder folder;
  // OBJ: the face's line, even in a later group; 1-based as written.
  const fs::path obj =
      write(folder, "oor.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\ng a\nf 1 2 3\ng b\nf 3 2 7\n");
  test::expectInputError(readError(obj), obj.string(), "line 7",
                         "vertex indices from 1 to 3 (the file has 3 vertices), found \"f 3 2 7\"",
                         ExpectedAt::RightAfterHead);
  const fs::path back = write(folder, "back.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n");
  test::expectInputError(readError(back), back.string(), "line 4", "found \"f 1 2 -4\"",
                         ExpectedAt::Anywhere);
  // PLY: the face's number, 0-based as written.
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 3\n";
  const fs::path plyPath = write(folder, "oor.ply", ply);
  test::expectInputError(readError(plyPath), plyPath.string(), "face 1",
                         "vertex indices from 0 to 2 (the file has 3 vertices), found 3",
                         ExpectedAt::RightAfterHead);
}

// Claim: an index beyond 32 bits is refused, not wrapped onto another vertex. 4294967299 is
// 2^32 + 3: tinyobjloader's int wraps it to 3, so this face was read as "f 1 2 3" before. A PLY
// index list is of an integer type, each value checked against its type (2^32 for uint32).
TEST(MeshFile, IndexBeyond32BitsIsRejectedNotWrapped) {
  const test::TempFolder folder;
  const fs::path obj = write(folder, "wrap.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967299\n");
  test::expectInputError(readError(obj), obj.string(), "line 4",
                         "a face corner \"v\", \"v/vt\", \"v//vn\" or \"v/vt/vn\" of integer indices "
                         "within +-2147483647, found \"4294967299\" in \"f 1 2 4294967299\"",
                         ExpectedAt::RightAfterHead);
  const fs::path texture = write(folder, "vt.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/99999999999 2 3\n");
  test::expectInputError(readError(texture), texture.string(), "line 5", "found \"1/99999999999\"",
                         ExpectedAt::Anywhere);
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar uint vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967299\n";
  const fs::path plyPath = write(folder, "wrap.ply", ply);
  test::expectInputError(readError(plyPath), plyPath.string(), "face 0",
                         "a list entry of property \"vertex_indices\" (uint), found \"4294967299\"",
                         ExpectedAt::RightAfterHead);
}

TEST(MeshFile, FacesOfFewerThanThreeVerticesAreRejected) {
  const test::TempFolder folder;
  const fs::path obj = write(folder, "line.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n");
  test::expectInputError(readError(obj), obj.string(), "line 4",
                         "a face \"f\" of 3 to 255 vertices, found \"f 1 2\" (2 vertices)",
                         ExpectedAt::RightAfterHead);
  const fs::path zero = write(folder, "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n");
  test::expectInputError(readError(zero), zero.string(), "",
                         "a valid OBJ file, found \"Failed parse", ExpectedAt::RightAfterHead);
  const std::string ply =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n2 0 1\n";
  const fs::path plyPath = write(folder, "line.ply", ply);
  test::expectInputError(readError(plyPath), plyPath.string(), "face 0",
                         "a face of at least 3 vertex indices, found 2 indices",
                         ExpectedAt::RightAfterHead);
}

TEST(MeshFile, TruncatedPlyFilesEndInAnErrorNotAHang) {
  // Debian's Assimp 5.2.5 loops forever on the first file and aborts on the second; both must
  // be one InputError here.
  const test::TempFolder folder;
  const std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\n"
      "property list uchar int vertex_indices\nend_header\n";
  const fs::path cutHeader = write(folder, "head.ply", header.substr(0, 60));
  test::expectInputError(readError(cutHeader), cutHeader.string(), "",
                         "a PLY header ending in a line \"end_header\", found end of file after 3 "
                         "header lines",
                         ExpectedAt::RightAfterHead);
  const fs::path cutData = write(folder, "data.ply", header + std::string(30, '\0'));
  test::expectInputError(readError(cutData), cutData.string(), "vertex 2",
                         "a value of property \"y\" (float), found end of file",
                         ExpectedAt::RightAfterHead);
  const fs::path cutList = write(folder, "list.ply", header + std::string(36, '\0') + "\x03");
  test::expectInputError(readError(cutList), cutList.string(), "face 0",
                         "a list entry of property \"vertex_indices\" (int), found end of file",
                         ExpectedAt::RightAfterHead);
}

TEST(MeshFile, MalformedPlyHeadersAndValuesAreNamed) {
  const test::TempFolder folder;
  const auto expectPly = [&](const std::string& text, const std::string& location,
                             const std::string& expected) {
    const fs::path path = write(folder, "bad.ply", text);
    test::expectInputError(readError(path), path.string(), location, expected,
                           ExpectedAt::RightAfterHead);
  };
  expectPly("ply\nformat binary 1.0\nend_header\n", "line 2",
            "\"format ascii 1.0\", \"format binary_little_endian 1.0\" or \"format "
            "binary_big_endian 1.0\", found \"format binary 1.0\"");
  expectPly("ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n", "line 4",
            "\"property TYPE NAME\" with TYPE one of");
  expectPly("ply\nformat ascii 1.0\nelement vertex -1\nend_header\n", "line 3",
            "\"element NAME COUNT\" with a whole COUNT >= 0, found \"element vertex -1\"");
  expectPly(
      "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 "
      "0\n",
      "", "an element \"vertex\" with scalar properties x, y and z, found no scalar property z");
  expectPly(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 one 0\n3 0 1 2\n",
      "vertex 2", "a value of property \"y\" (float), found \"one\"");
  expectPly(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2.5\n",
      "face 0", "a list entry of property \"vertex_indices\" (int), found \"2.5\"");
}

}  // namespace
}  // namespace fluidsound::io
