// tests/support/martin_moyce.h — the collapse of a liquid column (Martin & Moyce 1952) for the
// liquid solver's test and benchmark: the measured surge fronts, the scene, and the front read
// from the solver's liquid surface. Shared by tests/sim/martin_moyce_test.cpp and
// tests/bench/martin_moyce_bench.cpp so both measure the same thing.
//
// Dimensionless variables (Martin & Moyce 1952): a column a wide and n²a high (here n² = 2)
// stands against the wall x = 0; its surge front is at z(t) along the floor.
//   Z = z / a,   T = n·t·√(g/a) = t·√(2g/a).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <vector>

#include "sim/fluid/fluid_solver.h"
#include "sim/scene.h"

namespace fluidsound::test::martin_moyce {

/// A point of a front history: dimensionless time T = t·√(2g/a) and front Z = z/a [-].
struct FrontSample {
  double time = 0.0;   ///< T [-]
  double front = 0.0;  ///< Z [-]
};

/// Martin & Moyce (1952), "An experimental study of the collapse of liquid columns on a rigid
/// horizontal plane", Phil. Trans. R. Soc. Lond. A 244, 312–324 (doi:10.1098/rsta.1952.0006):
/// surge front of the n² = 2 column, a = 2¼ in, tabulated: the times at which the front passed
/// fixed marks (Z steps by 0.11, then 0.22: ¼ in, then ½ in at a = 2¼ in). Values as
/// transcribed in Ocellaris (TormodLandet/Ocellaris, scripts/plot_dam_break.py: "Data from Martin
/// and Moyce (1952), Table 2 and 6", plotted with a = 0.05715 m, n = √2); Lethe
/// (chaos-polymtl/lethe, examples/multiphysics/dam-break/dam-break-2d.py) carries the same
/// stations with times within ±0.02.
inline constexpr std::array<FrontSample, 15> kTabulatedFront = {{
    {0.41, 1.11}, {0.84, 1.22}, {1.19, 1.44}, {1.43, 1.67}, {1.63, 1.89},
    {1.83, 2.11}, {1.98, 2.33}, {2.20, 2.56}, {2.32, 2.78}, {2.51, 3.00},
    {2.65, 3.22}, {2.83, 3.44}, {2.98, 3.67}, {3.11, 3.89}, {3.33, 4.11},
}};

/// Martin & Moyce (1952) Fig. 3, n² = 2, digitised by PySPH (pypr/pysph,
/// pysph/examples/db_exp_data.py, mm_data_2 for a = 2¼ in, mm_data_1 for a = 1⅛ in), up to T ≈ 4.
inline constexpr std::array<FrontSample, 6> kFigureFrontLarge = {{
    {0.832, 1.217}, {1.219, 1.474}, {1.997, 2.292}, {2.547, 2.995}, {3.345, 4.134}, {4.034, 4.944},
}};
inline constexpr std::array<FrontSample, 6> kFigureFrontSmall = {{
    {0.849, 1.245}, {1.212, 1.443}, {1.602, 1.884}, {2.283, 2.689}, {2.950, 3.728}, {3.598, 4.528},
}};

/// A second, independent experiment with an n² = 2 column: Koshizuka & Oka (1996), Nucl. Sci.
/// Eng. 123, 421–434, as tabulated by PySPH (ko_data, same file, Z against t·√(2g/L)).
inline constexpr std::array<FrontSample, 9> kKoshizukaOkaFront = {{
    {0.0, 1.000}, {0.381, 1.111}, {0.769, 1.252}, {1.153, 1.505}, {1.537, 1.892},
    {1.935, 2.241}, {2.323, 2.615}, {2.719, 3.003}, {3.096, 3.624},
}};

/// Column width a [m]: Martin & Moyce's larger column, 2¼ in. (Without viscosity and surface
/// tension the solver's Z(T) does not depend on a: a = 0.5 m gives the same fronts to 0.01.)
inline constexpr double kColumnWidth = 0.05715;
/// Column height over width, n² [-].
inline constexpr double kHeightOverWidth = 2.0;
/// Length of the tank [a]: the front reaches Z ≈ 4.6 by T = 3.3, so it never meets the far wall.
inline constexpr double kTankLength = 6.0;
/// Height of the tank [a]: the collapsing column never rises above its initial 2a.
inline constexpr double kTankHeight = 2.5;
/// Cells across the thin third dimension: four (one parallel slab) between free-slip walls, so
/// the flow is plane, as Z(T) of the n² = 2 data is compared; eight cells move Z by < 0.01.
inline constexpr int kDepthCells = 4;
/// Frame length in T: the solver reseeds once per advanceTo, so frames are kept regular
/// (2.7 ms at a = 2¼ in); frames of 0.1 or 0.25 move Z by < 0.01.
inline constexpr double kFrameTime = 0.05;

/// The dam break: a closed tank kTankLength·a × kTankHeight·a × kDepthCells cells, all walls
/// free-slip (the solver is inviscid), gravity 9.81 m/s², the column a × 2a at the wall x = 0.
/// @param cellsPerWidth  a/Δx, the resolution across the column (10 and 20 in the acceptance point)
inline sim::Scene damBreakScene(int cellsPerWidth) {
  const double a = kColumnWidth, h = a / cellsPerWidth;
  sim::Scene scene;
  scene.domain.max = {kTankLength * a, kTankHeight * a, kDepthCells * h};
  scene.domain.cell = h;
  scene.time.duration = 1.0;
  scene.liquid.push_back({sim::Box{{0.0, 0.0, 0.0}, {a, kHeightOverWidth * a, kDepthCells * h}}, {}});
  return scene;
}

/// √(n² g / a) [1/s]: T = t · timeScale.
inline double timeScale(const sim::Scene& scene) {
  const Vec3& g = scene.gravity;
  return std::sqrt(kHeightOverWidth * std::hypot(g[0], g[1], g[2]) / kColumnWidth);
}

/// @brief The surge front [m]: where the liquid surface meets the floor, as a camera at floor
///        level sees it. Along each row of cells at the floor (centres h/2 above it), the last cell
///        inside the liquid (φ < 0, the solver's liquidDistance) and the linear zero of φ between
///        it and the next cell; averaged over the rows across the thin domain.
/// @note  Any liquid counts, also a sheet or drop ahead of the main body. The choice hardly
///        matters (measured for 1 ≤ T ≤ 3 at a/Δx = 10, 20, 40, 80): the farthest particle lies
///        within 0.03a of this front, the 99.9th percentile of particle x and the farthest column
///        holding a layer of h/2 or of 0.02a within 0.1a. The front is a coherent tongue, not a
///        stray particle.
inline double surgeFrontPosition(const sim::FluidSolver& solver) {
  const sim::GridGeometry& grid = solver.grid();
  const sim::Array3f& phi = solver.liquidDistance();
  const double h = grid.cellSize;
  double sum = 0.0;
  for (int k = 0; k < grid.cells[2]; ++k) {
    int last = -1;
    for (int i = 0; i < grid.cells[0]; ++i)
      if (phi(i, 0, k) < 0.0f) last = i;
    double x = grid.origin[0];
    if (last >= 0) {
      x = grid.cellCentre(last, 0, k)[0];
      if (last + 1 < grid.cells[0]) {
        const double inside = phi(last, 0, k), outside = phi(last + 1, 0, k);
        x += h * inside / (inside - outside);
      }
    }
    sum += x;
  }
  return sum / grid.cells[2];
}

/// @brief Runs the dam break at a/Δx = cellsPerWidth from rest to T = endTime and returns Z at
///        the end of every frame (T = kFrameTime, 2·kFrameTime, …), starting with (0, 1).
inline std::vector<FrontSample> simulateFront(int cellsPerWidth, double endTime) {
  const sim::Scene scene = damBreakScene(cellsPerWidth);
  sim::FluidSolver solver(scene);
  const double scale = timeScale(scene);
  std::vector<FrontSample> history{{0.0, surgeFrontPosition(solver) / kColumnWidth}};
  const int frames = static_cast<int>(std::ceil(endTime / kFrameTime - 1e-9));
  for (int f = 1; f <= frames; ++f) {
    const double T = f * kFrameTime;
    solver.advanceTo(T / scale);
    history.push_back({T, surgeFrontPosition(solver) / kColumnWidth});
  }
  return history;
}

/// @brief Z at time T, linear between the frames around it (interpolation error ≤ ΔT²/8·|Z''|
///        ≈ 3e-4 for ΔT = 0.05).
/// @throws std::out_of_range if T lies outside the history
inline double frontAt(std::span<const FrontSample> history, double time) {
  for (std::size_t s = 1; s < history.size(); ++s)
    if (time <= history[s].time && time >= history[s - 1].time) {
      const FrontSample &p = history[s - 1], &q = history[s];
      return p.front + (q.front - p.front) * (time - p.time) / (q.time - p.time);
    }
  throw std::out_of_range("martin_moyce::frontAt: T outside the simulated history");
}

/// @brief The first time T at which the simulated front reaches Z (linear between frames), or NaN
///        if it never does: the experiment's T minus this is its lag behind the simulation.
inline double timeToReach(std::span<const FrontSample> history, double front) {
  for (std::size_t s = 1; s < history.size(); ++s)
    if (history[s].front >= front) {
      const FrontSample &p = history[s - 1], &q = history[s];
      if (p.front >= front) return p.time;
      return p.time + (q.time - p.time) * (front - p.front) / (q.front - p.front);
    }
  return std::nan("");
}

}  // namespace fluidsound::test::martin_moyce
