// tests/io/cache_frame_test.cpp — a liquid cache's frame checked before the bubble model reads it
// (io/cache_frame.h; issue 21): fluidsound's own frames and Houdini's grid names pass; a grid
// missing, of the wrong type, with non-uniform voxels, on another transform or holding a NaN is
// one error naming the file and the grid.
#include "io/cache_frame.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include <limits>
#include <string>

#include "io/frame_files.h"
#include "io/input_error.h"
#include "sim/fluid/fluid_solver.h"
#include "sim/scene.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

/// A level set sphere of radius 2 cm at 5 mm voxels named `surfaceName`, and a velocity grid of
/// type VelocityGrid named `velocityName` on `velocityVoxel` (5 mm: the same transform).
template <class VelocityGrid = openvdb::Vec3SGrid>
fs::path writeFrame(const fs::path& path, const std::string& surfaceName, const std::string& velocityName,
                    double velocityVoxel = 0.005) {
  openvdb::initialize();
  openvdb::FloatGrid::Ptr surface =
      openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.02f, openvdb::Vec3f(0.0f), 0.005f);
  surface->setName(surfaceName);
  typename VelocityGrid::Ptr velocity = VelocityGrid::create();
  velocity->setTransform(openvdb::math::Transform::createLinearTransform(velocityVoxel));
  velocity->setName(velocityName);
  velocity->tree().setValue(openvdb::Coord(1, 2, 3), typename VelocityGrid::ValueType(0.1, 0.0, -0.2));
  openvdb::io::File(path.string()).write({surface, velocity});
  return path;
}

std::string errorOf(const fs::path& path, const CacheGridNames& names = {}) {
  try {
    checkCacheFrame(path, names);
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    EXPECT_EQ(e.file(), path.string());
    return e.what();
  }
  ADD_FAILURE() << "no error for " << path;
  return {};
}

TEST(CacheFrame, OurOwnFramesAndHoudinisNamesPass) {
  test::TempFolder folder;
  sim::Scene scene;
  scene.domain.max = {0.04, 0.04, 0.04};
  scene.domain.cell = 0.005;
  scene.time.duration = 1.0;
  scene.liquid.push_back({sim::Box{{0, 0, 0}, {0.04, 0.02, 0.04}}, {}});
  const sim::FluidSolver solver(scene);
  const fs::path ours = folder.path() / "0000.vdb";
  writeFrameVdb(ours, solver.grid(), solver.particles(), solver.velocity(), {solver.particleRadius()});
  const CacheFrameGrids found = checkCacheFrame(ours, {});
  EXPECT_EQ(found.surface, "surface");
  EXPECT_EQ(found.velocity, "velocity");
  EXPECT_NEAR(found.voxelSize, 0.005, 1e-12);
  const CacheFrameGrids houdini = checkCacheFrame(writeFrame(folder.path() / "h.vdb", "surface", "vel"), {});
  EXPECT_EQ(houdini.velocity, "vel");
  // Doubles for the velocity, and names given by the cache file.
  const CacheFrameGrids named = checkCacheFrame(
      writeFrame<openvdb::Vec3DGrid>(folder.path() / "b.vdb", "liquid", "flow"), {{"liquid"}, {"flow"}});
  EXPECT_EQ(named.surface, "liquid");
}

TEST(CacheFrame, EachProblemIsOneErrorNamingTheGrid) {
  test::TempFolder folder;
  const std::string missing = errorOf(writeFrame(folder.path() / "m.vdb", "density", "vel"));
  EXPECT_NE(missing.find("surface: expected a level set grid named surface, found grids density, vel"), std::string::npos)
      << missing;
  const std::string noVelocity = errorOf(writeFrame(folder.path() / "n.vdb", "surface", "v"));
  EXPECT_NE(noVelocity.find("vel: expected a velocity grid named vel or velocity"), std::string::npos) << noVelocity;
  // The level set's name on a vector grid, and the velocity's on a float grid.
  const std::string type = errorOf(writeFrame(folder.path() / "t.vdb", "phi", "vel"), {{"vel"}, {"phi"}});
  EXPECT_NE(type.find("vel: expected a FloatGrid (a level set), found a vec3s grid"), std::string::npos) << type;
  const std::string velocityType = errorOf(writeFrame(folder.path() / "t.vdb", "phi", "vel"), {{"phi"}, {"phi"}});
  EXPECT_NE(velocityType.find("phi: expected a Vec3 float or double grid (a velocity), found a float grid"),
            std::string::npos)
      << velocityType;
  // A grid named surface that is no FloatGrid is refused by the file check already.
  const std::string surfaceType = errorOf(writeFrame(folder.path() / "u.vdb", "phi", "surface"));
  EXPECT_NE(surfaceType.find("expected a FloatGrid"), std::string::npos) << surfaceType;
  const std::string transform = errorOf(writeFrame(folder.path() / "x.vdb", "surface", "vel", 0.01));
  EXPECT_NE(transform.find("vel: expected the transform of surface"), std::string::npos) << transform;

  openvdb::FloatGrid::Ptr stretched =
      openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.02f, openvdb::Vec3f(0.0f), 0.005f);
  stretched->setName("surface");
  stretched->transform().postScale(openvdb::Vec3d(1.0, 2.0, 1.0));
  openvdb::Vec3SGrid::Ptr vel = openvdb::Vec3SGrid::create();
  vel->setName("vel");
  const fs::path stretchedFile = folder.path() / "s.vdb";
  openvdb::io::File(stretchedFile.string()).write({stretched, vel});
  const std::string uniform = errorOf(stretchedFile);
  EXPECT_NE(uniform.find("surface: expected uniform voxels on a linear transform, found voxel size [0.005, 0.01, 0.005]"),
            std::string::npos)
      << uniform;

  openvdb::FloatGrid::Ptr nan = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(0.02f, openvdb::Vec3f(0.0f), 0.005f);
  nan->setName("surface");
  nan->tree().setValue(openvdb::Coord(0, 0, 0), std::numeric_limits<float>::quiet_NaN());
  openvdb::Vec3SGrid::Ptr v2 = openvdb::Vec3SGrid::create();
  v2->setTransform(nan->transform().copy());
  v2->setName("vel");
  const fs::path nanFile = folder.path() / "nan.vdb";
  openvdb::io::File(nanFile.string()).write({nan, v2});
  const std::string notFinite = errorOf(nanFile);
  EXPECT_NE(notFinite.find("surface: expected finite values, found a NaN or infinite value at voxel [0, 0, 0]"),
            std::string::npos)
      << notFinite;
  v2->tree().setValue(openvdb::Coord(4, 5, 6), openvdb::Vec3s(0.0f, std::numeric_limits<float>::infinity(), 0.0f));
  nan->tree().setValue(openvdb::Coord(0, 0, 0), 0.0f);
  openvdb::io::File(nanFile.string()).write({nan, v2});
  EXPECT_NE(errorOf(nanFile).find("vel: expected finite values, found a NaN or infinite value at voxel [4, 5, 6]"),
            std::string::npos);
  EXPECT_NE(errorOf(folder.path() / "absent.vdb").find("no such file"), std::string::npos);
}

}  // namespace
}  // namespace fluidsound::io
