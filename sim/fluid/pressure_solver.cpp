// sim/fluid/pressure_solver.cpp — see pressure_solver.h. Assembly and velocity update follow the
// paper's order (Batty, Bertails & Bridson 2007, §3–4): weights → matrix and weighted
// divergence → PCG → pressure gradient on the open faces.
#include "sim/fluid/pressure_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <tbb/parallel_for.h>

namespace fluidsound::sim {
namespace {

Index3 step(Index3 c, int axis, int by) {
  c[axis] += by;
  return c;
}

/// Ghost-fluid fraction of the segment between a liquid centre (φ < 0) and an air centre (φ ≥ 0)
/// that is liquid (Gibou et al. 2002), clamped below by kMinimumSurfaceFraction.
double surfaceFraction(double phiLiquid, double phiAir) {
  return std::max(phiLiquid / (phiLiquid - phiAir), kMinimumSurfaceFraction);
}

void requireSize(const Index3& actual, const Index3& expected, const std::string& what) {
  if (actual != expected)
    throw std::invalid_argument("pressure projection: " + what + " has size " +
                                std::to_string(actual[0]) + "x" + std::to_string(actual[1]) + "x" +
                                std::to_string(actual[2]) + ", expected " +
                                std::to_string(expected[0]) + "x" + std::to_string(expected[1]) +
                                "x" + std::to_string(expected[2]));
}

bool isLiquid(const Array3f& phi, const Index3& c) {
  return phi.contains(c[0], c[1], c[2]) && phi(c[0], c[1], c[2]) < 0.0f;
}

/// A liquid cell with at least one face of weight > 0: an unknown of the pressure solve.
bool hasOpenFace(const std::array<Array3f, 3>& faceOpen, const Index3& c) {
  for (int a = 0; a < 3; ++a) {
    const Index3 upper = step(c, a, 1);
    if (faceOpen[a](c[0], c[1], c[2]) > 0.0f || faceOpen[a](upper[0], upper[1], upper[2]) > 0.0f)
      return true;
  }
  return false;
}

/// w·u + (1 − w)·u_solid on one face: the flux per unit area through it [m/s] (Batty 2007).
double weightedFlux(const MacVelocity& velocity, const std::array<Array3f, 3>& faceOpen,
                    const std::array<Array3f, 3>* solidVelocity, int axis, const Index3& f) {
  const double w = faceOpen[axis](f[0], f[1], f[2]);
  const double solid = solidVelocity ? (*solidVelocity)[axis](f[0], f[1], f[2]) : 0.0;
  return w * velocity[axis](f[0], f[1], f[2]) + (1.0 - w) * solid;
}

/// Σ over the 6 faces of cell c of ±(weighted flux): h times the weighted divergence [m/s].
double weightedNetOutflow(const MacVelocity& velocity, const std::array<Array3f, 3>& faceOpen,
                          const std::array<Array3f, 3>* solidVelocity, const Index3& c) {
  double sum = 0.0;
  for (int a = 0; a < 3; ++a)
    sum += weightedFlux(velocity, faceOpen, solidVelocity, a, step(c, a, 1)) -
           weightedFlux(velocity, faceOpen, solidVelocity, a, c);
  return sum;
}

}  // namespace

std::ostream& operator<<(std::ostream& out, const PressureReport& r) {
  return out << "{iterations " << r.iterations << ", relativeResidual " << r.relativeResidual
             << ", converged " << (r.converged ? "yes" : "no") << ", unknowns " << r.unknowns
             << ", matrixVectorProducts " << r.matrixVectorProducts << ", matvecEquivalents "
             << r.matvecEquivalents << "}";
}

void PressureSolver::assemble(const MacVelocity& velocity, const PressureProblem& problem) {
  const Array3f& liquidPhi = problem.liquidPhi;
  const std::array<Array3f, 3>& faceOpen = problem.faceOpen;
  const GridGeometry& grid = problem.grid;
  // Number the unknowns in grid order (x fastest), as the MIC(0) sweep requires.
  unknownOfCell_ = Array3<std::int32_t>(grid.cells, -1);
  std::int32_t count = 0;
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i)
        if (liquidPhi(i, j, k) < 0.0f && hasOpenFace(faceOpen, {i, j, k}))
          unknownOfCell_(i, j, k) = count++;

