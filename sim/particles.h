// sim/particles.h — the liquid's marker particles: position, velocity and the APIC affine
// velocity field around each (Jiang et al. 2015), structure of arrays, float precision.
#pragma once

#include <array>
#include <cstdint>
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
};

}  // namespace fluidsound::sim
