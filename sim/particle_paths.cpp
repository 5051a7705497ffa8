// sim/particle_paths.cpp — see particle_paths.h.
#include "sim/particle_paths.h"

namespace fluidsound::sim {

PathPoint hermitePath(const Vec3f& x0, const Vec3f& v0, const Vec3f& x1, const Vec3f& v1, double interval,
                      double s) {
  const double s2 = s * s, s3 = s2 * s;
  // The cubic Hermite basis and its derivatives with respect to s.
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s, d11 = 3 * s2 - 2 * s;
  PathPoint p;
  for (int c = 0; c < 3; ++c) {
    p.position[c] = static_cast<float>(h00 * x0[c] + h10 * interval * v0[c] + h01 * x1[c] + h11 * interval * v1[c]);
    p.velocity[c] = static_cast<float>((d00 * x0[c] + d01 * x1[c]) / interval + d10 * v0[c] + d11 * v1[c]);
  }
  return p;
}

}  // namespace fluidsound::sim