  matrix_.reset(static_cast<std::size_t>(count));
  rhs_.assign(static_cast<std::size_t>(count), 0.0);
  std::vector<std::uint8_t> fixedLevel(static_cast<std::size_t>(count), 0);  // meets air or an open face
  const double scale = problem.dt / (problem.density * grid.cellSize * grid.cellSize);  // Δt/(ρh²)
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const std::int32_t row = unknownOfCell_(i, j, k);
        if (row < 0) continue;
        const Index3 c{i, j, k};
        const double phiC = liquidPhi(i, j, k);
        for (int a = 0; a < 3; ++a)
          for (int side : {-1, 1}) {
            const Index3 face = side < 0 ? c : step(c, a, 1);
            const double w = faceOpen[a](face[0], face[1], face[2]);
            if (w <= 0.0) continue;
            const Index3 n = step(c, a, side);
            const double coefficient = w * scale;
            if (!liquidPhi.contains(n[0], n[1], n[2])) {
              matrix_.diagonal[row] += coefficient / kOpenBoundarySurfaceFraction;
              fixedLevel[row] = 1;
            } else if (isLiquid(liquidPhi, n)) {
              // n has this open face too, so it is an unknown.
              matrix_.diagonal[row] += coefficient;
              const std::int32_t column = unknownOfCell_(n[0], n[1], n[2]);
              if (side > 0) {
                matrix_.plus[a][row] = -coefficient;
                matrix_.plusNeighbour[a][row] = column;
              } else {
                matrix_.minusNeighbour[a][row] = column;
              }
            } else {
              matrix_.diagonal[row] +=
                  coefficient / surfaceFraction(phiC, liquidPhi(n[0], n[1], n[2]));
              fixedLevel[row] = 1;
            }
          }
        rhs_[row] =
            -weightedNetOutflow(velocity, faceOpen, &problem.solidVelocity, c) / grid.cellSize;
        if (problem.targetDivergence != nullptr)
          rhs_[row] += (*problem.targetDivergence)(c[0], c[1], c[2]);
      }
  sealedPockets_ = sealPockets(fixedLevel, scale);
}

std::int64_t PressureSolver::sealPockets(const std::vector<std::uint8_t>& fixedLevel, double scale) {
  // A pocket of liquid walled in by solids on every side (a body resting on the floor can close
  // one) has no cell whose pressure is fixed by air or an open face: its block of the matrix is
  // singular (pure Neumann) and its right-hand side, the solids' net inflow, need not sum to zero
  // — PCG then divides by nothing and the pressure turns NaN. Incompressible liquid cannot change
  // the pocket's volume: remove the mean of its right-hand side (the compatible part), and pin
  // its first cell's pressure with one air-like term; the pinned equation then holds with p = 0
  // there (the rows of a Neumann block sum to zero), so every other equation holds exactly.
  const auto n = static_cast<std::int32_t>(fixedLevel.size());
  std::vector<std::int32_t> pocket(static_cast<std::size_t>(n), -1), stack;
  std::int64_t pockets = 0;
  for (std::int32_t seed = 0; seed < n; ++seed) {
    if (pocket[seed] >= 0) continue;
    std::vector<std::int32_t> members;
    bool fixed = false;
    pocket[seed] = seed;
    stack.push_back(seed);
    while (!stack.empty()) {
      const std::int32_t row = stack.back();
      stack.pop_back();
      members.push_back(row);
      fixed = fixed || fixedLevel[row] != 0;
      for (int a = 0; a < 3; ++a)
        for (const std::int32_t next : {matrix_.plusNeighbour[a][row], matrix_.minusNeighbour[a][row]})
          if (next >= 0 && pocket[next] < 0) {
            pocket[next] = seed;
            stack.push_back(next);
          }
    }
    if (fixed) continue;
    ++pockets;
    double mean = 0.0;
    for (const std::int32_t row : members) mean += rhs_[row];
    mean /= static_cast<double>(members.size());
    for (const std::int32_t row : members) rhs_[row] -= mean;
    matrix_.diagonal[seed] += scale;  // members are in ascending order's discovery: seed is the first
  }
  return pockets;
}

