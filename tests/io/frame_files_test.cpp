// Tests of io/frame_files.h: the per-frame VDB and PLY files read back with OpenVDB and by hand.
#include "sim/scene.h"
#include "io/frame_files.h"

#include <gtest/gtest.h>
#include <openvdb/openvdb.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "sim/fluid/fluid_solver.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

using test::TempFolder;

/// A resting layer 4 cm deep in a 10 cm closed box, 1 cm cells.
sim::FluidSolver layer() {
  sim::Scene s;
  s.domain.max = {0.1, 0.1, 0.1};
  s.domain.cell = 0.01;
  s.time.duration = 1.0;
  s.liquid.push_back({sim::Box{{0, 0, 0}, {0.1, 0.04, 0.1}}, {}});
  return sim::FluidSolver(s);
}

// DESIGN.md: frames/NNNN.vdb holds a narrow-band level set `surface` (negative inside the liquid)
// and a Vec3f `velocity`. Read back with OpenVDB: inside the layer φ < 0, above it φ > 0, and the
// zero crossing on the centre column lies within a cell of the layer's top (particle surface).
TEST(FrameFiles, VdbHoldsSurfaceAndVelocityGrids) {
  TempFolder folder;
  const sim::FluidSolver solver = layer();
  const auto path = folder.path() / "0000.vdb";
  writeFrameVdb(path, solver.grid(), solver.particles(), solver.velocity(), {solver.particleRadius()});
  openvdb::initialize();
  openvdb::io::File file(path.string());
  file.open();
  const auto surface = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("surface"));
  const auto velocity = openvdb::gridPtrCast<openvdb::Vec3fGrid>(file.readGrid("velocity"));
  file.close();
  ASSERT_TRUE(surface);
  ASSERT_TRUE(velocity);
  EXPECT_EQ(surface->getGridClass(), openvdb::GRID_LEVEL_SET);
  const auto acc = surface->getConstAccessor();
  const auto valueAt = [&](double y) {
    return acc.getValue(surface->transform().worldToIndexCellCentered(openvdb::Vec3d(0.05, y, 0.05)));
  };
  EXPECT_LT(valueAt(0.025), 0.0f);
  EXPECT_GT(valueAt(0.065), 0.0f);
  double crossing = -1.0;
  for (double y = 0.005; y < 0.09; y += 0.001)
    if (valueAt(y) < 0.0f && valueAt(y + 0.001) >= 0.0f) crossing = y;
  EXPECT_NEAR(crossing, 0.04, 0.01) << "m; the surface of a 4 cm layer";
  EXPECT_GT(velocity->activeVoxelCount(), 0u);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"0000.vdb"}) << "no temporary left";
}

// Issue 21: a frame says which it is, as Houdini and Blender show a file's metadata: fps, frame,
// time, units, up axis, and each grid's creator.
TEST(FrameFiles, VdbNamesItsFrameRateTimeUnitsAndCreator) {
  TempFolder folder;
  const sim::FluidSolver solver = layer();
  const auto path = folder.path() / "0012.vdb";
  writeFrameVdb(path, solver.grid(), solver.particles(), solver.velocity(), {solver.particleRadius()},
                {12, 0.5, 24.0, "fluidsound 9.9"});
  openvdb::initialize();
  openvdb::io::File file(path.string());
  file.open();
  const openvdb::MetaMap::Ptr meta = file.getMetadata();
  const openvdb::GridBase::Ptr surface = file.readGrid("surface");
  file.close();
  EXPECT_EQ(meta->metaValue<double>("fps"), 24.0);
  EXPECT_EQ(meta->metaValue<int32_t>("frame"), 12);
  EXPECT_EQ(meta->metaValue<double>("time"), 0.5);
  EXPECT_EQ(meta->metaValue<std::string>("units"), "m");
  EXPECT_EQ(meta->metaValue<std::string>("up_axis"), "y");
  EXPECT_EQ(surface->getCreator(), "fluidsound 9.9");
}

// DESIGN.md: frames/NNNN.ply is binary little-endian, one vertex per particle, float x y z vx vy vz
// and uint id, the particle's stable id (issue 21: a cache reader follows particles by it).
TEST(FrameFiles, PlyHoldsEveryParticleWithItsId) {
  TempFolder folder;
  const sim::FluidSolver solver = layer();
  const auto path = folder.path() / "0000.ply";
  writeParticlesPly(path, solver.particles());
  std::ifstream in(path, std::ios::binary);
  std::string line, header;
  while (std::getline(in, line) && line != "end_header") header += line + "\n";
  EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(header.find("element vertex " + std::to_string(solver.particles().size())), std::string::npos);
  EXPECT_NE(header.find("property float x\nproperty float y\nproperty float z\nproperty float vx\n"
                        "property float vy\nproperty float vz\nproperty uint id\n"),
            std::string::npos);
  struct Vertex {
    float x, y, z, vx, vy, vz;
    std::uint32_t id;
  };
  static_assert(sizeof(Vertex) == 28);
  std::vector<Vertex> data(solver.particles().size());
  in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size() * sizeof(Vertex)));
  ASSERT_TRUE(in);
  EXPECT_EQ(in.peek(), std::char_traits<char>::eof());
  EXPECT_EQ(data[7].y, solver.particles().position[7][1]);
  for (std::size_t p = 0; p < data.size(); ++p) ASSERT_EQ(data[p].id, solver.particles().id[p]) << p;
}

}  // namespace
}  // namespace fluidsound::io
