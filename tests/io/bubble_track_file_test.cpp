// tests/io/bubble_track_file_test.cpp — `fluidsound.bubbles/1`: valid files parse with their
// defaults, every kind of bad input gives one line naming file, JSON path and expectation, and
// write → read gives back the same tracks.
#include "io/bubble_track_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "support/input_error_expectations.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;
using acoustics::BubbleTrack;
using acoustics::BubbleTrackSet;
using acoustics::TrackSample;
using nlohmann::json;

using test::TempFolder;

/// The example of DESIGN.md, plus a second bubble without a track but with an amplitude.
json designExample() {
  return json::parse(R"({
    "format": "fluidsound.bubbles/1",
    "sample_rate": 48000,
    "duration": 2.0,
    "listeners": ["left", "right"],
    "bubbles": [
      { "radius": 0.001, "birth": 0.25,
        "track": [ { "t": 0.25,   "depth": 0.030, "transfer": [1.0, 0.8] },
                   { "t": 0.2667, "depth": 0.025, "transfer": [0.9, 0.7] } ] },
      { "radius": 0.002, "birth": 0.5, "amplitude": 0.01 }
    ]
  })");
}

/// The InputError that parsing `text` as drip.json throws (a test failure if none).
InputError parseError(const std::string& text) {
  return test::inputErrorOf([](const std::string& t) { parseBubbleTracks(t, "drip.json"); }, text);
}

/// The error is one line that names drip.json, exactly `field`, and contains `expected`.
void expectError(const InputError& error, const std::string& field, const std::string& expected) {
  test::expectInputError(error, "drip.json", field, expected, test::ExpectedAt::Anywhere);
}

// ---- valid input --------------------------------------------------------------------------------

TEST(BubbleTrackFile, ParsesTheDesignExample) {
  const BubbleTrackSet set = parseBubbleTracks(designExample().dump(), "drip.json");
  EXPECT_EQ(set.sampleRate, 48000.0);
  EXPECT_EQ(set.duration, 2.0);
  EXPECT_EQ(set.listeners, (std::vector<std::string>{"left", "right"}));
  EXPECT_EQ(set.channelCount(), 2u);
  ASSERT_EQ(set.bubbles.size(), 2u);
  const BubbleTrack& first = set.bubbles[0];
  EXPECT_EQ(first.radius, 0.001);
  EXPECT_EQ(first.birth, 0.25);
  EXPECT_FALSE(first.amplitude.has_value());
  ASSERT_EQ(first.track.size(), 2u);
  EXPECT_EQ(first.track[1].time, 0.2667);
  EXPECT_EQ(first.track[1].depth, 0.025);
  EXPECT_EQ(first.track[1].transfer, (std::vector<double>{0.9, 0.7}));
  EXPECT_FALSE(first.track[1].position.has_value());
  EXPECT_EQ(set.bubbles[1].amplitude, 0.01);
  EXPECT_TRUE(set.bubbles[1].track.empty());
}

TEST(BubbleTrackFile, AbsentOptionalFieldsTakeTheirDefaults) {
  const BubbleTrackSet set = parseBubbleTracks(
      R"({"format": "fluidsound.bubbles/1", "bubbles": [{"radius": 0.003, "birth": 0}]})",
      "drip.json");
  EXPECT_EQ(set.sampleRate, 48000.0);  // DESIGN.md: default 48000 Hz
  EXPECT_FALSE(set.duration.has_value());
  EXPECT_TRUE(set.listeners.empty());
  EXPECT_EQ(set.channelCount(), 1u);  // no listeners: one channel
  ASSERT_EQ(set.bubbles.size(), 1u);
  EXPECT_FALSE(set.bubbles[0].amplitude.has_value());
  EXPECT_TRUE(set.bubbles[0].track.empty());
}

TEST(BubbleTrackFile, ExtensionKeysAreAcceptedAndIgnored) {
  json withExtensions = designExample();
  withExtensions["x_solver"] = {{"name", "flip"}, {"cells", 128}};
  withExtensions["bubbles"][0]["x-seed-id"] = 17;
  withExtensions["bubbles"][0]["track"][1]["x_frame"] = 8;
  EXPECT_EQ(parseBubbleTracks(withExtensions.dump(), "drip.json"),
            parseBubbleTracks(designExample().dump(), "drip.json"));
}

TEST(BubbleTrackFile, PositionIsReadInMetres) {
  json document = designExample();
  document["bubbles"][0]["track"][0]["position"] = {0.1, -0.2, 0.3};
  const BubbleTrackSet set = parseBubbleTracks(document.dump(), "drip.json");
  EXPECT_EQ(set.bubbles[0].track[0].position, (std::array<double, 3>{0.1, -0.2, 0.3}));
  EXPECT_FALSE(set.bubbles[0].track[1].position.has_value());
}

