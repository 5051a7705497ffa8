// sim/bodies/domain_walls.cpp — thick static boxes behind the closed faces of the domain box.
#include "sim/bodies/domain_walls.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fluidsound::sim {

std::vector<WallBox> domainWalls(const DomainBox& domain, double thickness) {
  for (int a = 0; a < 3; ++a)
    if (!(domain.max[a] > domain.min[a]))
      throw std::invalid_argument("domainWalls: the domain box needs max > min on axis " +
                                  std::to_string(a) + ", got " + std::to_string(domain.min[a]) +
                                  " … " + std::to_string(domain.max[a]) + " m");
  if (!(thickness > 0.0))
    throw std::invalid_argument("domainWalls: wall thickness must be > 0 m, got " +
                                std::to_string(thickness));
  const auto isOpen = [&](int face) {
    return std::find(domain.openFaces.begin(), domain.openFaces.end(),
                     static_cast<DomainFace>(face)) != domain.openFaces.end();
  };
  std::vector<WallBox> walls;
  for (int face = 0; face < 6; ++face) {
    if (isOpen(face)) continue;
    const int axis = face / 2;
    const bool upper = face % 2 == 1;
    Vec3 lo{}, hi{};
    for (int a = 0; a < 3; ++a) {
      if (a == axis) {
        lo[a] = upper ? domain.max[a] : domain.min[a] - thickness;
        hi[a] = upper ? domain.max[a] + thickness : domain.min[a];
      } else {
        lo[a] = domain.min[a] - (isOpen(2 * a) ? 0.0 : thickness);
        hi[a] = domain.max[a] + (isOpen(2 * a + 1) ? 0.0 : thickness);
      }
    }
    WallBox wall;
    wall.face = static_cast<DomainFace>(face);
    for (int a = 0; a < 3; ++a) {
      wall.centre[a] = 0.5 * (lo[a] + hi[a]);
      wall.halfExtents[a] = 0.5 * (hi[a] - lo[a]);
    }
    walls.push_back(wall);
  }
  return walls;
}

}  // namespace fluidsound::sim
