// sim/bubbles/bubble_entrainment_reference.h — EntrainmentTagTable's lookup written plainly: a
// std::map by particle id, the specification the dense slots and the hash filter with binary
// search are tested against (tests/sim/bubbles/bubble_entrainment_reference_test.cpp). Not used
// by the bubble model.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <vector>

#include "sim/bubbles/bubble_entrainment.h"

namespace fluidsound::sim {

/// The records of one step by particle id.
class EntrainmentTagMap {
 public:
  /// @throws std::invalid_argument when two records share a particle id (as EntrainmentTagTable)
  explicit EntrainmentTagMap(std::span<const EntrainmentTag> tags);

  /// The record of particle `id`, or nullptr.
  const EntrainmentTag* find(std::uint64_t id) const;
  /// Every record, in id order.
  std::vector<EntrainmentTag> tags() const;

 private:
  std::map<std::uint64_t, EntrainmentTag> byId_;
};

}  // namespace fluidsound::sim