void PressureSolver::updateVelocity(MacVelocity& velocity, const PressureProblem& problem) {
  const GridGeometry& grid = problem.grid;
  const std::array<Array3f, 3>& faceOpen = problem.faceOpen;
  const std::array<Array3f, 3>& solidVelocity = problem.solidVelocity;
  const double gradientScale = problem.dt / (problem.density * grid.cellSize);  // Δt/(ρh)
  const int ni = grid.cells[0], nj = grid.cells[1];
  const float* const phi = problem.liquidPhi.values().data();
  const double* const pressure = pressure_.values().data();
  for (int a = 0; a < 3; ++a) {
    const Index3 n = grid.faceCount(a);
    valid_[a] = Array3<std::uint8_t>(n, 0);
    // Face (i, j, k) of axis a lies between cell (i, j, k) (+) and the cell one step down a (−);
    // either may be outside the grid. Flat cell indices: (k·nj + j)·ni + i.
    const std::ptrdiff_t stride = a == 0 ? 1 : a == 1 ? ni : static_cast<std::ptrdiff_t>(ni) * nj;
    // Each face is written by the slab that holds it only: the same result on any thread count.
    tbb::parallel_for(0, n[2], [&, a, n, stride](int k) {
      for (int j = 0; j < n[1]; ++j) {
        float* const u = &velocity[a](0, j, k);
        const float* const open = &faceOpen[a](0, j, k);
        const float* const wallVelocity = &solidVelocity[a](0, j, k);
        std::uint8_t* const valid = &valid_[a](0, j, k);
        const std::ptrdiff_t rowCell = (static_cast<std::ptrdiff_t>(k) * nj + j) * ni;
        for (int i = 0; i < n[0]; ++i) {
          if (open[i] <= 0.0f) {
            u[i] = wallVelocity[i];
            continue;
          }
          const int along = a == 0 ? i : a == 1 ? j : k;
          const std::ptrdiff_t plusCell = rowCell + i, minusCell = plusCell - stride;
          const bool hasPlus = along < grid.cells[a], hasMinus = along > 0;
          const bool plusLiquid = hasPlus && phi[plusCell] < 0.0f;
          const bool minusLiquid = hasMinus && phi[minusCell] < 0.0f;
          if (!plusLiquid && !minusLiquid) continue;
          const double pPlus = plusLiquid ? pressure[plusCell] : 0.0;
          const double pMinus = minusLiquid ? pressure[minusCell] : 0.0;
          double theta = 1.0;
          if (!plusLiquid || !minusLiquid) {
            const bool airInGrid = plusLiquid ? hasMinus : hasPlus;
            theta = airInGrid ? surfaceFraction(phi[plusLiquid ? plusCell : minusCell],
                                                phi[plusLiquid ? minusCell : plusCell])
                              : kOpenBoundarySurfaceFraction;
          }
          u[i] = static_cast<float>(u[i] - gradientScale * (pPlus - pMinus) / theta);
          valid[i] = 1;
        }
      }
    });
  }
}

