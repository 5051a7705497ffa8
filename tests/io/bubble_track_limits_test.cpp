// tests/io/bubble_track_limits_test.cpp — every number of a `fluidsound.bubbles/1` file outside its
// documented range (io/bubble_track_limits.h) is refused by both readers, naming the field; a key
// given twice and a document nested too deep are refused too.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "io/bubble_track_fast_reader.h"
#include "io/bubble_track_file.h"
#include "io/input_error.h"
#include "io/json_validation.h"
#include "support/input_error_expectations.h"

namespace fluidsound::io {
namespace {

using nlohmann::json;

/// A valid plain document with one bubble of one sample, where `field` (a JSON pointer) is set to
/// the number written as `literal` (inserted as text, so 1e308 and 5e-324 stay what they are).
std::string documentWith(const std::string& pointer, const std::string& literal) {
  json document = json::parse(R"({
    "format": "fluidsound.bubbles/1", "sample_rate": 48000, "duration": 1.0,
    "bubbles": [ { "radius": 0.001, "birth": 0.1, "amplitude": 0.01,
                   "track": [ { "t": 0.1, "depth": 0.02, "transfer": [1.0], "position": [0, 0, 0] } ] } ]
  })");
  document[json::json_pointer(pointer)] = "@";
  std::string text = document.dump();
  text.replace(text.find("\"@\""), 3, literal);
  return text;
}

struct OutOfRange {
  const char* name;
  const char* pointer;
  const char* literal;
  const char* field;
  const char* expected;
};

class BubbleTrackOutOfRange : public testing::TestWithParam<OutOfRange> {};

// Claim: the validating reader names the field and its range, and the one-pass reader declines the
// same document (so the two readers accept the same set of files).
TEST_P(BubbleTrackOutOfRange, IsRefusedByBothReadersNamingTheField) {
  const OutOfRange& c = GetParam();
  const std::string text = documentWith(c.pointer, c.literal);
  EXPECT_FALSE(parsePlainBubbleTracks(text, TransferValues::Required).has_value()) << text;
  const InputError error =
      test::inputErrorOf([](const std::string& t) { parseBubbleTracks(t, "drip.json"); }, text);
  test::expectInputError(error, "drip.json", c.field, c.expected, test::ExpectedAt::RightAfterHead);
  EXPECT_NE(std::string(error.what()).find(std::string("found ")), std::string::npos)
      << error.what();
}

constexpr const char* kRadius = "a number from 1e-06 to 1 (metres)";
constexpr const char* kAmplitude = "a number from 1e-09 to 100000 (Pa at 1 m)";
constexpr const char* kRate = "an integer from 8000 to 768000 (Hz)";
constexpr const char* kTime = "a number from 0 to 1e+06 (seconds)";
constexpr const char* kDepth = "a number > radius (0.001 m) and <= 11000 (metres)";
constexpr const char* kTransfer = "a number from -1e+06 to 1e+06 (pressure ratio)";
constexpr const char* kPosition = "a number from -1e+06 to 1e+06 (metres)";

INSTANTIATE_TEST_SUITE_P(
    Fields, BubbleTrackOutOfRange,
    testing::Values(
        OutOfRange{"radius_huge", "/bubbles/0/radius", "1e308", "bubbles[0].radius", kRadius},
        OutOfRange{"radius_denormal", "/bubbles/0/radius", "5e-324", "bubbles[0].radius", kRadius},
        OutOfRange{"radius_zero", "/bubbles/0/radius", "0", "bubbles[0].radius", kRadius},
        OutOfRange{"radius_integer_beyond_2_64", "/bubbles/0/radius",
                   "123456789012345678901234567890", "bubbles[0].radius", kRadius},
        OutOfRange{"amplitude_huge", "/bubbles/0/amplitude", "1e308", "bubbles[0].amplitude",
                   kAmplitude},
        OutOfRange{"amplitude_denormal", "/bubbles/0/amplitude", "5e-324", "bubbles[0].amplitude",
                   kAmplitude},
        OutOfRange{"amplitude_negative", "/bubbles/0/amplitude", "-1", "bubbles[0].amplitude",
                   kAmplitude},
        OutOfRange{"sample_rate_huge", "/sample_rate", "1e308", "sample_rate", kRate},
        OutOfRange{"sample_rate_fraction", "/sample_rate", "44100.5", "sample_rate", kRate},
        OutOfRange{"sample_rate_below", "/sample_rate", "7999", "sample_rate", kRate},
        OutOfRange{"sample_rate_above", "/sample_rate", "768001", "sample_rate", kRate},
        OutOfRange{"sample_rate_negative", "/sample_rate", "-48000", "sample_rate", kRate},
        OutOfRange{"duration_huge", "/duration", "1e9", "duration",
                   "a number > 0 and <= 1e+06 (seconds)"},
        OutOfRange{"duration_negative_denormal", "/duration", "-5e-324", "duration",
                   "a number > 0 and <= 1e+06 (seconds)"},
        OutOfRange{"birth_huge", "/bubbles/0/birth", "1e308", "bubbles[0].birth", kTime},
        OutOfRange{"t_huge", "/bubbles/0/track/0/t", "1e300", "bubbles[0].track[0].t", kTime},
        OutOfRange{"t_negative", "/bubbles/0/track/0/t", "-1", "bubbles[0].track[0].t", kTime},
        OutOfRange{"depth_huge", "/bubbles/0/track/0/depth", "1e308", "bubbles[0].track[0].depth",
                   kDepth},
        OutOfRange{"depth_denormal", "/bubbles/0/track/0/depth", "5e-324",
                   "bubbles[0].track[0].depth", kDepth},
        OutOfRange{"transfer_huge", "/bubbles/0/track/0/transfer/0", "1e308",
                   "bubbles[0].track[0].transfer[0]", kTransfer},
        OutOfRange{"transfer_huge_negative", "/bubbles/0/track/0/transfer/0", "-1e7",
                   "bubbles[0].track[0].transfer[0]", kTransfer},
        OutOfRange{"position_huge", "/bubbles/0/track/0/position/2", "1e308",
                   "bubbles[0].track[0].position[2]", kPosition}),
    [](const testing::TestParamInfo<OutOfRange>& info) { return std::string(info.param.name); });

// Claim: the limits are inclusive where documented: a document at every bound reads, in both
// readers, to the same values.
TEST(BubbleTrackLimits, ValuesAtTheBoundsAreAccepted) {
  for (const auto& [pointer, literal] : std::initializer_list<std::pair<const char*, const char*>>{
           {"/sample_rate", "8000"},
           {"/sample_rate", "768000"},
           {"/sample_rate", "44100.0"},
           {"/bubbles/0/radius", "1e-6"},
           {"/bubbles/0/amplitude", "1e5"},
           {"/bubbles/0/amplitude", "1e-9"},
           {"/duration", "1e6"},
           {"/bubbles/0/track/0/depth", "11000"},
           {"/bubbles/0/track/0/transfer/0", "-1e6"},
           {"/bubbles/0/track/0/position/0", "1e6"}}) {
    const std::string text = documentWith(pointer, literal);
    EXPECT_TRUE(parsePlainBubbleTracks(text, TransferValues::Required).has_value()) << text;
    EXPECT_NO_THROW(parseBubbleTracks(text, "drip.json")) << text;
  }
}

// Claim: a key given twice is an error in a bubble-track file as in a scene (nlohmann would keep
// the last silently), at the top level and inside a bubble, naming the JSON path.
TEST(BubbleTrackLimits, KeyGivenTwiceIsRefusedNamingItsPath) {
  const std::string top =
      R"({"format": "fluidsound.bubbles/1", "sample_rate": 48000, "sample_rate": 44100,
                               "bubbles": []})";
  test::expectInputError(
      test::inputErrorOf([](const std::string& t) { parseBubbleTracks(t, "drip.json"); }, top),
      "drip.json", "sample_rate", "each key at most once in an object",
      test::ExpectedAt::RightAfterHead);
  const std::string inner = R"({"format": "fluidsound.bubbles/1",
      "bubbles": [{"radius": 0.001, "birth": 0}, {"radius": 0.001, "birth": 0, "radius": 0.002}]})";
  test::expectInputError(
      test::inputErrorOf([](const std::string& t) { parseBubbleTracks(t, "drip.json"); }, inner),
      "drip.json", "bubbles[1].radius", "each key at most once in an object",
      test::ExpectedAt::RightAfterHead);
}

