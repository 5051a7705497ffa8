// io/mesh_file.h — reads the triangle meshes a scene names (`liquid[i].mesh`, `solids[i].mesh`)
// from OBJ or PLY files into sim::TriangleMesh, checking what the simulation relies on.
#pragma once

#include <filesystem>
#include <string>

#include "io/mesh_closedness.h"
#include "sim/fluid/triangle_mesh.h"

namespace fluidsound::io {

/// Where a mesh file was named, so that its errors point at the scene's field.
struct MeshReference {
  std::string sceneFile;  ///< the scene file as given (Scene::file); empty: read on its own
  std::string jsonPath;   ///< e.g. `solids[2].mesh`; empty: read on its own
};

/// @brief Reads a triangle mesh from an OBJ or PLY file (chosen by the extension, any case).
///        - OBJ (tinyobjloader): `v x y z` vertices and `f` faces (`i`, `i/t`, `i//n`, `i/t/n`,
///          negative indices counting back from the last vertex); polygons of 3 to 255 corners
///          are split into a fan of triangles (v0, vk, vk+1); every other statement (normals,
///          texture coordinates, groups, materials, lines, points) is ignored, `mtllib` files
///          are not opened.
///        - PLY (our reader; Assimp 5.2.5 hangs or aborts on truncated PLY files): `ascii`,
///          `binary_little_endian` or `binary_big_endian` 1.0; element `vertex` with scalar
///          properties x, y, z of any numeric type; element `face` with a list property
///          `vertex_indices` (or `vertex_index`), polygons split into fans as for OBJ; other
///          elements and properties are read and skipped.
///        Vertices and triangles are kept in file order (a vertex is not merged with another at
///        the same position; meshClosedness merges them for its test).
/// @param path       the mesh file; named in messages as given
/// @param reference  the scene field that named the file, if any (see @throws)
/// @return the mesh: at least one triangle, finite vertices (float), indices in range
/// @throws InputError at the first problem. Without a reference the message is
///         `MESH: LOCATION: expected …, found …` with LOCATION `line 4` (OBJ), `vertex 3` or
///         `face 2` (PLY, counted from 0 as PLY indices are), or none for the whole file; with a
///         reference it is `SCENE: JSON_PATH: expected …, found … (MESH, LOCATION)`. Problems: the
///         file is missing, a folder or unreadable; an extension other than .obj or .ply; a
///         malformed file (an OBJ vertex without 3 finite numbers, an OBJ statement the parser
///         rejects, a PLY header or value that does not parse, a file that ends early); a face
///         of fewer than 3 (or, in OBJ, more than 255) vertices; a vertex index out of range; a
///         coordinate that is NaN, infinite or beyond float range; no triangle at all.
sim::TriangleMesh readMeshFile(const std::filesystem::path& path,
                               const MeshReference& reference = {});

/// @brief Requires a closed mesh (MeshClosedness::closed: every edge shared by exactly two
///        triangles running along it in opposite directions).
///
///        Policy. Liquid meshes must be closed: the liquid is the volume inside. Solid meshes
///        must be closed too, for now: the signed distance (sim/fluid/mesh_distance.h, OpenVDB's
///        flood-filled sign) of a mesh with a hole loses its inside, the outside flooding in
///        through the hole (a box missing one triangle has no negative node left; test
///        MeshDistance.OpenBoxLosesItsInside), and a silent repair (OpenVDB's unsigned distance
///        with a winding-number sign) would change the geometry the user gave without a word. Open
///        or one-sided obstacles (a sheet, a glass modelled without thickness) belong to the
///        thin-obstacle task (ray queries), not to this check.
/// @param mesh       a mesh from readMeshFile(path, reference)
/// @param path       its file, for the message (OBJ vertices are counted from 1, PLY from 0)
/// @param reference  as for readMeshFile
/// @return the diagnosis (closed; its signedVolume is the enclosed volume [file units³])
/// @throws InputError naming each kind of bad edge with its count and first edge, e.g.
///         `pool.obj: expected a closed triangle mesh (every edge shared by exactly two triangles
///         that run along it in opposite directions), found 4 boundary edges (holes; the first
///         between vertices 5 and 6)`
MeshClosedness requireClosedMesh(const sim::TriangleMesh& mesh,
                                      const std::filesystem::path& path,
                                      const MeshReference& reference = {});

}  // namespace fluidsound::io