TEST(BubbleTrackFile, FileWithoutAnyTransferIsAcceptedWhenTransferIsOptional) {
  // The output of `fluidsound simulate` has depths and positions; transfer comes later.
  json document = designExample();
  for (auto& sample : document["bubbles"][0]["track"]) sample.erase("transfer");
  const BubbleTrackSet set =
      parseBubbleTracks(document.dump(), "drip.json", TransferValues::Optional);
  EXPECT_TRUE(set.bubbles[0].track[0].transfer.empty());
  EXPECT_TRUE(set.bubbles[0].track[1].transfer.empty());
}

// ---- bad input: one error per case
// ----------------------------------------------------------------

TEST(BubbleTrackFile, MalformedJsonGivesTheParserMessage) {
  const InputError error = parseError(R"({"format": "fluidsound.bubbles/1", "bubbles" []})");
  expectError(error, "", "valid JSON, found parse error at line 1, column 46");
  EXPECT_NE(std::string(error.what()).find("expected ':'"), std::string::npos) << error.what();
  EXPECT_EQ(std::string(error.what()).find("[json.exception"), std::string::npos) << error.what();
}

TEST(BubbleTrackFile, TruncatedJsonGivesTheParserMessage) {
  const std::string text = designExample().dump(2);
  const InputError error = parseError(text.substr(0, text.rfind(']')));  // cut before the end
  expectError(error, "", "valid JSON, found parse error");
  EXPECT_NE(std::string(error.what()).find("unexpected end of input"), std::string::npos)
      << error.what();
}

TEST(BubbleTrackFile, OverflowingNumberIsInvalidJson) {
  json document = designExample();
  std::string text = document.dump();
  text.replace(text.find("0.001"), 5, "1e999");
  expectError(parseError(text), "", "valid JSON, found number overflow parsing '1e999'");
}

TEST(BubbleTrackFile, WrongFormatTagShowsTheTagFound) {
  json document = designExample();
  document["format"] = "fluidsound.bubbles/2";
  const InputError error = parseError(document.dump());
  expectError(error, "format", R"(expected "fluidsound.bubbles/1", found "fluidsound.bubbles/2")");
}

TEST(BubbleTrackFile, MissingFormatTagIsNamed) {
  json document = designExample();
  document.erase("format");
  expectError(parseError(document.dump()), "format", R"("fluidsound.bubbles/1", found nothing)");
}

TEST(BubbleTrackFile, TopLevelArrayIsRejected) {
  expectError(parseError("[1, 2]"), "", "a JSON object");
}

TEST(BubbleTrackFile, MissingBubblesIsNamed) {
  json document = designExample();
  document.erase("bubbles");
  expectError(parseError(document.dump()), "bubbles", "an array of bubbles, found nothing");
}

TEST(BubbleTrackFile, NegativeRadiusIsNamedWithItsValue) {
  json document = designExample();
  document["bubbles"][1]["radius"] = -0.001;
  const InputError error = parseError(document.dump());
  EXPECT_STREQ(error.what(),
               "drip.json: bubbles[1].radius: expected a number from 1e-06 to 1 (metres), found -0.001");
}

TEST(BubbleTrackFile, NonNumericRadiusIsNamed) {
  json document = designExample();
  document["bubbles"][0]["radius"] = "1mm";
  expectError(parseError(document.dump()), "bubbles[0].radius",
              R"(a number from 1e-06 to 1 (metres), found "1mm")");
}

TEST(BubbleTrackFile, MissingBirthIsNamed) {
  json document = designExample();
  document["bubbles"][1].erase("birth");
  expectError(parseError(document.dump()), "bubbles[1].birth",
              "a number from 0 to 1e+06 (seconds), found nothing (required)");
}

TEST(BubbleTrackFile, NonPositiveSampleRateIsNamed) {
  json document = designExample();
  document["sample_rate"] = 0;
  expectError(parseError(document.dump()), "sample_rate", "an integer from 8000 to 768000 (Hz), found 0");
}

TEST(BubbleTrackFile, NonStringListenerIsNamed) {
  json document = designExample();
  document["listeners"][1] = 2;
  expectError(parseError(document.dump()), "listeners[1]", "a string (listener name), found 2");
}

TEST(BubbleTrackFile, DepthNotAboveTheRadiusIsNamed) {
  // Depth is centre to surface: a bubble with depth ≤ radius would stick out of the liquid.
  json document = designExample();
  document["bubbles"][0]["track"][1]["depth"] = 0.001;
  expectError(parseError(document.dump()), "bubbles[0].track[1].depth",
              "a number > radius (0.001 m) and <= 11000 (metres), found 0.001");
}

