// sim/particle_matching.cpp — see particle_matching.h.
#include "sim/particle_matching.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <unordered_map>

#include "sim/fluid/particle_transfer.h"

namespace fluidsound::sim {
namespace {

Vec3 toVec3(const Vec3f& v) { return {v[0], v[1], v[2]}; }

/// A cell of the hash grid of cell size `radius`.
struct CellKey {
  std::int64_t i, j, k;
  bool operator==(const CellKey&) const = default;
};
struct CellHash {
  std::size_t operator()(const CellKey& c) const {
    return static_cast<std::size_t>((c.i * 73856093) ^ (c.j * 19349663) ^ (c.k * 83492791));
  }
};
CellKey cellOf(const Vec3f& x, double radius) {
  return {static_cast<std::int64_t>(std::floor(x[0] / radius)), static_cast<std::int64_t>(std::floor(x[1] / radius)),
          static_cast<std::int64_t>(std::floor(x[2] / radius))};
}

}  // namespace

std::vector<Vec3f> carriedPositions(std::span<const Vec3f> from, const MacVelocity& velocityFrom,
                                   const MacVelocity& velocityTo, const GridGeometry& grid, double dt) {
  std::vector<Vec3f> out(from.size());
  for (std::size_t p = 0; p < from.size(); ++p) {
    const Vec3 x = toVec3(from[p]);
    const Vec3 u0 = interpolateVelocity(velocityFrom, grid, x);
    const Vec3 half{x[0] + 0.5 * dt * u0[0], x[1] + 0.5 * dt * u0[1], x[2] + 0.5 * dt * u0[2]};
    const Vec3 a = interpolateVelocity(velocityFrom, grid, half), b = interpolateVelocity(velocityTo, grid, half);
    for (int c = 0; c < 3; ++c) out[p][c] = static_cast<float>(x[c] + dt * 0.5 * (a[c] + b[c]));
  }
  return out;
}

std::vector<std::uint64_t> matchParticleIds(std::span<const Vec3f> predicted,
                                            std::span<const std::uint64_t> previousIds,
                                            std::span<const Vec3f> next, double radius,
                                            std::uint64_t& nextId) {
  if (predicted.size() != previousIds.size())
    throw std::invalid_argument("matchParticleIds: " + std::to_string(predicted.size()) + " positions but " +
                                std::to_string(previousIds.size()) + " ids");
  if (!(radius > 0.0)) throw std::invalid_argument("matchParticleIds: the radius must be > 0 (m)");
  std::unordered_map<CellKey, std::vector<std::uint32_t>, CellHash> cells;
  for (std::size_t p = 0; p < predicted.size(); ++p)
    cells[cellOf(predicted[p], radius)].push_back(static_cast<std::uint32_t>(p));
  // Every pair within reach: (squared distance, next index, previous index).
  std::vector<std::tuple<float, std::uint32_t, std::uint32_t>> pairs;
  const float reach = static_cast<float>(radius * radius);
  for (std::size_t q = 0; q < next.size(); ++q) {
    const CellKey c = cellOf(next[q], radius);
    for (std::int64_t dk = -1; dk <= 1; ++dk)
      for (std::int64_t dj = -1; dj <= 1; ++dj)
        for (std::int64_t di = -1; di <= 1; ++di) {
          const auto found = cells.find({c.i + di, c.j + dj, c.k + dk});
          if (found == cells.end()) continue;
          for (std::uint32_t p : found->second) {
            float d2 = 0.0f;
            for (int a = 0; a < 3; ++a) d2 += (next[q][a] - predicted[p][a]) * (next[q][a] - predicted[p][a]);
            if (d2 <= reach) pairs.emplace_back(d2, static_cast<std::uint32_t>(q), p);
          }
        }
  }
  std::sort(pairs.begin(), pairs.end());
  constexpr std::uint64_t kNone = ~std::uint64_t{0};
  std::vector<std::uint64_t> ids(next.size(), kNone);
  std::vector<bool> taken(predicted.size(), false);
  for (const auto& [d2, q, p] : pairs) {
    if (ids[q] != kNone || taken[p]) continue;
    ids[q] = previousIds[p];
    taken[p] = true;
  }
  for (std::uint64_t& id : ids)
    if (id == kNone) id = nextId++;
  return ids;
}

}  // namespace fluidsound::sim
