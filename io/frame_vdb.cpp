// io/frame_vdb.cpp — frames/NNNN.vdb (see frame_files.h). Its own file: instantiating
// ParticlesToLevelSet takes about a minute to compile (docs/toolchain facts).
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <cmath>

#include <fstream>
#include <iterator>
#include <string>

#include "io/atomic_file.h"
#include "io/frame_files.h"
#include "io/frame_points.h"
#include "io/input_error.h"
#include "io/output_file.h"

namespace fluidsound::io {
namespace {

/// The particle list interface ParticlesToLevelSet expects (OpenVDB tools/ParticlesToLevelSet.h).
class ParticleList {
 public:
  using PosType = openvdb::Vec3R;
  ParticleList(const sim::Particles& particles, double radius) : particles_(particles), radius_(radius) {}
  size_t size() const { return particles_.size(); }
  void getPos(size_t n, openvdb::Vec3R& xyz) const {
    const sim::Vec3f& p = particles_.position[n];
    xyz = openvdb::Vec3R(p[0], p[1], p[2]);
  }
  void getPosRad(size_t n, openvdb::Vec3R& xyz, openvdb::Real& radius) const {
    getPos(n, xyz);
    radius = radius_;
  }

 private:
  const sim::Particles& particles_;
  double radius_;
};


/// Voxel centres on the solver's cell centres.
openvdb::math::Transform::Ptr cellTransform(const sim::GridGeometry& grid) {
  const double h = grid.cellSize;
  const auto transform = openvdb::math::Transform::createLinearTransform(h);
  transform->postTranslate(openvdb::Vec3d(grid.origin[0] + 0.5 * h, grid.origin[1] + 0.5 * h,
                                          grid.origin[2] + 0.5 * h));
  return transform;
}

/// The MAC velocity as a staggered grid (OpenVDB's GRID_STAGGERED, as Houdini's FLIP writes `vel`):
/// voxel (i, j, k) holds the u, v, w of the faces on its low x, y and z sides, which are exactly the
/// solver's faces (i, j, k). Written in every cell of the liquid and its band (the level set below
/// its outside background: the interior's inactive tiles too) and in the cell above each of those
/// on every axis (its low face is the liquid's high face), so a cache reader finds the liquid's
/// velocity wherever a bubble can be.
openvdb::Vec3fGrid::Ptr cellVelocityGrid(const openvdb::FloatGrid& level, const sim::GridGeometry& grid,
                                         const sim::MacVelocity& velocity) {
  openvdb::Vec3fGrid::Ptr faces = openvdb::Vec3fGrid::create();
  faces->setTransform(level.transform().copy());
  faces->setName("velocity");
  faces->setGridClass(openvdb::GRID_STAGGERED);
  faces->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
  auto accessor = faces->getAccessor();
  auto inside = level.getConstAccessor();
  const float outside = level.background();
  const auto liquid = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < grid.cells[0] && j < grid.cells[1] && k < grid.cells[2] &&
           inside.getValue(openvdb::Coord(i, j, k)) < outside;
  };
  for (int k = 0; k <= grid.cells[2]; ++k)
    for (int j = 0; j <= grid.cells[1]; ++j)
      for (int i = 0; i <= grid.cells[0]; ++i) {
        if (!(liquid(i, j, k) || liquid(i - 1, j, k) || liquid(i, j - 1, k) || liquid(i, j, k - 1))) continue;
        const auto face = [&](int axis) {
          const sim::Array3f& u = velocity[axis];
          return u.contains(i, j, k) ? u(i, j, k) : 0.0f;
        };
        accessor.setValue(openvdb::Coord(i, j, k), openvdb::Vec3f(face(0), face(1), face(2)));
      }
  return faces;
}

/// A level set named `name` from φ at the cell centres [m]: the values within the band, ± the band
/// beyond (signed flood fill).
openvdb::FloatGrid::Ptr cellLevelSet(const sim::GridGeometry& grid, const sim::Array3f& phi, int halfWidthVoxels,
                                     const std::string& name) {
  openvdb::FloatGrid::Ptr level = openvdb::createLevelSet<openvdb::FloatGrid>(grid.cellSize, halfWidthVoxels);
  level->setTransform(cellTransform(grid));
  level->setName(name);
  const float band = level->background();
  auto accessor = level->getAccessor();
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i)
        if (std::abs(phi(i, j, k)) < band) accessor.setValue(openvdb::Coord(i, j, k), phi(i, j, k));
  openvdb::tools::signedFloodFill(level->tree());
  return level;
}

