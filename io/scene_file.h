// io/scene_file.h — reads `fluidsound.scene/1` (DESIGN.md; docs/scene.md) into sim::Scene,
// validating every field; errors name the file, the JSON path and what was expected.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "sim/scene.h"

namespace fluidsound::io {

/// @brief Parses and validates a `fluidsound.scene/1` document (docs/scene.md): JSON, SI units,
///        y up. Absent optional fields take their documented defaults (gravity [0, −9.81, 0] m/s²,
///        30 fps, CFL 1, seed 1, sample rate 48000 Hz, one listener named "listener" 0.5 m above
///        the domain centre, the SolverSettings defaults).
/// @param text  the JSON text
/// @param file  the scene file's path: named in error messages as given, stored in Scene::file,
///              and the folder of mesh paths (`liquid[i].mesh`, `solids[i].mesh`), which are
///              stored resolved (`folder / path`, lexically normalised)
/// @return the scene; emitter normals are unit vectors, Domain::open is in the order
///         −x, +x, −y, +y, −z, +z
/// @throws InputError at the first problem, naming the file, the JSON path (`solids[2].path[1].t`)
///         and what was expected: malformed JSON, a key given twice in one object, a wrong or
///         missing "format" (checked first), an unknown key (with the closest known key), a
///         missing required field, a value of the wrong type or range, a domain extent that is
///         not a whole number of cells (2 … 1024 per axis), a liquid or solid item without
///         exactly one shape, unsorted path keys, duplicate listener names, or a mesh file that
///         does not exist or cannot be read
/// @note Meshes are not loaded here (only opened); shapes may lie partly or wholly outside the
///       domain (the simulation clips them).
sim::Scene parseScene(std::string_view text, const std::filesystem::path& file);

/// @brief Reads and parses a scene file.
/// @throws InputError if the file is missing, a folder or unreadable, or as parseScene
sim::Scene readScene(const std::filesystem::path& path);

/// @brief The scene with another grid cell size: the `--cell` override of `fluidsound simulate`
///        and `run` (docs/cli.md), checked by the rules of `domain.cell` (docs/scene.md: > 0,
///        each extent a whole number of cells within a relative 10⁻⁶, 2 … 1024 cells per axis).
///        Before or after io/scene_meshes.h reads the meshes: the solver computes their
///        distances on its own grid (sim/fluid/scene_mesh_distances.h).
/// @param scene   a parsed scene
/// @param cell    the new cell size [m]
/// @param source  what the error names in place of the file and JSON path, e.g. "--cell"
/// @throws InputError with no file and `source` as the field, e.g. `--cell: expected a cell size
///         (metres) that divides the extent along x (0.6 m) into a whole number of cells, such as
///         0.006976744186 (86 cells), found 0.007 (85.7143 cells)`
sim::Scene withCellSize(sim::Scene scene, double cell, const std::string& source);

}  // namespace fluidsound::io
