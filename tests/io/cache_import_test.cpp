// tests/io/cache_import_test.cpp — the import of a liquid cache end to end (issue 21;
// docs/import.md): fluidsound's own frames of a splashing column read back through the cache path,
// and the same cache rewritten as Blender and Houdini write theirs — z up in centimetres with
// Houdini's grid names (`surface`, `vel`, a cell-centred velocity), and without particle ids —
// give the same bubbles.
#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>
#include <openvdb/points/PointAttribute.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/tools/PointIndexGrid.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "io/cache_file.h"
#include "io/cache_frame_reader.h"
#include "io/cache_liquid_frames.h"
#include "io/cache_particles.h"
#include "io/frame_files.h"
#include "io/frame_folder.h"
#include "io/frame_sequence.h"
#include "io/scene_file.h"
#include "sim/cache_bubbles.h"
#include "sim/simulation.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

/// The falling column of the command tests at 1 cm cells for 0.8 s: about 300 bubbles in 1.5 s.
constexpr const char* kColumn = R"({
  "format": "fluidsound.scene/1",
  "domain": { "min": [0, 0, 0], "max": [0.24, 0.16, 0.04], "cell": 0.01 },
  "time": { "duration": 0.8, "fps": 30 },
  "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.08, 0.14, 0.04] } } ],
  "listeners": [ { "name": "above", "position": [0.12, 0.4, 0.02] } ]
})";

/// Writes every frame as `fluidsound simulate` does.
class FrameFolderWriter : public sim::SimulationObserver {
 public:
  explicit FrameFolderWriter(fs::path folder) : folder_(std::move(folder)) { fs::create_directories(folder_); }
  void onFrame(const sim::FrameView& v, const sim::FrameRecord& r) override {
    writeFrameVdb(folder_ / frameFileName(r.frame, "vdb"), v.grid, v.particles, v.velocity, {v.particleRadius},
                  {r.frame, r.time, 30.0});
  }

 private:
  fs::path folder_;
};

