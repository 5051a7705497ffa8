// tests/io/cache_file_test.cpp — `fluidsound.cache/1` (io/cache_file.h; docs/import.md): the
// minimum the issue names reads with every default, each field reaches its record, and each bad
// field — the cache's own and the scene's it shares — is one error naming the cache file and its
// JSON path.
#include "io/cache_file.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "io/input_error.h"
#include "support/input_error_expectations.h"

namespace fluidsound::io {
namespace {

using nlohmann::json;

json minimum() { return json::parse(R"({"format": "fluidsound.cache/1", "frames": "frames/%04d.vdb", "fps": 30})"); }

void expectError(const json& document, const std::string& field, const std::string& expected) {
  const InputError error = test::inputErrorOf(
      [](const std::string& t) { parseCacheFile(t, "shots/cache.json"); }, document.dump());
  test::expectInputError(error, "shots/cache.json", field, expected, test::ExpectedAt::Anywhere);
}

TEST(CacheFile, TheMinimumReadsWithEveryDefault) {
  const CacheDescription cache = parseCacheFile(minimum().dump(), "shots/cache.json");
  EXPECT_EQ(cache.frames, "frames/%04d.vdb");
  EXPECT_EQ(cache.fps, 30.0);
  EXPECT_EQ(cache.grids.surface, (std::vector<std::string>{"surface"}));
  EXPECT_EQ(cache.grids.velocity, (std::vector<std::string>{"vel", "velocity"}));
  EXPECT_EQ(cache.metresPerUnit, 1.0);
  EXPECT_EQ(cache.up, UpAxis::Y);
  EXPECT_FALSE(cache.particles);
  EXPECT_TRUE(cache.defaultListener);
  EXPECT_TRUE(cache.scene.listeners.empty());
  EXPECT_EQ(cache.scene.sampleRate, 48000.0);
}

TEST(CacheFile, EachFieldReachesItsRecord) {
  json document = minimum();
  document["frames"] = "geo/surface.$F4.vdb";
  document["fps"] = 24;
  document["grids"] = {{"surface", {"liquid_sdf", "surface"}}, {"velocity", "flow"}};
  document["units"] = {{"metres_per_unit", 0.01}, {"up", "z"}};
  document["particles"] = "geo/points.$F4.vdb";
  document["listeners"] = json::parse(R"([{"name": "ears", "position": [0, 1, 0.3], "head": {"facing": [0, 0, -1]}}])");
  document["audio"] = {{"sample_rate", 44100}};
  document["transfer"] = {{"model", "geometric"}};
  const CacheDescription cache = parseCacheFile(document.dump(), "shots/cache.json");
  EXPECT_EQ(cache.fps, 24.0);
  EXPECT_EQ(cache.grids.surface, (std::vector<std::string>{"liquid_sdf", "surface"}));
  EXPECT_EQ(cache.grids.velocity, (std::vector<std::string>{"flow"}));
  EXPECT_EQ(cache.metresPerUnit, 0.01);
  EXPECT_EQ(cache.up, UpAxis::Z);
  EXPECT_EQ(cache.particles, "geo/points.$F4.vdb");
  EXPECT_FALSE(cache.defaultListener);
  ASSERT_EQ(cache.scene.listeners.size(), 1u);
  EXPECT_TRUE(cache.scene.listeners[0].head);
  EXPECT_EQ(cache.scene.sampleRate, 44100.0);
  EXPECT_EQ(cache.scene.transfer.model, sim::TransferModel::Geometric);
}

TEST(CacheFile, EachBadFieldIsNamedInTheCacheFile) {
  json tag = minimum();
  tag["format"] = "fluidsound.scene/1";
  expectError(tag, "format", R"("fluidsound.cache/1", found "fluidsound.scene/1")");
  json frames = minimum();
  frames.erase("frames");
  expectError(frames, "frames", "a frame pattern such as");
  json fps = minimum();
  fps["fps"] = 0;
  expectError(fps, "fps", "a number > 0 and <= 1000 (frames per second), found 0");
  json typo = minimum();
  typo["frame_rate"] = 30;
  expectError(typo, "frame_rate", "one of format, frames, fps, grids, units, particles, container");
  json grid = minimum();
  grid["grids"] = {{"surface", 3}};
  expectError(grid, "grids.surface", "a grid name or an array of grid names");
  json empty = minimum();
  empty["grids"] = {{"velocity", {"vel", ""}}};
  expectError(empty, "grids.velocity[1]", "a grid name or an array of grid names");
  json up = minimum();
  up["units"] = {{"up", "x"}};
  expectError(up, "units.up", R"("y" (Houdini, fluidsound) or "z" (Blender), found "x")");
  json scale = minimum();
  scale["units"] = {{"metres_per_unit", -1}};
  expectError(scale, "units.metres_per_unit", "a number > 0");
  // A scene field, by the scene's rules, named in the cache file.
  json listener = minimum();
  listener["listeners"] = json::parse(R"([{"name": "a"}])");
  expectError(listener, "listeners[0].position", "found nothing");
  json domain = minimum();
  domain["domain"] = json::object();  // the frames give the domain
  expectError(domain, "domain", "one of format, frames, fps");
}

// The container: the box and its open faces reach the record; a box with no volume, an unknown face
// or one listed twice is named.
TEST(CacheFile, TheContainerIsReadAndCheckedLikeADomain) {
  json document = minimum();
  document["container"] = json::parse(R"({"min": [0, 0, 0], "max": [0.5, 0.3, 0.1], "open": ["+y"]})");
  const CacheDescription cache = parseCacheFile(document.dump(), "shots/cache.json");
  ASSERT_TRUE(cache.container);
  EXPECT_EQ(cache.container->max[1], 0.3);
  EXPECT_EQ(cache.container->open, (std::array<bool, 6>{false, false, false, true, false, false}));
  json flat = minimum();
  flat["container"] = json::parse(R"({"min": [0, 0, 0], "max": [0.5, 0, 0.1]})");
  expectError(flat, "container.max", "a corner above container.min on every axis");
  json face = minimum();
  face["container"] = json::parse(R"({"min": [0, 0, 0], "max": [1, 1, 1], "open": ["+y", "top"]})");
  expectError(face, "container.open[1]", "an array of face names");
  json twice = minimum();
  twice["container"] = json::parse(R"({"min": [0, 0, 0], "max": [1, 1, 1], "open": ["+y", "+y"]})");
  expectError(twice, "container.open[1]", "each once");
}

}  // namespace
}  // namespace fluidsound::io