TEST(BubbleTrackFile, UnsortedTrackNamesThePreviousTime) {
  json document = designExample();
  document["bubbles"][0]["track"][1]["t"] = 0.25;  // equal to track[0].t: not strictly later
  expectError(parseError(document.dump()), "bubbles[0].track[1].t",
              "a time greater than track[0].t = 0.25 (samples in time order), found 0.25");
}

TEST(BubbleTrackFile, NegativeTrackTimeIsNamed) {
  json document = designExample();
  document["bubbles"][0]["track"][0]["t"] = -0.1;
  expectError(parseError(document.dump()), "bubbles[0].track[0].t",
              "a number from 0 to 1e+06 (seconds), found -0.1");
}

TEST(BubbleTrackFile, WrongTransferLengthNamesTheListenerCount) {
  json document = designExample();
  document["bubbles"][0]["track"][1]["transfer"] = {0.9};
  expectError(parseError(document.dump()), "bubbles[0].track[1].transfer",
              "an array of 2 numbers (one per listener), found an array of 1 value");
}

TEST(BubbleTrackFile, WithoutListenersTransferHasOneEntry) {
  json document = designExample();
  document.erase("listeners");
  expectError(parseError(document.dump()), "bubbles[0].track[0].transfer",
              "an array of 1 number (one per listener; no listeners: one channel), found an array "
              "of 2 values");
}

TEST(BubbleTrackFile, NonNumericTransferEntryIsNamed) {
  json document = designExample();
  document["bubbles"][0]["track"][0]["transfer"][1] = nullptr;
  expectError(parseError(document.dump()), "bubbles[0].track[0].transfer[1]",
              "a number from -1e+06 to 1e+06 (pressure ratio), found null");
}

TEST(BubbleTrackFile, MissingTransferIsNamed) {
  json document = designExample();
  for (auto& sample : document["bubbles"][0]["track"]) sample.erase("transfer");
  expectError(parseError(document.dump()), "bubbles[0].track[0].transfer",
              "an array of 2 numbers (one per listener), found nothing (required)");
}

TEST(BubbleTrackFile, OptionalTransferMissingFromOneSampleOnlyIsNamed) {
  json document = designExample();
  document["bubbles"][0]["track"][1].erase("transfer");
  try {
    parseBubbleTracks(document.dump(), "drip.json", TransferValues::Optional);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    expectError(
        error, "bubbles[0].track[1].transfer",
        "an array of 2 numbers (one per listener), as in bubbles[0].track[0], found nothing");
  }
}

TEST(BubbleTrackFile, PositionOfWrongLengthIsNamed) {
  json document = designExample();
  document["bubbles"][0]["track"][0]["position"] = {0.1, 0.2};
  expectError(parseError(document.dump()), "bubbles[0].track[0].position",
              "an array of 3 numbers [x, y, z] (metres), found an array of 2 values");
}

TEST(BubbleTrackFile, UnknownKeySuggestsTheClosestKnownKey) {
  json document = designExample();
  document["bubbles"][0]["radus"] = 0.001;
  expectError(parseError(document.dump()), "bubbles[0].radus",
              "one of radius, birth, amplitude, rings, track (did you mean 'radius'?)");
}

TEST(BubbleTrackFile, UnknownCamelCaseKeySuggestsTheSnakeCaseKey) {
  json document = designExample();
  document["sampleRate"] = 44100;
  expectError(
      parseError(document.dump()), "sampleRate",
      "one of format, sample_rate, duration, listeners, heads, hrtf, bubbles (did you mean 'sample_rate'?)");
}

TEST(BubbleTrackFile, UnknownKeyWithoutNearMatchPointsToExtensionKeys) {
  json document = designExample();
  document["bubbles"][0]["track"][0]["colour"] = "blue";
  expectError(parseError(document.dump()), "bubbles[0].track[0].colour",
              "one of t, depth, transfer, position (or an extension key starting with x_ or x-)");
}

TEST(BubbleTrackFile, MissingFileIsAnInputErrorNamingIt) {
  TempFolder folder;
  const fs::path path = folder.path() / "nope.json";
  try {
    readBubbleTracks(path);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path.string());
    EXPECT_EQ(error.field(), "");
    EXPECT_EQ(std::string(error.what()),
              path.string() + ": expected a readable file, found no such file");
  }
}

TEST(BubbleTrackFile, FolderIsNotAReadableFile) {
  TempFolder folder;
  EXPECT_THROW(readBubbleTracks(folder.path()), InputError);
}