/// A frame of ours rewritten as a Blender-style cache: z up, centimetres, the level set `surface`
/// and a cell-centred velocity `vel` on voxels turned with the axes, the points with `v` and,
/// when `ids`, `id`. Cell (i, j, k) of ours is voxel (i, −k, j) of the copy.
void rewriteZUpCentimetres(const fs::path& from, const fs::path& to, bool ids) {
  constexpr double kUnit = 0.01;  // metres per centimetre
  openvdb::io::File in(from.string());
  in.open();
  const auto surface = openvdb::gridPtrCast<openvdb::FloatGrid>(in.readGrid("surface"));
  const auto faces = openvdb::gridPtrCast<openvdb::Vec3fGrid>(in.readGrid("velocity"));
  in.close();
  const double h = surface->voxelSize()[0];
  const openvdb::Vec3d c0 = surface->indexToWorld(openvdb::Coord(0, 0, 0));  // our voxel (0, 0, 0)'s centre
  const auto transform = openvdb::math::Transform::createLinearTransform(h / kUnit);
  transform->postTranslate(openvdb::Vec3d(c0[0], -c0[2], c0[1]) / kUnit);
  const auto turned = [](const openvdb::Coord& c) { return openvdb::Coord(c.x(), -c.z(), c.y()); };

  auto level = openvdb::FloatGrid::create(static_cast<float>(surface->background() / kUnit));
  level->setTransform(transform);
  level->setGridClass(openvdb::GRID_LEVEL_SET);
  level->setName("surface");
  for (auto it = surface->cbeginValueOn(); it; ++it)
    level->tree().setValue(turned(it.getCoord()), static_cast<float>(*it / kUnit));
  openvdb::tools::signedFloodFill(level->tree());

  auto vel = openvdb::Vec3fGrid::create();
  vel->setTransform(transform->copy());
  vel->setName("vel");
  const auto read = faces->getConstAccessor();
  for (auto it = faces->cbeginValueOn(); it; ++it) {  // the cell's mean of its faces, turned
    const openvdb::Coord c = it.getCoord();
    const openvdb::Vec3f v(0.5f * ((*it)[0] + read.getValue(c.offsetBy(1, 0, 0))[0]),
                           0.5f * ((*it)[1] + read.getValue(c.offsetBy(0, 1, 0))[1]),
                           0.5f * ((*it)[2] + read.getValue(c.offsetBy(0, 0, 1))[2]));
    vel->tree().setValue(turned(c), openvdb::Vec3f(v[0], -v[2], v[1]) / static_cast<float>(kUnit));
  }

  const sim::FrameParticles p = *readPointParticles(from, 1.0, UpAxis::Y);
  std::vector<openvdb::Vec3R> positions;
  std::vector<openvdb::Vec3f> velocities;
  std::vector<openvdb::Int32> idValues;
  for (std::size_t q = 0; q < p.size(); ++q) {
    const Vec3 x = toCacheAxes({p.position[q][0], p.position[q][1], p.position[q][2]}, UpAxis::Z);
    const Vec3 u = toCacheAxes({p.velocity[q][0], p.velocity[q][1], p.velocity[q][2]}, UpAxis::Z);
    positions.emplace_back(x[0] / kUnit, x[1] / kUnit, x[2] / kUnit);
    velocities.emplace_back(u[0] / kUnit, u[1] / kUnit, u[2] / kUnit);
    idValues.push_back(static_cast<openvdb::Int32>(p.id[q]));  // Houdini's ids are int32
  }
  openvdb::GridPtrVec grids{level, vel};
  if (!positions.empty()) {
    using namespace openvdb::points;
    const PointAttributeVector<openvdb::Vec3R> list(positions);
    const auto index = openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(list, *transform);
    auto points = createPointDataGrid<NullCodec, PointDataGrid>(*index, list, *transform);
    appendAttribute<openvdb::Vec3f>(points->tree(), "v");
    populateAttribute(points->tree(), index->tree(), "v", PointAttributeVector<openvdb::Vec3f>(velocities));
    if (ids) {
      appendAttribute<openvdb::Int32>(points->tree(), "id");
      populateAttribute(points->tree(), index->tree(), "id", PointAttributeVector<openvdb::Int32>(idValues));
    }
    points->setName("flip_points");
    grids.push_back(points);
  }
  openvdb::io::File(to.string()).write(grids);
}

/// Bubbles of a cache by the import path (as `fluidsound from-cache` runs it).
std::vector<sim::BubbleHistory> importedBubbles(const fs::path& cacheFile, const std::string& text) {
  const CacheDescription cache = parseCacheFile(text, cacheFile);
  const auto frames = frameSequence(cache.frames, cacheFile.parent_path(), cacheFile.string(), "frames");
  const sim::GridGeometry grid = cacheGrid(cache, frames);
  sim::Scene scene = cache.scene;
  scene.domain = {cache.container->min, cache.container->max, grid.cellSize, cache.container->open};
  CacheLiquidFrames source(cache, frames, {}, grid);
  sim::CacheBubbleObserver quiet;
  return sim::cacheBubbles(source, grid, scene, {}, quiet).bubbles;
}

/// The measures the acceptance compares: count; the slope of log(count per bin) against log(radius)
/// over 10 log-spaced bins from 0.1 to 10 mm (report.json's radius_histogram), by least squares
/// weighted by each bin's count (a Poisson count's log has variance 1/count, so a bin of one
/// bubble does not tip the line); and the mean Minnaert frequency 3.26/r Hz·m as the spectrum's
/// centroid stand-in.
struct BubbleMeasures {
  double count = 0.0, slope = 0.0, meanFrequency = 0.0;
};

