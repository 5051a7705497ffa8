// tests/io/bubble_track_fast_reader_test.cpp — the one-pass reader of `fluidsound.bubbles/1`:
// what fluidsound writes reads back bit-identical, its numbers are the doubles nlohmann-json
// reads, and anything outside its plain subset or invalid is declined (left to the validating
// reader, whose messages tests/io/bubble_track_file_test.cpp checks).
#include "io/bubble_track_fast_reader.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "io/bubble_track_file.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

using acoustics::BubbleTrack;
using acoustics::BubbleTrackSet;
using acoustics::TrackSample;

/// A set of many bubbles with numbers spread over many decades (radii 10 µm–5 cm, times up to
/// minutes), some without a track or an amplitude: what the simulation and transfer stages write.
BubbleTrackSet randomSet(std::uint32_t seed, bool withTransfer) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  BubbleTrackSet set;
  set.sampleRate = 44100.0;
  set.duration = 120.0 * unit(random);
  set.listeners = {"left", "right", "far away"};
  for (int b = 0; b < 200; ++b) {
    BubbleTrack bubble;
    bubble.radius = 1e-5 * std::pow(5000.0, unit(random));
    bubble.birth = 100.0 * unit(random);
    if (b % 3 == 0) bubble.amplitude = std::pow(10.0, -6.0 * unit(random));
    double t = bubble.birth;
    const int samples = b % 7 == 0 ? 0 : 1 + b % 11;
    for (int s = 0; s < samples; ++s) {
      TrackSample sample;
      sample.time = t;
      t += 1.0 / 30.0 * (0.5 + unit(random));
      sample.depth = bubble.radius * (1.0 + 1e3 * unit(random));
      if (withTransfer)
        for (int l = 0; l < 3; ++l) sample.transfer.push_back((unit(random) - 0.2) * std::pow(10.0, -8.0 * unit(random)));
      sample.position = std::array<double, 3>{unit(random) - 0.5, 1e-9 * unit(random), 3.0 * unit(random)};
      bubble.track.push_back(sample);
    }
    set.bubbles.push_back(bubble);
  }
  return set;
}

std::string writtenText(const BubbleTrackSet& set) {
  test::TempFolder folder;
  const auto path = folder.path() / "bubbles.json";
  writeBubbleTracks(path, set);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The DESIGN.md example with `body` as its only bubble's track sample.
std::string withSample(const std::string& sample) {
  return R"({"format": "fluidsound.bubbles/1", "listeners": ["left", "right"],
             "bubbles": [ {"radius": 0.001, "birth": 0.25, "track": [)" + sample + "]}]}";
}

// Claim: every number fluidsound writes (the shortest round-trip text) reads back as the same
// double, so write → read is the identity. Reference: the set written. Tolerance: none (== on
// doubles: bit-identical but for the sign of zero, which no field here has).
TEST(BubbleTrackFastReader, WhatFluidsoundWritesReadsBackExactly) {
  for (const bool transfer : {false, true}) {
    const BubbleTrackSet set = randomSet(transfer ? 7 : 8, transfer);
    const std::optional<BubbleTrackSet> read = parsePlainBubbleTracks(writtenText(set), TransferValues::Optional);
    ASSERT_TRUE(read.has_value()) << "a document fluidsound wrote was declined";
    EXPECT_TRUE(*read == set);
  }
}

// Claim: a number reads as the double nlohmann-json gives for the same text (both correctly
// rounded), including integers, exponents, subnormals and more digits than a double holds, within
// a transfer value's range (|v| <= 1e6). Reference: nlohmann::json::parse of the same literal.
// Tolerance: none (bit patterns compared).
TEST(BubbleTrackFastReader, NumbersAreTheDoublesNlohmannJsonReads) {
  for (const std::string literal :
       {"48000", "0.1", "1e-3", "2.5E+2", "0.30000000000000004", "4.9e-324", "2.2250738585072011e-308",
        "999999.999999999999999999999", "-999999.99999999999999999999", "1000000", "-7", "-0.0",
        "1e-300", "0.000123456789012345678901234567890"}) {
    const double expected = nlohmann::json::parse(literal).get<double>();
    const std::optional<BubbleTrackSet> read = parsePlainBubbleTracks(
        withSample(R"({"t": 1, "depth": 2, "transfer": [)" + literal + ", 0]}"), TransferValues::Required);
    ASSERT_TRUE(read.has_value()) << literal;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(read->bubbles[0].track[0].transfer[0]),
              std::bit_cast<std::uint64_t>(expected))
        << literal << ": read " << read->bubbles[0].track[0].transfer[0] << ", nlohmann " << expected;
  }
}

