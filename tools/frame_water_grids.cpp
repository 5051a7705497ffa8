// tools/frame_water_grids.cpp — see frame_water_grids.h.
#include "tools/frame_water_grids.h"

#include <cmath>
#include <string>
#include <utility>

#include "io/frame_folder.h"
#include "io/frame_surface.h"
#include "io/input_error.h"
#include "io/json_validation.h"
#include "io/scene_file.h"
#include "sim/fluid/solid_boundary.h"

namespace fluidsound::tools {
namespace {

/// Voxel sizes of two frames of one simulation agree to this relative tolerance (both are the
/// double the solver's grid had, written into the VDB transform).
constexpr double kVoxelSizeTolerance = 1e-9;

std::filesystem::path framePath(const std::filesystem::path& outdir, int frame) {
  return outdir / "frames" / io::frameFileName(frame, "vdb");
}

/// The scene at `cellSize` by the rules of domain.cell, an error naming `source` otherwise.
sim::Scene atCellSize(const sim::Scene& scene, double cellSize, const std::string& source) {
  try {
    return io::withCellSize(scene, cellSize, "voxel size");
  } catch (const io::InputError& e) {
    throw io::InputError(source, "voxel size", e.expected(), e.found());
  }
}

}  // namespace

double simulatedCellSize(const sim::Scene& scene, const std::filesystem::path& outdir, int frame) {
  const std::filesystem::path path = framePath(outdir, frame);
  const double h = io::FrameLevelSet(path).voxelSize();
  atCellSize(scene, h, path.string());
  return h;
}

FrameFolderWaterGrids::FrameFolderWaterGrids(const sim::Scene& scene, std::filesystem::path outdir,
                                             double cellSize)
    : scene_(atCellSize(scene, cellSize, scene.file.string())),
      outdir_(std::move(outdir)),
      grid_(scene_.grid()) {
  scene_.liquid.clear();  // the solids' distances only: the liquid comes from each frame
  meshes_ = sim::sceneMeshDistances(scene_, grid_);
  rays_ = sim::SolidMeshRays(scene_.solids);
}

/// Each cell's open volume fraction: the share of 4³ points inside it where the scene solids'
/// node distance (trilinear, negative inside a solid) is positive. The water side's −k² term
/// weighs each cell by it, which places a floor between two faces where it is (docs/transfer.md).
std::vector<float> FrameFolderWaterGrids::openVolumeFractions(const sim::Array3f& nodeDistance,
                                                              const acoustics::WaterGrid& water) {
  constexpr int n = 4;
  std::vector<float> open(water.cellCount());
  for (int k = 0; k < water.cells[2]; ++k)
    for (int j = 0; j < water.cells[1]; ++j)
      for (int i = 0; i < water.cells[0]; ++i) {
        int outside = 0;
        for (int c = 0; c < n; ++c)
          for (int b = 0; b < n; ++b)
            for (int a = 0; a < n; ++a) {
              const double x = (a + 0.5) / n, y = (b + 0.5) / n, z = (c + 0.5) / n;
              double d = 0.0;
              for (int corner = 0; corner < 8; ++corner) {
                const int di = corner & 1, dj = (corner >> 1) & 1, dk = (corner >> 2) & 1;
                d += (di ? x : 1 - x) * (dj ? y : 1 - y) * (dk ? z : 1 - z) *
                     nodeDistance(i + di, j + dj, k + dk);
              }
              outside += d > 0.0 ? 1 : 0;
            }
        open[water.cellIndex(i, j, k)] = static_cast<float>(outside) / (n * n * n);
      }
  return open;
}

acoustics::WaterGrid FrameFolderWaterGrids::open(int frame) const {
  const std::filesystem::path path = framePath(outdir_, frame);
  const io::FrameLevelSet levelSet(path);
  const double h = levelSet.voxelSize();
  if (!(std::abs(h - grid_.cellSize) <= kVoxelSizeTolerance * grid_.cellSize))
    throw io::InputError(
        path.string(), "surface",
        "a level set with the simulation's voxel size, " + io::formatNumber(grid_.cellSize) + " m",
        io::formatNumber(h) + " m");
  acoustics::WaterGrid water;
  water.cells = grid_.cells;
  water.cellSize = grid_.cellSize;
  water.origin = grid_.origin;
  water.phi.resize(water.cellCount());
  for (int k = 0; k < grid_.cells[2]; ++k)
    for (int j = 0; j < grid_.cells[1]; ++j)
      for (int i = 0; i < grid_.cells[0]; ++i)
        water.phi[water.cellIndex(i, j, k)] =
            static_cast<float>(levelSet.phi(grid_.cellCentre(i, j, k)));
  const sim::SolidBoundary solids = sim::solidBoundaryAt(grid_, scene_.domain, scene_.solids, rays_,
                                                         frame / scene_.time.fps, meshes_.solids);
  // sim::Array3 and WaterGrid index faces alike (x fastest, one more along the face's axis).
  for (int a = 0; a < 3; ++a) water.faceOpen[a] = solids.faceOpen[a].values();
  water.cellOpen = openVolumeFractions(solids.sceneNodeDistance, water);
  water.openSides = scene_.domain.open;
  return water;
}

}  // namespace fluidsound::tools