BubbleMeasures measure(const std::vector<sim::BubbleHistory>& bubbles) {
  std::vector<double> bins(10, 0.0);
  BubbleMeasures m;
  for (const sim::BubbleHistory& b : bubbles) {
    const int bin = std::clamp(static_cast<int>(std::floor(5.0 * std::log10(b.radius / 1e-4))), 0, 9);
    bins[bin] += 1.0;
    m.meanFrequency += 3.26 / b.radius;
  }
  m.count = static_cast<double>(bubbles.size());
  m.meanFrequency /= std::max(1.0, m.count);
  double sx = 0, sy = 0, sxx = 0, sxy = 0, n = 0;
  for (int i = 0; i < 10; ++i) {
    if (bins[i] == 0.0) continue;
    const double x = std::log10(1e-4) + (i + 0.5) * 0.2, y = std::log10(bins[i]), w = bins[i];
    sx += w * x, sy += w * y, sxx += w * x * x, sxy += w * x * y, n += w;
  }
  m.slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return m;
}

// Tolerances: the issue's — count within 15 %, the histogram's slope within 0.2, the spectrum's
// centroid within 10 % (here the mean Minnaert frequency, which the centroid follows).
void expectSameBubbles(const BubbleMeasures& got, const BubbleMeasures& want, const std::string& what) {
  std::printf("%s: count %.0f vs %.0f, slope %.3f vs %.3f, mean frequency %.0f vs %.0f Hz\n", what.c_str(), got.count, want.count, got.slope, want.slope, got.meanFrequency, want.meanFrequency);
  EXPECT_NEAR(got.count / want.count, 1.0, 0.15) << what << ": " << got.count << " vs " << want.count;
  EXPECT_NEAR(got.slope, want.slope, 0.2) << what;
  EXPECT_NEAR(got.meanFrequency / want.meanFrequency, 1.0, 0.10) << what;
}

// Also: the import is deterministic — the same bubbles, bit for bit, on one thread as on all.
TEST(CacheImport, ZUpCentimetreAndIdFreeCopiesOfACacheGiveItsBubbles) {
  test::TempFolder folder;
  sim::Scene scene = parseScene(kColumn, folder.path() / "column.json");
  FrameFolderWriter writer(folder.path() / "frames");
  sim::simulate(scene, {}, writer);
  const auto frames = frameSequence("frames", folder.path(), "cache.json", "frames");
  fs::create_directories(folder.path() / "blender");
  fs::create_directories(folder.path() / "noid");
  for (const SequenceFrame& f : frames) {
    rewriteZUpCentimetres(f.path, folder.path() / "blender" / ("fluid_" + frameFileName(f.frame, "vdb")), true);
    rewriteZUpCentimetres(f.path, folder.path() / "noid" / frameFileName(f.frame, "vdb"), false);
  }
  const std::string ours = R"({"format": "fluidsound.cache/1", "frames": "frames/%04d.vdb", "fps": 30,
    "container": {"min": [0, 0, 0], "max": [0.24, 0.16, 0.04]}})";
  const std::string blender = R"({"format": "fluidsound.cache/1", "frames": "blender/fluid_####.vdb", "fps": 30,
    "units": {"metres_per_unit": 0.01, "up": "z"}, "grids": {"surface": "surface", "velocity": "vel"},
    "container": {"min": [0, 0, 0], "max": [0.24, 0.16, 0.04]}})";
  const std::string noIds = R"({"format": "fluidsound.cache/1", "frames": "noid/%04d.vdb", "fps": 30,
    "units": {"metres_per_unit": 0.01, "up": "z"}, "grids": {"velocity": "vel"},
    "container": {"min": [0, 0, 0], "max": [0.24, 0.16, 0.04]}})";
  const auto reference = importedBubbles(folder.path() / "cache.json", ours);
  ASSERT_GT(reference.size(), 100u);
  {  // the same bits on one thread
    const oneapi::tbb::global_control one(oneapi::tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_TRUE(importedBubbles(folder.path() / "cache.json", ours) == reference);
  }
  const BubbleMeasures want = measure(reference);
  expectSameBubbles(measure(importedBubbles(folder.path() / "blender.json", blender)), want, "z up, cm, Houdini names");
  expectSameBubbles(measure(importedBubbles(folder.path() / "noid.json", noIds)), want, "no particle ids");
}

}  // namespace
}  // namespace fluidsound::io
