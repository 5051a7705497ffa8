// Tests of io/scene_bubbles.h: the scene's `bubbles` block (docs/bubbles.md).
#include "io/scene_bubbles.h"

#include <gtest/gtest.h>

#include "io/scene_documents.h"
#include "io/scene_file.h"

namespace fluidsound::io::scene_test {
namespace {

// Claim: every key of the block lands in its field, in the block's units; absent keys keep the
// documented defaults, and a scene without the block gets BubbleSettings{}.
TEST(SceneBubbles, ValuesLandInTheirFieldsAndDefaultsStay) {
  EXPECT_EQ(parseScene(minimalScene().dump(), "tank.json").bubbles, sim::BubbleSettings{});
  const json document = withChange(minimalScene(), "/bubbles", R"({
      "rate": 35, "entrainment_speed": 0.8, "seed_lifetime": 0.2, "min_seeds": 2, "band_cells": 1.5,
      "sizes": { "gaussian": { "mean_radius": 0.002, "radius_deviation": 0.0005, "max_radius": 0.004 } } })");
  const sim::BubbleSettings s = parseScene(document.dump(), "tank.json").bubbles;
  EXPECT_EQ(s.rate, 35.0);
  EXPECT_EQ(s.entrainmentSpeed, 0.8);
  EXPECT_EQ(s.seedLifetime, 0.2);
  EXPECT_EQ(s.minSeeds, 2);
  EXPECT_EQ(s.bandCells, 1.5);
  EXPECT_EQ(s.potentialDecayTime, sim::BubbleSettings{}.potentialDecayTime);
  const auto* g = std::get_if<sim::GaussianBubbleSizes>(&s.sizes);
  ASSERT_NE(g, nullptr);
  EXPECT_EQ(g->meanRadius, 0.002);
  EXPECT_EQ(g->maxRadius, 0.004);
  EXPECT_EQ(g->minRadius, sim::GaussianBubbleSizes{}.minRadius);
}

// Bad input (issue 6): a negative rate, a minimum radius above the maximum, an unknown
// distribution, a typo — each names its JSON path.
TEST(SceneBubbles, BadParametersNameTheirPath) {
  expectError(parseError(withChange(minimalScene(), "/bubbles", R"({"rate": -1})").dump()), "bubbles.rate",
              "a number >= 0");
  expectError(parseError(withChange(minimalScene(), "/bubbles",
                                    R"({"sizes": {"power_law": {"min_radius": 0.006, "max_radius": 0.005}}})")
                             .dump()),
              "bubbles.sizes.power_law.max_radius", "a radius > min_radius");
  expectError(parseError(withChange(minimalScene(), "/bubbles", R"({"sizes": {"lognormal": {}}})").dump()),
              "bubbles.sizes.lognormal", "one of");
  expectError(parseError(withChange(minimalScene(), "/bubbles", R"({"sizes": {}})").dump()), "bubbles.sizes",
              "exactly one distribution");
  expectError(parseError(withChange(minimalScene(), "/bubbles", R"({"rates": 3})").dump()), "bubbles.rates",
              "one of");
  expectError(parseError(withChange(minimalScene(), "/bubbles", R"({"min_seeds": 0})").dump()),
              "bubbles.min_seeds", "an integer from 1");
  expectError(parseError(withChange(minimalScene(), "/bubbles",
                                    R"({"sizes": {"gaussian": {"mean_radius": 0.001}}})").dump()),
              "bubbles.sizes.gaussian.radius_deviation", "a number > 0");
}

}  // namespace
}  // namespace fluidsound::io::scene_test