/// Writes `grids` with the frame's metadata to `path` by the output rule.
void writeFrameGrids(const std::filesystem::path& path, const openvdb::GridPtrVec& grids, const FrameStamp& stamp) {
  // OpenVDB writes its file format only to a seekable file: a frame for a device or a FIFO is
  // composed in a temporary of the system's temporary folder, then its bytes are written through.
  const OutputTarget target = resolveOutput(path);
  const bool replace = target.kind == OutputKind::Replace;
  AtomicFile out(replace ? path : std::filesystem::temp_directory_path() / "fluidsound-frame.vdb");
  try {
    openvdb::io::File file(out.temporaryPath().string());
    for (const openvdb::GridBase::Ptr& grid : grids) grid->setCreator(stamp.creator);
    openvdb::MetaMap meta;
    meta.insertMeta("fps", openvdb::DoubleMetadata(stamp.fps));
    meta.insertMeta("frame", openvdb::Int32Metadata(stamp.frame));
    meta.insertMeta("time", openvdb::DoubleMetadata(stamp.time));
    meta.insertMeta("units", openvdb::StringMetadata("m"));
    meta.insertMeta("up_axis", openvdb::StringMetadata("y"));
    file.write(grids, meta);
    file.close();
  } catch (const openvdb::Exception& e) {
    throw OutputError(path.string() + ": cannot write the VDB file: " + e.what());
  }
  if (replace) {
    out.commit();
  } else {
    std::ifstream composed(out.temporaryPath(), std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(composed)),
                            std::istreambuf_iterator<char>());
    if (!composed)
      throw OutputError(path.string() + ": cannot write: the composed frame cannot be read back");
    writeOutputFile(path, bytes);
  }
}

}  // namespace

void writeFrameVdb(const std::filesystem::path& path, const sim::GridGeometry& grid,
                   const sim::Particles& particles, const sim::MacVelocity& velocity,
                   const SurfaceSettings& surface, const FrameStamp& stamp) {
  openvdb::initialize();  // registers OpenVDB's types; repeated calls do nothing
  const double h = grid.cellSize;
  const auto transform = cellTransform(grid);
  openvdb::FloatGrid::Ptr level = openvdb::createLevelSet<openvdb::FloatGrid>(h, surface.halfWidthVoxels);
  level->setTransform(transform);
  level->setName("surface");
  openvdb::tools::ParticlesToLevelSet<openvdb::FloatGrid> raster(*level);
  // Spheres of twice the particle radius overlap at the particle spacing (2r), so the union has
  // no holes; eroding by r afterwards would put the surface back where the particles' own radius
  // says, which for a seeded layer is 0.21 h below its top (the top particles sit in the middle
  // of the top sub-cells: measured, tests/io/frame_surface_test.cpp). Eroding 0.2 h less puts a
  // flat surface where the liquid is (measured 0.01 h low).
  // OpenVDB skips spheres below 1.5 voxels by default; ours are ~0.5 voxel, so no minimum.
  constexpr double kRasterRadiusFactor = 2.0;
  raster.setRmin(0.0);
  raster.rasterizeSpheres(ParticleList(particles, kRasterRadiusFactor * surface.particleRadius));
  raster.finalize(true);
  openvdb::tools::LevelSetFilter<openvdb::FloatGrid> filter(*level);
  for (int i = 0; i < surface.smoothingIterations; ++i) filter.mean();
  constexpr double kLayerTopLiftCells = 0.2;
  filter.offset(static_cast<float>((kRasterRadiusFactor - 1.0) * surface.particleRadius - kLayerTopLiftCells * h));
  writeFrameGrids(path, {level, cellVelocityGrid(*level, grid, velocity), particlePointGrid(particles, transform)},
                  stamp);
}

void writeLevelSetFrameVdb(const std::filesystem::path& path, const sim::GridGeometry& grid, const sim::Array3f& phi,
                           const sim::MacVelocity& velocity, int halfWidthVoxels, const FrameStamp& stamp) {
  openvdb::initialize();
  const openvdb::FloatGrid::Ptr level = cellLevelSet(grid, phi, halfWidthVoxels, "surface");
  writeFrameGrids(path, {level, cellVelocityGrid(*level, grid, velocity)}, stamp);
}

}  // namespace fluidsound::io
