// tests/io/cache_frame_reader_test.cpp — a cache frame read in fluidsound's frame (io/
// cache_frame_reader.h; issue 21): the same liquid written y-up in metres and z-up in
// centimetres (Blender's way) reads the same φ, velocity and bounds.
#include "io/cache_frame_reader.h"

#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/LevelSetSphere.h>

#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

/// A sphere of liquid of radius 3 cm at `centre` [m, y up] moving at `velocity` [m/s], written in
/// `unit` metres with `up` as the cache's up axis, 2.5 mm voxels (scaled with the unit).
fs::path writeSphere(const fs::path& path, const Vec3& centre, const Vec3& velocity, double unit, UpAxis up) {
  openvdb::initialize();
  const Vec3 c = toCacheAxes(centre, up), v = toCacheAxes(velocity, up);
  const float voxel = static_cast<float>(0.0025 / unit);
  openvdb::FloatGrid::Ptr surface = openvdb::tools::createLevelSetSphere<openvdb::FloatGrid>(
      static_cast<float>(0.03 / unit), openvdb::Vec3f(c[0] / unit, c[1] / unit, c[2] / unit), voxel);
  surface->setName("surface");
  openvdb::Vec3SGrid::Ptr vel = openvdb::Vec3SGrid::create();
  vel->setTransform(surface->transform().copy());
  vel->setName("vel");
  const openvdb::Vec3s value(v[0] / unit, v[1] / unit, v[2] / unit);
  for (auto it = surface->cbeginValueAll(); it; ++it)  // the velocity wherever the level set has a value
    if (it.isVoxelValue()) vel->tree().setValue(it.getCoord(), value);
  openvdb::io::File(path.string()).write({surface, vel});
  return path;
}

// Reference: the y-up metre frame itself. The centimetre z-up copy holds the same level set built
// at scaled voxels, so the two agree to float rounding: 10⁻⁶ m in φ, 10⁻⁶ m/s in velocity, a
// voxel (2.5 mm) in the bounds.
TEST(CacheFrameReader, AZUpCentimetreCopyReadsAsTheYUpMetreFrame) {
  test::TempFolder folder;
  const Vec3 centre{0.1, 0.05, -0.02}, velocity{0.3, -1.2, 0.4};
  const CacheFrameReader metres(writeSphere(folder.path() / "m.vdb", centre, velocity, 1.0, UpAxis::Y), {}, 1.0,
                                UpAxis::Y);
  const CacheFrameReader blender(writeSphere(folder.path() / "b.vdb", centre, velocity, 0.01, UpAxis::Z), {}, 0.01,
                                 UpAxis::Z);
  EXPECT_NEAR(metres.voxelSize(), 0.0025, 1e-9);
  EXPECT_NEAR(blender.voxelSize(), 0.0025, 1e-9);
  for (const Vec3& x : {centre, Vec3{0.1, 0.075, -0.02}, Vec3{0.12, 0.05, -0.01}, Vec3{0.09, 0.04, 0.0}}) {
    EXPECT_NEAR(metres.phi(x), blender.phi(x), 1e-6);
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(blender.velocity(x)[a], velocity[a], 1e-6) << a;
  }
  EXPECT_NEAR(metres.phi({0.1, 0.075, -0.02}), 0.025 - 0.03, 0.0005);  // 2.5 cm up from the centre
  const auto a = metres.bounds(), b = blender.bounds();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(a[0][k], b[0][k], 0.0025) << k;
    EXPECT_NEAR(a[1][k], b[1][k], 0.0025) << k;
    EXPECT_LT(a[0][k], centre[k] - 0.03);
    EXPECT_GT(a[1][k], centre[k] + 0.03);
  }
}

TEST(CacheFrameReader, TheAxesTurnBothWays) {
  const Vec3 v{1.0, 2.0, 3.0};
  EXPECT_EQ(fromCacheAxes(v, UpAxis::Z), (Vec3{1.0, 3.0, -2.0}));  // Blender's z is our y
  EXPECT_EQ(toCacheAxes(fromCacheAxes(v, UpAxis::Z), UpAxis::Z), v);
  EXPECT_EQ(fromCacheAxes(v, UpAxis::Y), v);
}

}  // namespace
}  // namespace fluidsound::io
