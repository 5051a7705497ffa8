// tests/io/bubble_track_rings_test.cpp — a bubble's `rings` in `fluidsound.bubbles/1`
// (docs/bubbles-format.md; docs/transfer.md, "The air column's ring"): written and read back
// exactly, and a bad ring named by its JSON path.
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

json withRings() {
  return json::parse(R"({
    "format": "fluidsound.bubbles/1", "sample_rate": 48000, "listeners": ["a", "b"],
    "bubbles": [ { "radius": 0.001, "birth": 0.25,
      "rings": [ { "frequency": 912.5, "decay_rate": 160, "gain": [0.01, 0.002], "phase": [0.5, -2.5] },
                 { "frequency": 3100, "decay_rate": 140, "gain": [0.001, 0], "phase": [0, 3] } ],
      "track": [ { "t": 0.25, "depth": 0.03, "transfer": [1.0, 0.8] } ] } ]
  })");
}

void expectError(const json& document, const std::string& field, const std::string& expected) {
  const InputError error = test::inputErrorOf(
      [](const std::string& t) { parseBubbleTracks(t, "drip.json"); }, document.dump());
  test::expectInputError(error, "drip.json", field, expected, test::ExpectedAt::Anywhere);
}

TEST(BubbleTrackRings, RingsAreReadAndWrittenBackExactly) {
  const acoustics::BubbleTrackSet set = parseBubbleTracks(withRings().dump(), "drip.json");
  ASSERT_EQ(set.bubbles[0].rings.size(), 2u);
  EXPECT_EQ(set.bubbles[0].rings[0].frequency, 912.5);
  EXPECT_EQ(set.bubbles[0].rings[1].phase, (std::vector<double>{0.0, 3.0}));
  test::TempFolder folder;
  writeBubbleTracks(folder.path() / "b.json", set);
  EXPECT_EQ(readBubbleTracks(folder.path() / "b.json"), set);
}

TEST(BubbleTrackRings, EachBadRingIsNamedByItsPath) {
  json count = withRings();
  count["bubbles"][0]["rings"][1]["gain"] = {0.1};
  expectError(count, "bubbles[0].rings[1].gain", "an array of 2 numbers (one per listener)");
  json negative = withRings();
  negative["bubbles"][0]["rings"][0]["gain"][1] = -0.1;
  expectError(negative, "bubbles[0].rings[0].gain[1]", "a number >= 0");
  json frequency = withRings();
  frequency["bubbles"][0]["rings"][0].erase("frequency");
  expectError(frequency, "bubbles[0].rings[0].frequency", "found nothing");
  json phase = withRings();
  phase["bubbles"][0]["rings"][0]["phase"][0] = 7;
  expectError(phase, "bubbles[0].rings[0].phase[0]", "a number from -4 to 4 (radians)");
  json notObject = withRings();
  notObject["bubbles"][0]["rings"][0] = 3;
  expectError(notObject, "bubbles[0].rings[0]", "an object with frequency");
}

}  // namespace
}  // namespace fluidsound::io
