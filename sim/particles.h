// sim/particles.h — the liquid's marker particles: position, velocity and the APIC affine
// velocity field around each (Jiang et al. 2015), structure of arrays, float precision.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace fluidsound::sim {

using Vec3f = std::array<float, 3>;

struct Particles {
  std::vector<Vec3f> position;  ///< [m], world space
  std::vector<Vec3f> velocity;  ///< [m/s]
  /// APIC: affine[a] is the gradient of velocity component a at the particle [1/s]
  /// (Jiang, Schroeder, Selle, Teran & Stomakhin 2015, with trilinear weights: C_a = Σ u_a,i ∇w_i).
  std::vector<std::array<Vec3f, 3>> affine;

  std::size_t size() const { return position.size(); }
  void resize(std::size_t n) {
    position.resize(n);
    velocity.resize(n);
    affine.resize(n);
  }
  void push(const Vec3f& x, const Vec3f& v) {
    position.push_back(x);
    velocity.push_back(v);
    affine.push_back({});
  }
  /// Appends particle p of `other` (position, velocity and affine part).
  void pushFrom(const Particles& other, std::size_t p) {
    position.push_back(other.position[p]);
    velocity.push_back(other.velocity[p]);
    affine.push_back(other.affine[p]);
  }
  /// The concatenation of `parts`, in order (per-slab results of a parallel loop).
  static Particles concatenate(std::span<const Particles> parts) {
    Particles all;
    std::size_t total = 0;
    for (const Particles& p : parts) total += p.size();
    all.position.reserve(total);
    all.velocity.reserve(total);
    all.affine.reserve(total);
    for (const Particles& p : parts) {
      all.position.insert(all.position.end(), p.position.begin(), p.position.end());
      all.velocity.insert(all.velocity.end(), p.velocity.begin(), p.velocity.end());
      all.affine.insert(all.affine.end(), p.affine.begin(), p.affine.end());
    }
    return all;
  }
};

}  // namespace fluidsound::sim
