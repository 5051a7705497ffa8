// tests/tools/from_cache_errors_test.cpp — the real `fluidsound from-cache` on broken caches
// (issue 21; docs/import.md, docs/cli.md "Exit status"): one line on stderr naming the file,
// exit 3, and nothing written — no OUTDIR at all, since every frame is checked before the first
// output. One case per way a cache breaks: a missing frame, an empty sequence, a grid of the wrong
// name or type, a level set on another transform than the velocity, non-uniform voxels, a NaN,
// a frame without particles. And the good cache runs (exit 0, the WAV and report written).
#include <gtest/gtest.h>
#include <openvdb/io/File.h>
#include <openvdb/openvdb.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <string>

#include "support/command_runner.h"
#include "support/temp_folder.h"

namespace fluidsound {
namespace {

namespace fs = std::filesystem;
using test::runFluidsound;

constexpr int kExitBadInput = 3;  // docs/cli.md

/// A falling column at 2 cm cells for 0.1 s: frames 0 … 3 in a fraction of a second.
constexpr const char* kScene = R"({
  "format": "fluidsound.scene/1",
  "domain": { "min": [0, 0, 0], "max": [0.24, 0.16, 0.04], "cell": 0.02 },
  "time": { "duration": 0.1, "fps": 30 },
  "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.08, 0.14, 0.04] } } ]
})";

constexpr const char* kCache = R"({"format": "fluidsound.cache/1", "frames": "sim/frames/%04d.vdb", "fps": 30,
  "container": {"min": [0, 0, 0], "max": [0.24, 0.16, 0.04]}})";

/// Simulates kScene into WORK/sim and writes WORK/cache.json (kCache) naming its frames.
bool simulateCache(const fs::path& work) {
  std::ofstream(work / "scene.json") << kScene;
  std::ofstream(work / "cache.json") << kCache;
  return runFluidsound({"simulate", (work / "scene.json").string(), "-o", (work / "sim").string(), "-q"}).exitCode == 0;
}

/// Reads every grid of a frame, lets `change` edit the list, writes it back.
void rewriteFrame(const fs::path& path, const std::function<void(openvdb::GridPtrVec&)>& change) {
  openvdb::initialize();
  openvdb::io::File in(path.string());
  in.open();
  openvdb::GridPtrVec grids = *in.getGrids();
  in.close();
  change(grids);
  openvdb::io::File(path.string()).write(grids);
}

openvdb::GridBase::Ptr named(openvdb::GridPtrVec& grids, const std::string& name) {
  for (auto& g : grids)
    if (g->getName() == name) return g;
  return nullptr;
}

struct Broken {
  const char* name;
  std::function<void(const fs::path& work)> breakIt;  ///< edits WORK/sim/frames or WORK/cache.json
  const char* namedFile;  ///< the file the message names, relative to WORK
  const char* says;       ///< a part of the line after it
};

class FromCacheErrors : public ::testing::TestWithParam<Broken> {};

TEST_P(FromCacheErrors, OneLineExitThreeAndNothingWritten) {
  test::TempFolder folder;
  const fs::path work = folder.path();
  ASSERT_TRUE(simulateCache(work));
  GetParam().breakIt(work);
  const test::CommandOutcome outcome =
      runFluidsound({"from-cache", (work / "cache.json").string(), "-o", (work / "out").string(), "-q"});
  EXPECT_EQ(outcome.exitCode, kExitBadInput) << outcome.err;
  EXPECT_EQ(std::count(outcome.err.begin(), outcome.err.end(), '\n'), 1) << outcome.err;
  EXPECT_NE(outcome.err.find("fluidsound: error: " + (work / GetParam().namedFile).string()), std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find(GetParam().says), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(work / "out"));
}