// Claim: a document nested deeper than kMaxJsonDepth is refused where the limit is hit, naming the
// path of the first level too deep and the limit. 100 000 levels (200 KB) would take gigabytes
// if each level held its path; the check stops at level 65, so this takes milliseconds.
TEST(BubbleTrackLimits, DeepNestingIsRefusedAtTheLimit) {
  const std::size_t levels = 100000;
  const std::string text = R"({"format": "fluidsound.bubbles/1", "bubbles": )" +
                           std::string(levels, '[') + std::string(levels, ']') + "}";
  const InputError error =
      test::inputErrorOf([](const std::string& t) { parseBubbleTracks(t, "drip.json"); }, text);
  std::string field = "bubbles";
  for (std::size_t level = 2; level <= kMaxJsonDepth; ++level) field += "[0]";
  test::expectInputError(error, "drip.json", field, "at most 64 nested arrays and objects",
                         test::ExpectedAt::RightAfterHead);
}

// Claim: exactly kMaxJsonDepth levels are allowed (the limit is not off by one): the document
// below has 64 open levels and fails only on its content.
TEST(BubbleTrackLimits, NestingAtTheLimitParses) {
  const std::string text = R"({"format": "fluidsound.bubbles/1", "x_deep": )" +
                           std::string(kMaxJsonDepth - 1, '[') +
                           std::string(kMaxJsonDepth - 1, ']') + R"(, "bubbles": []})";
  EXPECT_NO_THROW(parseBubbleTracks(text, "drip.json"));
}

}  // namespace
}  // namespace fluidsound::io
