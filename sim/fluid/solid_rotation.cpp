// sim/fluid/solid_rotation.cpp — see solid_rotation.h.
#include "sim/fluid/solid_rotation.h"

#include <cmath>
#include <numbers>

namespace fluidsound::sim {
namespace {

Mat3 multiply(const Mat3& a, const Mat3& b) {
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
  return r;
}

}  // namespace

Mat3 rotationFromEulerDegrees(const Vec3& degrees) {
  const double toRadians = std::numbers::pi / 180.0;
  const double cx = std::cos(degrees[0] * toRadians), sx = std::sin(degrees[0] * toRadians);
  const double cy = std::cos(degrees[1] * toRadians), sy = std::sin(degrees[1] * toRadians);
  const double cz = std::cos(degrees[2] * toRadians), sz = std::sin(degrees[2] * toRadians);
  const Mat3 rx{{{1, 0, 0}, {0, cx, -sx}, {0, sx, cx}}};
  const Mat3 ry{{{cy, 0, sy}, {0, 1, 0}, {-sy, 0, cy}}};
  const Mat3 rz{{{cz, -sz, 0}, {sz, cz, 0}, {0, 0, 1}}};
  return multiply(rz, multiply(ry, rx));
}

Vec3 rotateByEulerDegrees(const Vec3& offset, const Vec3& degrees) {
  const Mat3 r = rotationFromEulerDegrees(degrees);
  Vec3 out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i] += r[i][j] * offset[j];
  return out;
}

}  // namespace fluidsound::sim