TEST(BubbleTrackFile, ReadFileErrorsNameThePathAsGiven) {
  TempFolder folder;
  const fs::path path = folder.path() / "drip.json";
  {
    std::ofstream out(path);
    out << R"({"format": "fluidsound.bubbles/1", "bubbles": [{"radius": 0, "birth": 0}]})";
  }
  try {
    readBubbleTracks(path);
    FAIL() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              path.string() + ": bubbles[0].radius: expected a number from 1e-06 to 1 (metres), found 0");
  }
}

// ---- writing -----------------------------------------------------------------------------------

/// Tracks whose numbers have no short decimal form, so a lossy writer would change them.
BubbleTrackSet awkwardTracks() {
  BubbleTrackSet set;
  set.sampleRate = 44100.0;
  set.duration = 1.0 / 3.0;
  set.listeners = {"left", "right \"quoted\"", "ünïcode"};
  BubbleTrack bubble;
  bubble.radius = 0.1 + 0.2;  // 0.30000000000000004
  bubble.birth = std::nextafter(0.25, 1.0);
  bubble.amplitude = 1e-7 / 3.0;
  for (int j = 0; j < 3; ++j) {
    TrackSample sample;
    sample.time = bubble.birth + j / 30.0;
    sample.depth = 1.0 + j * std::numeric_limits<double>::epsilon();
    sample.transfer = {1.0 / 7.0, -2.0 / 3.0, 1e-300};
    if (j != 1) sample.position = std::array<double, 3>{0.1, 2.0 / 3.0, -5e-17};
    bubble.track.push_back(sample);
  }
  set.bubbles.push_back(bubble);
  BubbleTrack trackless;
  trackless.radius = 5e-5;
  trackless.birth = 0.0;
  set.bubbles.push_back(trackless);
  return set;
}

TEST(BubbleTrackFile, WriteThenReadGivesEqualTracks) {
  // Claim: write → read is the identity on every field, bit for bit (shortest round-trip decimal).
  TempFolder folder;
  const fs::path path = folder.path() / "bubbles.json";
  const BubbleTrackSet tracks = awkwardTracks();
  writeBubbleTracks(path, tracks);
  EXPECT_EQ(readBubbleTracks(path), tracks);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"bubbles.json"});  // no temporary left
}

TEST(BubbleTrackFile, WriteThenReadKeepsDefaultsAbsent) {
  TempFolder folder;
  const fs::path path = folder.path() / "bubbles.json";
  BubbleTrackSet tracks;  // no duration, no listeners, no bubbles
  writeBubbleTracks(path, tracks);
  EXPECT_EQ(readBubbleTracks(path), tracks);
  std::ifstream in(path);
  const json written = json::parse(in);
  EXPECT_FALSE(written.contains("duration"));
  EXPECT_FALSE(written.contains("listeners"));
  EXPECT_EQ(written["format"], "fluidsound.bubbles/1");
}

TEST(BubbleTrackFile, TracksWithoutTransferRoundTripWhenTransferIsOptional) {
  TempFolder folder;
  const fs::path path = folder.path() / "bubbles.json";
  BubbleTrackSet tracks = awkwardTracks();
  for (TrackSample& sample : tracks.bubbles[0].track) sample.transfer.clear();
  writeBubbleTracks(path, tracks);
  EXPECT_EQ(readBubbleTracks(path, TransferValues::Optional), tracks);
  EXPECT_THROW(readBubbleTracks(path), InputError);  // synthesis needs transfer values
}

TEST(BubbleTrackFile, WriteReplacesAnExistingFile) {
  TempFolder folder;
  const fs::path path = folder.path() / "bubbles.json";
  { std::ofstream(path) << "old"; }
  writeBubbleTracks(path, awkwardTracks());
  EXPECT_EQ(readBubbleTracks(path), awkwardTracks());
}

TEST(BubbleTrackFile, WritingInvalidTracksThrowsAndLeavesNoFile) {
  TempFolder folder;
  BubbleTrackSet tracks = awkwardTracks();
  tracks.bubbles[0].track[2].depth = std::numeric_limits<double>::quiet_NaN();
  try {
    writeBubbleTracks(folder.path() / "bubbles.json", tracks);
    FAIL() << "no std::invalid_argument";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("bubbles[0].track[2].depth"), std::string::npos)
        << error.what();
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(BubbleTrackFile, WritingIntoAMissingFolderIsAnOutputError) {
  TempFolder folder;
  const fs::path path = folder.path() / "missing" / "bubbles.json";
  try {
    writeBubbleTracks(path, awkwardTracks());
    FAIL() << "no OutputError";
  } catch (const OutputError& error) {
    EXPECT_TRUE(std::string(error.what()).starts_with(path.string() + ": cannot write"))
        << error.what();
  }
}

}  // namespace
}  // namespace fluidsound::io
