// sim/fluid/particles.h — the liquid's marker particles: position, velocity and the APIC affine
// velocity field around each (Jiang et al. 2015), structure of arrays, float precision.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "sim/fluid/particle_ids.h"

namespace fluidsound::sim {

using Vec3f = std::array<float, 3>;

struct Particles {
  std::vector<Vec3f> position;  ///< [m], world space
  std::vector<Vec3f> velocity;  ///< [m/s]
  /// APIC: affine[a] is the gradient of velocity component a at the particle [1/s]
  /// (Jiang, Schroeder, Selle, Teran & Stomakhin 2015, with trilinear weights: C_a = Σ u_a,i ∇w_i).
  std::vector<std::array<Vec3f, 3>> affine;
  /// Stable identity (particle_ids.h): kept through sorts and deletions; new particles get
  /// kUnassignedParticleId until the solver numbers them.
  std::vector<std::uint64_t> id;

  std::size_t size() const { return position.size(); }
  void resize(std::size_t n) {
    position.resize(n);
    velocity.resize(n);
    affine.resize(n);
    id.resize(n, kUnassignedParticleId);
  }
  void push(const Vec3f& x, const Vec3f& v) {
    position.push_back(x);
    velocity.push_back(v);
    affine.push_back({});
    id.push_back(kUnassignedParticleId);
  }
  /// Appends particle p of `other` (position, velocity, affine part and id).
  void pushFrom(const Particles& other, std::size_t p) {
    position.push_back(other.position[p]);
    velocity.push_back(other.velocity[p]);
    affine.push_back(other.affine[p]);
    id.push_back(other.id[p]);
  }
  /// Moves particle `from` to slot `to` (compaction after deletions).
  void move(std::size_t from, std::size_t to) {
    position[to] = position[from];
    velocity[to] = velocity[from];
    affine[to] = affine[from];
    id[to] = id[from];
  }
  /// The concatenation of `parts`, in order (per-slab results of a parallel loop).
  static Particles concatenate(std::span<const Particles> parts) {
    Particles all;
    std::size_t total = 0;
    for (const Particles& p : parts) total += p.size();
    all.position.reserve(total);
    all.velocity.reserve(total);
    all.affine.reserve(total);
    all.id.reserve(total);
    for (const Particles& p : parts) {
      all.position.insert(all.position.end(), p.position.begin(), p.position.end());
      all.velocity.insert(all.velocity.end(), p.velocity.begin(), p.velocity.end());
      all.affine.insert(all.affine.end(), p.affine.begin(), p.affine.end());
      all.id.insert(all.id.end(), p.id.begin(), p.id.end());
    }
    return all;
  }
};

}  // namespace fluidsound::sim
