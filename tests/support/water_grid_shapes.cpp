// tests/support/water_grid_shapes.cpp — see water_grid_shapes.h.
#include "support/water_grid_shapes.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fluidsound::test {
namespace {

/// The open fraction of face (i, j, k) normal to `axis`: its samples² points on a cell-centred
/// sub-grid of the face, the fraction outside the solid.
float faceOpenFraction(const acoustics::WaterGrid& grid, int axis, const std::array<int, 3>& face,
                       const SolidDistance& solid, int samples) {
  const int u = (axis + 1) % 3;
  const int v = (axis + 2) % 3;
  Vec3 p{};
  p[axis] = grid.origin[axis] + face[axis] * grid.cellSize;
  int outside = 0;
  for (int a = 0; a < samples; ++a) {
    for (int b = 0; b < samples; ++b) {
      p[u] = grid.origin[u] + (face[u] + (a + 0.5) / samples) * grid.cellSize;
      p[v] = grid.origin[v] + (face[v] + (b + 0.5) / samples) * grid.cellSize;
      if (solid(p) >= 0.0) ++outside;
    }
  }
  return static_cast<float>(static_cast<double>(outside) / (samples * samples));
}

int wholeCells(double length, double cellSize, const char* name) {
  const double cells = length / cellSize;
  const int n = static_cast<int>(std::lround(cells));
  if (n < 1 || std::abs(cells - n) > 1e-9 * std::max(1.0, cells)) {
    throw std::invalid_argument(std::string(name) + " must be a whole number of cells, found " +
                                std::to_string(cells) + " cells");
  }
  return n;
}

WaterGridFrame boxFrame(const WaterBoxShape& box) {
  WaterGridFrame frame;
  frame.cellSize = box.cellSize;
  frame.cells = {wholeCells(box.width, box.cellSize, "box width"),
                 static_cast<int>(std::ceil(box.depth / box.cellSize - 1e-9)) + box.airCells,
                 wholeCells(box.length, box.cellSize, "box length")};
  frame.origin = {0.0, 0.0, 0.0};
  frame.openSides = {false, false, false, true, false, false};
  return frame;
}

/// The vessel's grid: the cavity's horizontal extent ±a plus the margin, its depth below the rim
/// plus the margin, the rim `rimCellFraction` of a cell above a face, air layers above.
WaterGridFrame vesselFrame(const VesselShape& vessel, double depthBelowRim) {
  const double h = vessel.cellSize;
  const int half = static_cast<int>(std::ceil(vessel.radius / h - 1e-9)) + vessel.marginCells;
  const int below = static_cast<int>(std::ceil(depthBelowRim / h - vessel.rimCellFraction - 1e-9)) +
                    vessel.marginCells;
  WaterGridFrame frame;
  frame.cellSize = h;
  frame.cells = {2 * half, below + 1 + vessel.airCells, 2 * half};
  frame.origin = {-half * h, vessel.rimHeight - (below + vessel.rimCellFraction) * h, -half * h};
  frame.openSides = {false, false, false, true, false, false};
  return frame;
}

}  // namespace

acoustics::WaterGrid waterGridFromSolid(const WaterGridFrame& frame, double surfaceHeight,
                                        const SolidDistance& solid, int samplesPerSide) {
  acoustics::WaterGrid grid;
  grid.cells = frame.cells;
  grid.cellSize = frame.cellSize;
  grid.origin = frame.origin;
  grid.openSides = frame.openSides;
  grid.phi.resize(grid.cellCount());
  for (int k = 0; k < grid.cells[2]; ++k) {
    for (int j = 0; j < grid.cells[1]; ++j) {
      for (int i = 0; i < grid.cells[0]; ++i) {
        grid.phi[grid.cellIndex(i, j, k)] =
            static_cast<float>(grid.cellCentre(i, j, k)[1] - surfaceHeight);
      }
    }
  }
  for (int axis = 0; axis < 3; ++axis) {
    std::array<int, 3> n = grid.cells;
    ++n[axis];
    auto& open = grid.faceOpen[axis];
    open.resize(static_cast<std::size_t>(n[0]) * n[1] * n[2]);
    for (int k = 0; k < n[2]; ++k) {
      for (int j = 0; j < n[1]; ++j) {
        for (int i = 0; i < n[0]; ++i) {
          open[grid.faceIndex(axis, i, j, k)] =
              faceOpenFraction(grid, axis, {i, j, k}, solid, samplesPerSide);
        }
      }
    }
  }
  // The open volume of each cell, by the same sampling in three dimensions.
  grid.cellOpen.resize(grid.cellCount());
  const double h = grid.cellSize;
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        int outside = 0;
        for (int c = 0; c < samplesPerSide; ++c)
          for (int b = 0; b < samplesPerSide; ++b)
            for (int a = 0; a < samplesPerSide; ++a) {
              const Vec3 p{grid.origin[0] + (i + (a + 0.5) / samplesPerSide) * h,
                           grid.origin[1] + (j + (b + 0.5) / samplesPerSide) * h,
                           grid.origin[2] + (k + (c + 0.5) / samplesPerSide) * h};
              outside += solid(p) > 0.0 ? 1 : 0;
            }
        grid.cellOpen[grid.cellIndex(i, j, k)] =
            static_cast<float>(outside) / (samplesPerSide * samplesPerSide * samplesPerSide);
      }
  return grid;
}