const Broken kBroken[] = {
    {"MissingFrame", [](const fs::path& w) { fs::remove(w / "sim/frames/0002.vdb"); }, "cache.json",
     "frames: expected every frame from 0 to 3, found no"},
    {"EmptySequence",
     [](const fs::path& w) {
       std::ofstream(w / "cache.json") << R"({"format": "fluidsound.cache/1", "frames": "sim/frames/flip.%04d.vdb", "fps": 30})";
     },
     "cache.json", "frames: expected at least one frame file"},
    {"WrongGridName",
     [](const fs::path& w) {
       rewriteFrame(w / "sim/frames/0001.vdb", [](openvdb::GridPtrVec& g) { named(g, "velocity")->setName("flow"); });
     },
     "sim/frames/0001.vdb", "vel: expected a velocity grid named vel or velocity, found grids"},
    {"WrongGridType",
     [](const fs::path& w) {
       rewriteFrame(w / "sim/frames/0001.vdb", [](openvdb::GridPtrVec& g) {
         named(g, "surface")->setName("old");
         auto v = openvdb::Vec3fGrid::create();
         v->setName("surface");
         g.push_back(v);
       });
     },
     "sim/frames/0001.vdb", "expected a FloatGrid"},
    {"TransformUnlikeTheVelocitys",
     [](const fs::path& w) {
       rewriteFrame(w / "sim/frames/0003.vdb", [](openvdb::GridPtrVec& g) {
         named(g, "velocity")->setTransform(openvdb::math::Transform::createLinearTransform(0.03));
       });
     },
     "sim/frames/0003.vdb", "velocity"},
    {"NonUniformVoxels",
     [](const fs::path& w) {
       rewriteFrame(w / "sim/frames/0000.vdb", [](openvdb::GridPtrVec& g) {
         auto t = openvdb::math::Transform::createLinearTransform(0.02);
         t->preScale(openvdb::Vec3d(1, 1, 2));
         named(g, "surface")->setTransform(t);
       });
     },
     "sim/frames/0000.vdb", "uniform voxels"},
    {"NaN",
     [](const fs::path& w) {
       rewriteFrame(w / "sim/frames/0002.vdb", [](openvdb::GridPtrVec& g) {
         openvdb::gridPtrCast<openvdb::FloatGrid>(named(g, "surface"))->tree().setValue(openvdb::Coord(1, 1, 1), std::nanf(""));
       });
     },
     "sim/frames/0002.vdb", "NaN"},
    {"NoParticles",
     [](const fs::path& w) {
       rewriteFrame(w / "sim/frames/0002.vdb", [](openvdb::GridPtrVec& g) {
         g.erase(std::remove_if(g.begin(), g.end(), [](const auto& grid) { return grid->getName() == "points"; }), g.end());
       });
     },
     "sim/frames/0002.vdb", "expected the liquid's particles as a point grid"},
};

INSTANTIATE_TEST_SUITE_P(BrokenCaches, FromCacheErrors, ::testing::ValuesIn(kBroken),
                         [](const auto& info) { return std::string(info.param.name); });

// The unbroken cache: exit 0, OUTDIR with the audio, the spectrogram, the bubbles, the frames and
// a complete report.
TEST(FromCache, AGoodCacheRendersWhatRunWrites) {
  test::TempFolder folder;
  const fs::path work = folder.path();
  ASSERT_TRUE(simulateCache(work));
  const test::CommandOutcome outcome =
      runFluidsound({"from-cache", (work / "cache.json").string(), "-o", (work / "out").string(), "-q"});
  ASSERT_EQ(outcome.exitCode, 0) << outcome.err;
  for (const char* file : {"cache.wav", "spectrogram.png", "bubbles.json", "report.json", "frames/0003.vdb"})
    EXPECT_TRUE(fs::is_regular_file(work / "out" / file)) << file;
}

// OUTDIR/frames is where from-cache writes its frames: an OUTDIR whose frames/ are the cache's own
// is refused before anything is read or written.
TEST(FromCache, RefusesToWriteOverItsOwnFrames) {
  test::TempFolder folder;
  const fs::path work = folder.path();
  ASSERT_TRUE(simulateCache(work));
  const auto before = fs::last_write_time(work / "sim/frames/0001.vdb");
  const test::CommandOutcome outcome =
      runFluidsound({"from-cache", (work / "cache.json").string(), "-o", (work / "sim").string(), "-q"});
  EXPECT_EQ(outcome.exitCode, kExitBadInput) << outcome.err;
  EXPECT_NE(outcome.err.find("choose another -o"), std::string::npos) << outcome.err;
  EXPECT_EQ(fs::last_write_time(work / "sim/frames/0001.vdb"), before);
}

}  // namespace
}  // namespace fluidsound
