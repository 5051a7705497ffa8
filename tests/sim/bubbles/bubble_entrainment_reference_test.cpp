// tests/sim/bubbles/bubble_entrainment_reference_test.cpp — the entrainment records' fast lookup
// (a slot per dense id; a hash filter and binary search for other ids) finds what a std::map by
// particle id finds, for dense, offset and scattered ids, present and absent, and for the records
// of a real step.
#include "sim/bubbles/bubble_entrainment_reference.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "sim/bubbles/bubble_entrainment.h"
#include "support/synthetic_tank.h"

namespace fluidsound::sim {
namespace {

/// Both find the same record (equal values) or both none, for every id in `queries`.
void expectSameLookups(const EntrainmentTagTable& table, const EntrainmentTagMap& map,
                       const std::vector<std::uint64_t>& queries) {
  int found = 0;
  for (const std::uint64_t id : queries) {
    const EntrainmentTag* fast = table.find(id);
    const EntrainmentTag* plain = map.find(id);
    ASSERT_EQ(fast == nullptr, plain == nullptr) << "id " << id;
    if (!fast) continue;
    EXPECT_EQ(*fast, *plain) << "id " << id;
    ++found;
  }
  EXPECT_EQ(static_cast<std::size_t>(found), table.size());
  const std::vector<EntrainmentTag> inOrder(table.tags().begin(), table.tags().end());
  EXPECT_EQ(inOrder, map.tags());
}

TEST(EntrainmentTagLookup, FindsWhatAMapByParticleIdFinds) {
  // Claim: for ids as the solver numbers them (dense from 0, with gaps), the same shifted near the
  // largest id the dense slots take, and scattered 64-bit ids (the filter and binary search),
  // records given in a shuffled order, every present id finds its record and every other id
  // (neighbours, random ids, 0, the largest id) finds none, as in the map; tags() is the map's
  // id order. Tolerance: exact (the same records).
  std::mt19937_64 random(18);
  const auto makeIds = [&](int layout) {
    std::vector<std::uint64_t> ids;
    for (std::uint64_t id = 0; ids.size() < 3000; ++id) {
      if (random() % 3 == 0) continue;  // gaps: particles without a record
      ids.push_back(layout == 0   ? id
                    : layout == 1 ? (std::uint64_t{1} << 20) + 64 * 2000 + id
                                  : random());
    }
    return ids;
  };
  for (int layout = 0; layout < 3; ++layout) {
    const std::vector<std::uint64_t> ids = makeIds(layout);
    std::vector<EntrainmentTag> records;
    for (const std::uint64_t id : ids)
      records.push_back({id, 0.001 * static_cast<double>(random() % 100),
                         1e-3 * static_cast<double>(random() % 7), -1.0 * (random() % 2)});
    std::shuffle(records.begin(), records.end(), random);
    const EntrainmentTagMap map(records);
    const EntrainmentTagTable table(records);
    std::vector<std::uint64_t> queries = {0, std::numeric_limits<std::uint64_t>::max()};
    for (const std::uint64_t id : ids) queries.insert(queries.end(), {id - 1, id, id + 1});
    for (int q = 0; q < 20000; ++q) queries.push_back(random() % 2 ? random() : random() % 8000);
    std::sort(queries.begin(), queries.end());
    queries.erase(std::unique(queries.begin(), queries.end()), queries.end());
    expectSameLookups(table, map, queries);
  }
}

TEST(EntrainmentTagLookup, RecordsOfARealStepAreFoundAsInTheMap) {
  // Claim: the records detectEntrainment returns (particles struck into a tank at 1.1 m/s, tagged
  // and seeds) are found for every particle id of the tank exactly as in a map of them.
  test::SyntheticTank tank(16, 0.0075, 0.06, 7);
  for (Vec3f& u : tank.velocities()) u = {0.0f, -1.1f, 0.0f};
  const EntrainmentStep step = detectEntrainment(tank.state(), {}, BubbleSettings{}, 0.0);
  ASSERT_GT(step.tags.size(), 100u);
  const EntrainmentTagMap map(step.tags.tags());
  std::vector<std::uint64_t> queries(tank.ids().begin(), tank.ids().end());
  std::sort(queries.begin(), queries.end());
  expectSameLookups(step.tags, map, queries);
}

TEST(EntrainmentTagLookup, BothRefuseDuplicateIds) {
  // Claim: two records with one id fail in both, dense and scattered.
  for (const std::uint64_t id : {std::uint64_t{5}, std::uint64_t{1} << 60}) {
    const std::vector<EntrainmentTag> records = {{id}, {id + 1}, {id}};
    EXPECT_THROW(EntrainmentTagTable{records}, std::invalid_argument) << id;
    EXPECT_THROW(EntrainmentTagMap{records}, std::invalid_argument) << id;
  }
}

}  // namespace
}  // namespace fluidsound::sim