PressureReport PressureSolver::project(MacVelocity& velocity, const PressureProblem& problem,
                                       const PressureSettings& settings) {
  const GridGeometry& grid = problem.grid;
  const double density = problem.density, dt = problem.dt;
  if (problem.targetDivergence != nullptr)
    requireSize(problem.targetDivergence->size(), grid.cells, "targetDivergence");
  requireSize(problem.liquidPhi.size(), grid.cells, "liquidPhi");
  for (int a = 0; a < 3; ++a) {
    const std::string axis = std::to_string(a);
    requireSize(velocity[a].size(), grid.faceCount(a), "velocity[" + axis + "]");
    requireSize(problem.faceOpen[a].size(), grid.faceCount(a), "faceOpen[" + axis + "]");
    requireSize(problem.solidVelocity[a].size(), grid.faceCount(a), "solidVelocity[" + axis + "]");
  }
  if (!(density > 0.0) || !(dt > 0.0) || !(grid.cellSize > 0.0))
    throw std::invalid_argument("pressure projection: density " + std::to_string(density) +
                                " kg/m³, dt " + std::to_string(dt) + " s and cell size " +
                                std::to_string(grid.cellSize) + " m must all be > 0");

  assemble(velocity, problem);
  const PcgStop stop{settings.tolerance, settings.maxIterations};
  PcgResult solve;
  if (settings.preconditioner == Preconditioner::Multigrid) {
    multigrid_.build(unknownOfCell_, problem.faceOpen,
                     dt / (density * grid.cellSize * grid.cellSize));
    solve = pcg_.solve(matrix_, rhs_, solution_, stop, multigrid_.forSolve(matrix_));
  } else {
    mic0_.build(matrix_);
    solve = pcg_.solve(matrix_, rhs_, solution_, stop, mic0_.forSolve(matrix_));
  }

  pressure_ = Array3d(grid.cells, 0.0);
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i)
        if (const std::int32_t row = unknownOfCell_(i, j, k); row >= 0)
          pressure_(i, j, k) = solution_[row];
  updateVelocity(velocity, problem);

  PressureReport report;
  report.iterations = solve.iterations;
  report.relativeResidual = solve.relativeResidual;
  report.converged = solve.converged;
  report.unknowns = static_cast<std::int64_t>(matrix_.size());
  report.sealedPockets = sealedPockets_;
  report.matrixVectorProducts = solve.matrixVectorProducts;
  report.matvecEquivalents = solve.matvecEquivalents;
  return report;
}

namespace {

double relativeDivergence(const MacVelocity& velocity, const Array3f& liquidPhi,
                          const std::array<Array3f, 3>& faceOpen,
                          const std::array<Array3f, 3>* solidVelocity, const GridGeometry& grid,
                          double speedFloor) {
  double maxOutflow = 0.0;
  double maxSpeed = speedFloor;
  for (int k = 0; k < grid.cells[2]; ++k)
    for (int j = 0; j < grid.cells[1]; ++j)
      for (int i = 0; i < grid.cells[0]; ++i) {
        const Index3 c{i, j, k};
        if (liquidPhi(i, j, k) >= 0.0f || !hasOpenFace(faceOpen, c)) continue;
        maxOutflow = std::max(maxOutflow,
                              std::abs(weightedNetOutflow(velocity, faceOpen, solidVelocity, c)));
        for (int a = 0; a < 3; ++a)
          for (const Index3& f : {c, step(c, a, 1)})
            maxSpeed = std::max(maxSpeed, double(std::abs(velocity[a](f[0], f[1], f[2]))));
      }
  if (maxSpeed == 0.0) return maxOutflow == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return maxOutflow / maxSpeed;
}

}  // namespace

double maxRelativeDivergence(const MacVelocity& velocity, const Array3f& liquidPhi,
                             const std::array<Array3f, 3>& faceOpen,
                             const std::array<Array3f, 3>& solidVelocity,
                             const GridGeometry& grid, double speedFloor) {
  return relativeDivergence(velocity, liquidPhi, faceOpen, &solidVelocity, grid, speedFloor);
}

double maxRelativeDivergence(const MacVelocity& velocity, const Array3f& liquidPhi,
                             const std::array<Array3f, 3>& faceOpen, const GridGeometry& grid) {
  return relativeDivergence(velocity, liquidPhi, faceOpen, nullptr, grid, 0.0);
}

}  // namespace fluidsound::sim
