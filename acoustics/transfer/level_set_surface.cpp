// acoustics/transfer/level_set_surface.cpp — see level_set_surface.h.
#include "acoustics/transfer/level_set_surface.h"

#include <cmath>

namespace fluidsound::acoustics {

LocalSurface localSurfacePlane(const LevelSetSampler& level, const Vec3& centre, double depth,
                               const Vec3& up) {
  const LocalSurface flat{
      {centre[0] + depth * up[0], centre[1] + depth * up[1], centre[2] + depth * up[2]}, up, depth};
  const double voxel = level.voxelSize();
  const Vec3& p = flat.point;
  const double value = level.phi(p);
  if (std::abs(value) >= 0.99 * level.bandHalfWidth()) return flat;  // beyond the band
  Vec3 gradient{};
  double norm2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    Vec3 plus = p, minus = p;
    plus[a] += voxel, minus[a] -= voxel;
    gradient[a] = (level.phi(plus) - level.phi(minus)) / (2.0 * voxel);
    norm2 += gradient[a] * gradient[a];
  }
  if (norm2 < 0.25) return flat;
  const double norm = std::sqrt(norm2);
  LocalSurface s;
  double h = 0.0;
  for (int a = 0; a < 3; ++a) {
    s.normal[a] = gradient[a] / norm;
    s.point[a] = p[a] - value * s.normal[a];
  }
  for (int a = 0; a < 3; ++a) h += (s.point[a] - centre[a]) * s.normal[a];
  if (!(h > 0.0)) return flat;
  s.depth = h;
  // The plane through the surface point; the bubble sits h below it along the normal.
  for (int a = 0; a < 3; ++a) s.point[a] = centre[a] + h * s.normal[a];
  return s;
}

}  // namespace fluidsound::acoustics