acoustics::WaterGrid waterBox(const WaterBoxShape& box) {
  return waterGridFromSolid(boxFrame(box), box.depth, [](const Vec3&) { return 1.0; });
}

acoustics::WaterGrid waterBoxWithWall(const WaterBoxShape& box, double wallX) {
  const double surface = box.depth;
  // Solid where x < wallX and below the surface: the intersection of two half-spaces.
  return waterGridFromSolid(boxFrame(box), surface, [wallX, surface](const Vec3& p) {
    return std::max(p[0] - wallX, p[1] - surface);
  });
}

acoustics::WaterGrid cylindricalTank(const VesselShape& vessel) {
  const double a = vessel.radius;
  const double rim = vessel.rimHeight;
  const double floor = rim - vessel.depth;
  return waterGridFromSolid(vesselFrame(vessel, vessel.depth), rim, [a, rim, floor](const Vec3& p) {
    // The cavity (r < a above the floor) as a signed-distance bound; the solid is below the rim
    // and outside it.
    const double cavity = std::max(std::hypot(p[0], p[2]) - a, floor - p[1]);
    return std::max(p[1] - rim, -cavity);
  });
}

acoustics::WaterGrid hemisphericalBowl(const VesselShape& vessel) {
  const double a = vessel.radius;
  const double rim = vessel.rimHeight;
  return waterGridFromSolid(vesselFrame(vessel, a), rim, [a, rim](const Vec3& p) {
    const double cavity = std::hypot(p[0], p[1] - rim, p[2]) - a;
    return std::max(p[1] - rim, -cavity);
  });
}

acoustics::WaterGrid tubeOnLiquid(double radius, double top, double cellSize) {
  const double h = cellSize;
  const int across = static_cast<int>(std::lround(0.12 / h));
  const int rows = static_cast<int>(std::lround((top + 0.09) / h));
  acoustics::WaterGrid g;
  g.cells = {across, rows, across};
  g.cellSize = h;
  g.origin = {-0.06, -0.02, -0.06};
  g.phi.resize(g.cellCount());
  for (int k = 0; k < across; ++k)
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < across; ++i)
        g.phi[g.cellIndex(i, j, k)] = static_cast<float>(g.cellCentre(i, j, k)[1]);
  for (int a = 0; a < 3; ++a) {
    std::array<int, 3> f = g.cells;
    ++f[a];
    g.faceOpen[a].assign(static_cast<std::size_t>(f[0]) * f[1] * f[2], 1.0f);
    if (a == 1) continue;
    for (int k = 0; k < f[2]; ++k)
      for (int j = 0; j < f[1]; ++j)
        for (int i = 0; i < f[0]; ++i) {
          std::array<int, 3> lo{i, j, k}, hi{i, j, k};
          --lo[a];
          if (lo[a] < 0 || hi[a] >= g.cells[a]) continue;
          const Vec3 x0 = g.cellCentre(lo[0], lo[1], lo[2]), x1 = g.cellCentre(hi[0], hi[1], hi[2]);
          if (x0[1] < 0.0 || x0[1] > top) continue;
          if ((std::hypot(x0[0], x0[2]) < radius) != (std::hypot(x1[0], x1[2]) < radius))
            g.faceOpen[a][g.faceIndex(a, i, j, k)] = 0.0f;
        }
  }
  return g;
}

}  // namespace fluidsound::test
