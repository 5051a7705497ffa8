// io/frame_vdb.cpp — frames/NNNN.vdb (see frame_files.h). Its own file: instantiating
// ParticlesToLevelSet takes about a minute to compile (docs/toolchain facts).
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetFilter.h>
#include <openvdb/tools/ParticlesToLevelSet.h>

#include <fstream>
#include <iterator>
#include <string>

#include "io/atomic_file.h"
#include "io/frame_files.h"
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

}  // namespace

void writeFrameVdb(const std::filesystem::path& path, const sim::GridGeometry& grid,
                   const sim::Particles& particles, const sim::MacVelocity& velocity,
                   const SurfaceSettings& surface, const FrameStamp& stamp) {
  openvdb::initialize();  // registers OpenVDB's types; repeated calls do nothing
  const double h = grid.cellSize;
  // Voxel centres coincide with the solver's cell centres.
  const auto transform = openvdb::math::Transform::createLinearTransform(h);
  transform->postTranslate(openvdb::Vec3d(grid.origin[0] + 0.5 * h, grid.origin[1] + 0.5 * h,
                                          grid.origin[2] + 0.5 * h));

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

  openvdb::Vec3fGrid::Ptr cellVelocity = openvdb::Vec3fGrid::create();
  cellVelocity->setTransform(transform);
  cellVelocity->setName("velocity");
  cellVelocity->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
  auto accessor = cellVelocity->getAccessor();
  // Velocity where the level set has active voxels (the liquid and its band), averaged from faces.
  for (auto it = level->cbeginValueOn(); it; ++it) {
    const openvdb::Coord c = it.getCoord();
    if (c.x() < 0 || c.y() < 0 || c.z() < 0 || c.x() >= grid.cells[0] || c.y() >= grid.cells[1] ||
        c.z() >= grid.cells[2])
      continue;
    const openvdb::Vec3f v(0.5f * (velocity[0](c.x(), c.y(), c.z()) + velocity[0](c.x() + 1, c.y(), c.z())),
                           0.5f * (velocity[1](c.x(), c.y(), c.z()) + velocity[1](c.x(), c.y() + 1, c.z())),
                           0.5f * (velocity[2](c.x(), c.y(), c.z()) + velocity[2](c.x(), c.y(), c.z() + 1)));
    accessor.setValue(c, v);
  }

  // OpenVDB writes its file format only to a seekable file: a frame for a device or a FIFO is
  // composed in a temporary of the system's temporary folder, then its bytes are written through.
  const OutputTarget target = resolveOutput(path);
  const bool replace = target.kind == OutputKind::Replace;
  AtomicFile out(replace ? path : std::filesystem::temp_directory_path() / "fluidsound-frame.vdb");
  try {
    openvdb::io::File file(out.temporaryPath().string());
    level->setCreator(stamp.creator);
    cellVelocity->setCreator(stamp.creator);
    openvdb::MetaMap meta;
    meta.insertMeta("fps", openvdb::DoubleMetadata(stamp.fps));
    meta.insertMeta("frame", openvdb::Int32Metadata(stamp.frame));
    meta.insertMeta("time", openvdb::DoubleMetadata(stamp.time));
    meta.insertMeta("units", openvdb::StringMetadata("m"));
    meta.insertMeta("up_axis", openvdb::StringMetadata("y"));
    file.write({level, cellVelocity}, meta);
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

}  // namespace fluidsound::io
