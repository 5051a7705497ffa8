// io/frame_files.h — the per-frame artefacts of the simulation (DESIGN.md): frames/NNNN.vdb with
// the liquid level set `surface` (narrow band, negative inside), `velocity` (cell centres, in the
// liquid and its band) and the particles as OpenVDB points `points` (P, v, id), and
// frames/NNNN.ply with the particles (binary little-endian, float x y z vx vy vz, uint id). Both written
// atomically, readable by Houdini, Blender and OpenVDB's tools.
#pragma once

#include <filesystem>
#include <string>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particles.h"

namespace fluidsound::io {

/// Settings of the level set built from the particles.
struct SurfaceSettings {
  double particleRadius = 0.0;  ///< r [m]; the surface is the union of particle spheres, smoothed
  int halfWidthVoxels = 3;      ///< narrow-band half width [voxels]
  int smoothingIterations = 1;  ///< mean-value filter passes over the band (0: none)
};

/// Which frame a file holds, for the metadata Houdini and Blender show (docs/import.md).
struct FrameStamp {
  int frame = 0;
  double time = 0.0;   ///< [s]
  double fps = 30.0;   ///< frames per second
  std::string creator = "fluidsound";  ///< the program and its version
};

/// @brief Builds the surface (OpenVDB ParticlesToLevelSet on the solver's cell size, then a
///        smoothing filter), the cell-centred velocity and the particles as points
///        (frame_points.h), and writes them to `path`, with file metadata `fps`, `frame`, `time` [s], `units` ("m"), `up_axis` ("y") and each grid's
///        `creator`.
/// @throws OutputError if the file cannot be written
void writeFrameVdb(const std::filesystem::path& path, const sim::GridGeometry& grid,
                   const sim::Particles& particles, const sim::MacVelocity& velocity,
                   const SurfaceSettings& surface, const FrameStamp& stamp = {});

/// @brief Writes a frame of the import (`from-cache`): `surface` from φ at the cell centres [m]
///        (the values within halfWidthVoxels of the surface; beyond, ± the band), `velocity` as
///        writeFrameVdb's; no points. The same metadata.
/// @throws OutputError if the file cannot be written
void writeLevelSetFrameVdb(const std::filesystem::path& path, const sim::GridGeometry& grid, const sim::Array3f& phi,
                           const sim::MacVelocity& velocity, int halfWidthVoxels, const FrameStamp& stamp = {});

/// @brief Writes the particles as a binary little-endian PLY: one vertex per particle with float
///        properties x y z vx vy vz and uint id (the particle's stable id, particle_ids.h, which
///        a cache reader follows from frame to frame).
/// @throws OutputError if the file cannot be written
void writeParticlesPly(const std::filesystem::path& path, const sim::Particles& particles);

}  // namespace fluidsound::io
