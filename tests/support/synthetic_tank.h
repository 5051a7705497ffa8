// tests/support/synthetic_tank.h — a liquid state made by hand for the bubble model's tests: a
// tank of particles at rest under a flat free surface (φ = y − surface, exact), walls on every
// side but the top, an optional solid box, and a vertical jet that drives particles down through
// the surface at a chosen speed (injecting new particles at its top, as a pour would).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "sim/fluid/array3.h"
#include "sim/fluid/grid.h"
#include "sim/fluid/liquid_state.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/particle_seeding.h"
#include "sim/fluid/particles.h"
#include "sim/scene.h"

namespace fluidsound::test {

/// A vertical cylinder of liquid moving down at `speed`, from `top` to `bottom` [m].
struct Jet {
  double x = 0.06, z = 0.06;  ///< axis [m]
  double radius = 0.015;      ///< [m]
  double top = 0.08;          ///< where particles are injected [m]
  double bottom = 0.04;       ///< where they stop [m]
  double speed = 1.0;         ///< [m/s], downward
};

class SyntheticTank {
 public:
  /// @param cells    cells per axis; @param h  cell size [m]; @param surface  y of the free surface [m]
  /// @param perCell  particles per cell (2×2×2 strata when 8), below the surface and outside solids
  SyntheticTank(int cells, double h, double surface, std::uint64_t seed, std::optional<sim::Box> solidBox = {},
                int perCell = 8)
      : surface_(surface), box_(solidBox), random_(seed) {
    grid_.cells = {cells, cells, cells};
    grid_.cellSize = h;
    phi_ = sim::Array3f(grid_.cells);
    for (int k = 0; k < cells; ++k)
      for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i) phi_(i, j, k) = static_cast<float>(grid_.cellCentre(i, j, k)[1] - surface);
    solid_ = sim::Array3f(grid_.nodeCount());
    for (int k = 0; k <= cells; ++k)
      for (int j = 0; j <= cells; ++j)
        for (int i = 0; i <= cells; ++i)
          solid_(i, j, k) = static_cast<float>(solidDistance(grid_.worldFromGrid({1.0 * i, 1.0 * j, 1.0 * k})));
    velocity_ = sim::MacVelocity(grid_);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int strata = perCell == 8 ? 2 : 1;
    for (int k = 0; k < cells; ++k)
      for (int j = 0; j < cells; ++j)
        for (int i = 0; i < cells; ++i)
          for (int s = 0; s < perCell; ++s) {
            const int sub[3] = {s % strata, (s / strata) % strata, s / (strata * strata)};
            Vec3 g{i + (sub[0] + unit(random_)) / strata, j + (sub[1] + unit(random_)) / strata,
                        k + (sub[2] + unit(random_)) / strata};
            if (strata == 1) g = {i + unit(random_), j + unit(random_), k + unit(random_)};
            const Vec3 p = grid_.worldFromGrid(g);
            if (p[1] < surface && solidDistance(p) > 0.0) add(p, {0.0, 0.0, 0.0});
          }
  }

  const sim::GridGeometry& grid() const { return grid_; }
  double surface() const { return surface_; }
  sim::MacVelocity& velocity() { return velocity_; }
  std::vector<sim::Vec3f>& positions() { return position_; }
  std::vector<sim::Vec3f>& velocities() { return particleVelocity_; }
  std::vector<std::uint64_t>& ids() { return id_; }
  std::size_t size() const { return position_.size(); }

  /// Exact signed distance to the solids [m]: the five closed walls and the box, if any.
  double solidDistance(const Vec3& p) const {
    const double extent = grid_.cells[0] * grid_.cellSize;
    double d = std::min({p[0], extent - p[0], p[1], p[2], extent - p[2]});
    if (box_) d = std::min(d, sim::regionDistance(sim::LiquidRegion{*box_, {}}, p));
    return d;
  }

  sim::LiquidState state() const {
    return sim::LiquidState{position_, particleVelocity_, id_, phi_, velocity_, solid_, grid_};
  }

  void add(const Vec3& p, const Vec3& v) {
    position_.push_back({static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2])});
    particleVelocity_.push_back({static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])});
    id_.push_back(nextId_++);
  }

  /// Sets the grid's v-faces inside the jet's cylinder between `from` and `to` (y, m) to −speed.
  void setJetGridVelocity(const Jet& jet, double from, double to) {
    sim::Array3f& v = velocity_[1];
    for (int k = 0; k < v.nk(); ++k)
      for (int j = 0; j < v.nj(); ++j)
        for (int i = 0; i < v.ni(); ++i) {
          const Vec3 f = grid_.worldFromGrid({i + 0.5, 1.0 * j, k + 0.5});
          if (insideCylinder(jet, f) && f[1] > from && f[1] < to) v(i, j, k) = static_cast<float>(-jet.speed);
        }
  }

  /// Moves the jet's particles down by speed·dt (those reaching `bottom` stop there, at rest) and
  /// injects new ones, with new ids, in the slab [top − speed·dt, top] at the particle density
  /// perCell/h³ (the fractional remainder carried to the next call).
  void driveJet(const Jet& jet, double dt, int perCell = 8) {
    const double drop = jet.speed * dt;
    for (std::size_t p = 0; p < position_.size(); ++p) {
      const Vec3 x{position_[p][0], position_[p][1], position_[p][2]};
      if (!insideCylinder(jet, x) || x[1] <= jet.bottom || x[1] > jet.top) continue;
      const double y = std::max(x[1] - drop, jet.bottom);
      position_[p][1] = static_cast<float>(y);
      particleVelocity_[p] = {0.0f, y > jet.bottom ? static_cast<float>(-jet.speed) : 0.0f, 0.0f};
    }
    const double h = grid_.cellSize;
    const double count = perCell / (h * h * h) * std::numbers::pi * jet.radius * jet.radius * drop + carry_;
    const int whole = static_cast<int>(std::floor(count));
    carry_ = count - whole;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < whole;) {
      const Vec3 p{jet.x + jet.radius * (2.0 * unit(random_) - 1.0), jet.top - drop * unit(random_),
                        jet.z + jet.radius * (2.0 * unit(random_) - 1.0)};
      if (!insideCylinder(jet, p)) continue;
      add(p, {0.0, -jet.speed, 0.0});
      ++n;
    }
  }

  /// Small random displacements (uniform in ±amplitude per axis, around each particle's rest
  /// position) and velocities (uniform in ±speed per axis): the spurious motion of a resting FLIP tank.
  void jiggle(const std::vector<sim::Vec3f>& rest, double amplitude, double speed) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (std::size_t p = 0; p < position_.size(); ++p)
      for (int a = 0; a < 3; ++a) {
        position_[p][a] = static_cast<float>(rest[p][a] + amplitude * unit(random_));
        particleVelocity_[p][a] = static_cast<float>(speed * unit(random_));
      }
  }

 private:
  static bool insideCylinder(const Jet& jet, const Vec3& p) {
    return (p[0] - jet.x) * (p[0] - jet.x) + (p[2] - jet.z) * (p[2] - jet.z) <= jet.radius * jet.radius;
  }

  sim::GridGeometry grid_;
  double surface_;
  std::optional<sim::Box> box_;
  std::mt19937_64 random_;
  sim::Array3f phi_, solid_;
  sim::MacVelocity velocity_;
  std::vector<sim::Vec3f> position_, particleVelocity_;
  std::vector<std::uint64_t> id_;
  std::uint64_t nextId_ = 0;
  double carry_ = 0.0;
};

}  // namespace fluidsound::test
