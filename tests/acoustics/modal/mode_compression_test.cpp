// tests/acoustics/modal/mode_compression_test.cpp — the discrimination limit and the grouping of
// modes against shared solids.md T8 (after the thesis §3.51–3.52).
#include "acoustics/modal/mode_compression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace fluidsound::acoustics {
namespace {

// Zwicker & Fastl §7.2: 3.6 Hz below 500 Hz, 0.7 % of f above.
TEST(ModeCompression, DiscriminationLimitGrowsWithFrequency) {
  EXPECT_DOUBLE_EQ(frequencyDiscriminationLimit(100.0), 3.6);
  EXPECT_DOUBLE_EQ(frequencyDiscriminationLimit(500.0), 3.6);
  EXPECT_DOUBLE_EQ(frequencyDiscriminationLimit(2000.0), 14.0);
  EXPECT_DOUBLE_EQ(frequencyDiscriminationLimit(10000.0), 70.0);
}

// T8: two modes at 2000 and 2000.8 Hz merge; 2000 and 2030 Hz do not.
TEST(ModeCompression, ModesWithinTheLimitMergeOthersDoNot) {
  const std::vector<double> close{2000.0, 2000.8};
  EXPECT_EQ(groupIndistinguishableModes(close).first.size(), 1u);
  const std::vector<double> apart{2000.0, 2030.0};
  EXPECT_EQ(groupIndistinguishableModes(apart).first.size(), 2u);
}

// Every member of a group lies within the limit of its lead: a chain of modes 10 Hz apart at 2 kHz
// (limit 14 Hz) does not creep into one group.
TEST(ModeCompression, GroupsDoNotChainBeyondTheLimit) {
  std::vector<double> f;
  for (int i = 0; i < 10; ++i) f.push_back(2000.0 + 10.0 * i);
  const ModeGroups groups = groupIndistinguishableModes(f);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double lead = f[groups.first[groups.group[i]]];
    EXPECT_LT(f[i] - lead, frequencyDiscriminationLimit(lead));
  }
  EXPECT_EQ(groups.first.size(), 5u);  // 2000+2010, 2020+2030, …
}

// T8: whatever the mesh, fewer than 1000 groups are left over the audible range: a mode at every
// 0.5 Hz from 20 Hz to 20 kHz (39 961 modes, far denser than any body's spectrum) leaves the
// limit's bin count, 134 + ln(20000/514)/ln(1.007) ≈ 660, and never more than 1000.
TEST(ModeCompression, AnyDenseSpectrumLeavesFewerThanAThousandModes) {
  std::vector<double> f;
  for (double x = 20.0; x <= 20000.0; x += 0.5) f.push_back(x);
  const std::size_t groups = groupIndistinguishableModes(f).first.size();
  EXPECT_LT(groups, 1000u);
  EXPECT_GT(groups, 600u);
  EXPECT_LT(groups, 700u);
}

TEST(ModeCompression, RejectsUnsortedFrequencies) {
  const std::vector<double> f{100.0, 50.0};
  EXPECT_THROW(groupIndistinguishableModes(f), std::invalid_argument);
}

// The thesis §3.52: a mode stops when a·e^{−dt} < 1e-5 × the event's peak: ln(1e5)/d for a mode at
// the peak; 0 for one that starts below.
TEST(ModeCompression, TruncationTimeIsWhereTheModeFallsBelowTheThreshold) {
  EXPECT_NEAR(truncationTime(1.0, 10.0, 1.0), std::log(1e5) / 10.0, 1e-12);
  EXPECT_NEAR(truncationTime(0.01, 10.0, 1.0), std::log(1e3) / 10.0, 1e-12);
  EXPECT_EQ(truncationTime(1e-6, 10.0, 1.0), 0.0);
}

}  // namespace
}  // namespace fluidsound::acoustics