// Claim: key order and whitespace do not matter, as in any JSON reader. Reference: the same
// document in the written order. Tolerance: none.
TEST(BubbleTrackFastReader, KeyOrderAndWhitespaceDoNotMatter) {
  const std::optional<BubbleTrackSet> a = parsePlainBubbleTracks(
      withSample(R"({"t": 0.25, "depth": 0.03, "transfer": [1.0, 0.8], "position": [1, 2, 3]})"),
      TransferValues::Required);
  const std::optional<BubbleTrackSet> b = parsePlainBubbleTracks(
      "\t\r\n" + withSample("{ \"position\" : [ 1 ,2,3 ] ,\n\"transfer\":[1.0,0.8],\"depth\":0.03,\"t\":0.25}") + " \n",
      TransferValues::Required);
  ASSERT_TRUE(a.has_value());
  ASSERT_TRUE(b.has_value());
  EXPECT_TRUE(*a == *b);
  EXPECT_EQ(a->bubbles[0].track[0].position, (std::array<double, 3>{1.0, 2.0, 3.0}));
}

// Claim: every invalid document, and every valid one outside the plain subset, is declined (so
// that the validating reader names the problem, or reads it with its full rules).
TEST(BubbleTrackFastReader, DeclinesInvalidAndUnusualDocuments) {
  const std::vector<std::string> declined = {
      withSample(R"({"t": 1, "depth": 0.0005, "transfer": [1, 1]})"),    // depth ≤ radius
      withSample(R"({"t": -1, "depth": 2, "transfer": [1, 1]})"),        // negative time
      withSample(R"({"t": 1, "depth": 2, "transfer": [1]})"),            // one value, two listeners
      withSample(R"({"t": 1, "depth": 2, "transfer": []})"),             // no value
      withSample(R"({"t": 1, "depth": 2})"),                             // transfer required
      withSample(R"({"t": 2, "depth": 2, "transfer": [1, 1]}, {"t": 1, "depth": 2, "transfer": [1, 1]})"),
      withSample(R"({"t": 1, "depth": 2, "transfer": [1, 1], "position": [1, 2]})"),
      withSample(R"({"t": 1, "depth": 2, "transfer": [1, 1], "x_note": 1})"),    // extension key
      withSample(R"({"t": 1, "t": 2, "depth": 2, "transfer": [1, 1]})"),         // duplicate key
      withSample(R"({"t": 1, "depth": 2, "transfer": [-0, 1]})"),                 // integer −0
      withSample(R"({"t": 1, "depth": 2, "transfer": [1e999, 1]})"),              // beyond double
      withSample(R"({"t": 1, "depth": 2, "transfer": [01, 1]})"),                 // not JSON
      withSample(R"({"t": 1, "depth": 2, "transfer": [1., 1]})"),                 // not JSON
      withSample(R"({"t": 1, "depth": 2, "transfer": [1, 1]} )") + " x",          // trailing text
      R"({"format": "fluidsound.bubbles/2", "bubbles": []})",
      R"({"bubbles": []})",
      R"({"format": "fluidsound.bubbles/1"})",
      R"({"format": "fluidsound.bubbles/1", "sample_rate": 0, "bubbles": []})",
      R"({"format": "fluidsound.bubbles/1", "listeners": ["caf\u00e9"], "bubbles": []})",
      R"({"format": "fluidsound.bubbles/1", "bubbles": [{"radius": 0.001}]})",
      R"({"format": "fluidsound.bubbles/1", "bubbles": [{"radius": 0.001, "birth": 0, "amplitude": 0}]})",
      R"({"format": "fluidsound.bubbles/1", "bubbles": [)",
  };
  for (const std::string& text : declined)
    EXPECT_FALSE(parsePlainBubbleTracks(text, TransferValues::Required).has_value()) << text;
  // Transfer in some samples only: declined even when optional (all or nothing).
  EXPECT_FALSE(parsePlainBubbleTracks(
                   withSample(R"({"t": 1, "depth": 2, "transfer": [1, 1]}, {"t": 2, "depth": 2})"),
                   TransferValues::Optional)
                   .has_value());
  EXPECT_TRUE(parsePlainBubbleTracks(withSample(R"({"t": 1, "depth": 2}, {"t": 2, "depth": 2})"),
                                     TransferValues::Optional)
                  .has_value());
}

}  // namespace
}  // namespace fluidsound::io
