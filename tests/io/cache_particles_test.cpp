// tests/io/cache_particles_test.cpp — a frame of `fluidsound simulate` read back by the cache path
// (issue 21; io/cache_particles.h, io/cache_frame_reader.h): every particle with its own velocity
// and id, and the MAC velocity on the faces exactly as the solver had it.
#include "io/cache_particles.h"

#include <gtest/gtest.h>

#include <map>

#include "io/cache_frame_reader.h"
#include "io/frame_files.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

/// A 10×8×6 grid of 1 cm cells from (0.1, 0, -0.03) with a 4 cm slab of liquid at its bottom,
/// 500 particles in it with distinct velocities and shuffled ids, and face velocities that vary
/// per face.
struct SlabFrame {
  sim::GridGeometry grid{{10, 8, 6}, 0.01, {0.1, 0.0, -0.03}};
  sim::Particles particles;
  sim::MacVelocity velocity{grid};
  SlabFrame() {
    for (int p = 0; p < 500; ++p) {
      const float x = 0.1f + 0.0001f + 0.0998f * ((p * 37) % 500) / 500.0f;
      const float y = 0.0001f + 0.039f * ((p * 91) % 500) / 500.0f;
      const float z = -0.03f + 0.0001f + 0.0598f * ((p * 13) % 500) / 500.0f;
      particles.push({x, y, z}, {0.001f * p, -0.5f + 0.002f * p, 0.25f - 0.001f * p});
      particles.id.back() = static_cast<std::uint64_t>((p * 7919) % 1000);
    }
    for (int a = 0; a < 3; ++a) {
      const sim::Index3 n = grid.faceCount(a);
      for (int k = 0; k < n[2]; ++k)
        for (int j = 0; j < n[1]; ++j)
          for (int i = 0; i < n[0]; ++i) velocity[a](i, j, k) = 0.1f * a + 0.01f * i - 0.02f * j + 0.005f * k;
    }
  }
};

// The points are stored as float offsets within their voxel (no quantising codec): a position reads
// back to float rounding of the voxel-relative offset (1e-7 m on 1 cm voxels), velocities bit for
// bit, matched by id in whatever order the point grid holds them.
TEST(CacheParticles, AFrameOfSimulateHoldsEveryParticleWithItsVelocityAndId) {
  test::TempFolder folder;
  const SlabFrame f;
  const auto path = folder.path() / "0000.vdb";
  writeFrameVdb(path, f.grid, f.particles, f.velocity, {0.002});
  const std::optional<sim::FrameParticles> read = readPointParticles(path, 1.0, UpAxis::Y);
  ASSERT_TRUE(read);
  ASSERT_EQ(read->size(), f.particles.size());
  ASSERT_EQ(read->id.size(), f.particles.size());
  ASSERT_EQ(read->velocity.size(), f.particles.size());
  std::map<std::uint64_t, std::size_t> byId;
  for (std::size_t p = 0; p < f.particles.size(); ++p) byId[f.particles.id[p]] = p;
  for (std::size_t q = 0; q < read->size(); ++q) {
    const std::size_t p = byId.at(read->id[q]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(read->position[q][c], f.particles.position[p][c], 1e-7) << q << " " << c;
      EXPECT_FLOAT_EQ(read->velocity[q][c], f.particles.velocity[p][c]) << q << " " << c;
    }
  }
}

// The staggered velocity grid holds the solver's faces: read on the same grid they come back
// exactly (float rounding: 1e-6 m/s) in and around the liquid.
TEST(CacheParticles, TheFrameVelocityReadsBackOnTheSolversFaces) {
  test::TempFolder folder;
  const SlabFrame f;
  const auto path = folder.path() / "0000.vdb";
  writeFrameVdb(path, f.grid, f.particles, f.velocity, {0.002});
  const CacheFrameReader reader(path, {}, 1.0, UpAxis::Y);
  const sim::MacVelocity read = reader.faceVelocity(f.grid);
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < f.grid.cells[2]; ++k)
      for (int j = 0; j < 4; ++j)  // the slab and the band above it
        for (int i = 0; i < f.grid.cells[0]; ++i)
          EXPECT_NEAR(read[a](i, j, k), f.velocity[a](i, j, k), 1e-6) << a << " " << i << " " << j << " " << k;
}

TEST(CacheParticles, AFrameWithoutPointsHasNone) {
  test::TempFolder folder;
  const SlabFrame f;
  const auto path = folder.path() / "0000.vdb";
  writeLevelSetFrameVdb(path, f.grid, sim::Array3f(f.grid.cells, -0.01f), f.velocity, 3);
  EXPECT_FALSE(readPointParticles(path, 1.0, UpAxis::Y));
}

}  // namespace
}  // namespace fluidsound::io
