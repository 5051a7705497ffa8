// sim/bubbles/bubble_entrainment_reference.cpp — see bubble_entrainment_reference.h.
#include "sim/bubbles/bubble_entrainment_reference.h"

#include <stdexcept>
#include <string>

namespace fluidsound::sim {

EntrainmentTagMap::EntrainmentTagMap(std::span<const EntrainmentTag> tags) {
  for (const EntrainmentTag& t : tags)
    if (!byId_.emplace(t.particleId, t).second)
      throw std::invalid_argument("LiquidState.particleIds must be unique, but id " +
                                  std::to_string(t.particleId) + " belongs to two particles");
}

const EntrainmentTag* EntrainmentTagMap::find(std::uint64_t id) const {
  const auto it = byId_.find(id);
  return it == byId_.end() ? nullptr : &it->second;
}

std::vector<EntrainmentTag> EntrainmentTagMap::tags() const {
  std::vector<EntrainmentTag> all;
  for (const auto& [id, tag] : byId_) all.push_back(tag);
  return all;
}

}  // namespace fluidsound::sim
