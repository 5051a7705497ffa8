// tools/frame_water_grids.h — the frames `fluidsound simulate` wrote into OUTDIR as the geometric
// transfer's water grids (acoustics::FrameWaterGrids, acoustics/transfer/water_grid.h): frame f's
// liquid level set (frames/NNNN.vdb, io/frame_surface.h) at the solver grid's cell centres, and
// the scene's solids at the frame's time t = f / fps as the pressure projection sees them
// (sim::solidBoundaryAt: open face fractions, faces across thin mesh walls closed).
// docs/transfer.md, "The water grid of a frame".
#pragma once

#include <filesystem>

#include "acoustics/transfer/water_grid.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/scene_mesh_distances.h"
#include "sim/fluid/solid_mesh_rays.h"
#include "sim/scene.h"

namespace fluidsound::tools {

/// @brief The cell size [m] the simulation in `outdir` ran at: the voxel size of frame `frame`'s
///        level set (simulate may have run with --cell), checked by the rules of domain.cell
///        against the scene's domain (a whole number of cells per axis, 2 … 1024).
/// @throws io::InputError naming the frame file for a missing or damaged frame or a voxel size
///         that does not divide the domain
double simulatedCellSize(const sim::Scene& scene, const std::filesystem::path& outdir, int frame);

class FrameFolderWaterGrids : public acoustics::FrameWaterGrids {
 public:
  /// Builds the grid (the scene's domain at `cellSize`), the mesh solids' node distances on it
  /// and their ray queries, once for every frame.
  /// @param scene     its mesh solids read (io::loadSceneMeshes); copied
  /// @param cellSize  the simulation's cell size [m] (simulatedCellSize)
  /// @throws io::InputError if `cellSize` does not divide the domain
  FrameFolderWaterGrids(const sim::Scene& scene, std::filesystem::path outdir, double cellSize);

  /// @brief Frame `frame`'s water grid: φ at every cell centre (the level set's trilinear value,
  ///        < 0 in the liquid), the open face fractions at t = frame / fps, and the open grid
  ///        sides: those of the domain's faces listed in domain.open (docs/transfer.md).
  ///        Safe from several threads at once (reads only what the constructor built).
  /// @throws io::InputError naming the frame file for a missing or damaged frame or one whose
  ///         voxel size is not the simulation's
  acoustics::WaterGrid open(int frame) const override;

  const sim::GridGeometry& grid() const { return grid_; }

 private:
  static std::vector<float> openVolumeFractions(const sim::Array3f& nodeDistance,
                                                const acoustics::WaterGrid& water);
  sim::Scene scene_;  ///< at the simulation's cell size, its liquid regions dropped
  std::filesystem::path outdir_;
  sim::GridGeometry grid_;
  sim::SceneMeshDistances meshes_;
  sim::SolidMeshRays rays_;
};

}  // namespace fluidsound::tools
