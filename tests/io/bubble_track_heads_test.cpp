// tests/io/bubble_track_heads_test.cpp — the `heads` and `hrtf` fields of `fluidsound.bubbles/1`
// (docs/bubbles-format.md; docs/binaural.md): written and read back exactly, and each bad head
// named by its JSON path.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "io/bubble_track_file.h"
#include "io/input_error.h"
#include "support/input_error_expectations.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

using nlohmann::json;

json withHead() {
  return json::parse(R"({
    "format": "fluidsound.bubbles/1",
    "sample_rate": 48000,
    "listeners": ["near", "ears"],
    "heads": [ { "listener": "ears", "position": [0, 0.3, 1], "facing": [0, 0, -1], "up": [0, 1, 0] } ],
    "hrtf": "sets/kemar.sofa",
    "bubbles": [
      { "radius": 0.001, "birth": 0.25,
        "track": [ { "t": 0.25, "depth": 0.03, "transfer": [1.0, 0.8], "position": [0.1, 0.0, 0.0] } ] }
    ]
  })");
}

void expectError(const json& document, const std::string& field, const std::string& expected) {
  const InputError error = test::inputErrorOf(
      [](const std::string& t) { parseBubbleTracks(t, "drip.json"); }, document.dump());
  test::expectInputError(error, "drip.json", field, expected, test::ExpectedAt::Anywhere);
}

TEST(BubbleTrackHeads, AHeadAndItsSetAreReadAndWrittenBackExactly) {
  const acoustics::BubbleTrackSet set = parseBubbleTracks(withHead().dump(), "drip.json");
  ASSERT_EQ(set.heads.size(), 1u);
  EXPECT_EQ(set.heads[0].listener, "ears");
  EXPECT_EQ(set.heads[0].facing, (Vec3{0.0, 0.0, -1.0}));
  EXPECT_EQ(set.hrtf, "sets/kemar.sofa");
  EXPECT_EQ(acoustics::outputChannelNames(set), (std::vector<std::string>{"near", "ears.left", "ears.right"}));
  EXPECT_EQ(acoustics::outputChannelListeners(set), (std::vector<std::size_t>{0, 1, 1}));
  test::TempFolder folder;
  writeBubbleTracks(folder.path() / "b.json", set);
  EXPECT_EQ(readBubbleTracks(folder.path() / "b.json"), set);
}

TEST(BubbleTrackHeads, EachBadHeadIsNamedByItsPath) {
  json unknown = withHead();
  unknown["heads"][0]["listener"] = "nobody";
  expectError(unknown, "heads[0].listener", "the name of a listener in listeners");
  json twice = withHead();
  twice["heads"].push_back(twice["heads"][0]);
  expectError(twice, "heads[1].listener", "not used by another head");
  json parallel = withHead();
  parallel["heads"][0]["up"] = {0, 0, 2};
  expectError(parallel, "heads[0].up", "a direction not parallel to facing");
  json zero = withHead();
  zero["heads"][0]["facing"] = {0, 0, 0};
  expectError(zero, "heads[0].up", "both non-zero");
  json missing = withHead();
  missing["heads"][0].erase("facing");
  expectError(missing, "heads[0].facing", "found nothing");
  json noPosition = withHead();
  noPosition["bubbles"][0]["track"][0].erase("position");
  expectError(noPosition, "bubbles[0].track", "a track sample with a position");
  json emptySet = withHead();
  emptySet["hrtf"] = "";
  expectError(emptySet, "hrtf", "the path of a SOFA file");
}

}  // namespace
}  // namespace fluidsound::io
