// tests/sim/fluid/pressure_solver_test.cpp — the variational pressure projection (Batty, Bertails &
// Bridson 2007) with a ghost-fluid free surface: liquid at rest in tanks of several shapes stays
// at rest with hydrostatic pressure, a random field becomes discretely divergence-free, a moving
// solid drives the liquid at its own speed, and the result is bit-identical for any thread count.
#include "sim/fluid/pressure_solver.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <random>
#include <span>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "sim/fluid/solid_geometry.h"

namespace fluidsound::sim {
namespace {

constexpr double kGravity = 9.81;    // m/s², standard gravity (the scene default)
constexpr double kDensity = 1000.0;  // kg/m³, water
constexpr double kDt = 0.01;         // s, a typical liquid substep
constexpr double kCell = 0.01;       // h [m]

/// A closed box domain of n³ cells of kCell, its solids, and liquid below a flat surface.
struct Tank {
  GridGeometry grid;
  Domain domain;
  Array3f nodeDistance;
  std::array<Array3f, 3> faceOpen;
  std::array<Array3f, 3> solidVelocity;
  Array3f liquidPhi;  ///< y − surfaceHeight at cell centres [m]
  double surfaceHeight = 0.0;

  Tank(int n, double surface, std::span<const Solid> solids = {}, bool openTop = false,
       double time = 0.0)
      : surfaceHeight(surface) {
    grid = GridGeometry{{n, n, n}, kCell, {0.0, 0.0, 0.0}};
    domain.min = {0.0, 0.0, 0.0};
    domain.max = {n * kCell, n * kCell, n * kCell};
    domain.cell = kCell;
    domain.open = {false, false, false, openTop, false, false};
    nodeDistance = solidNodeDistance(grid, domain, solids, time);
    solidVelocity = solidFaceVelocity(grid, domain, solids, time);
    liquidPhi = Array3f(grid.cells);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          liquidPhi(i, j, k) = float(grid.cellCentre(i, j, k)[1] - surface);
    updateWeights();
  }
  void updateWeights() { faceOpen = faceOpenFractions(nodeDistance, grid); }
};

/// Velocity at rest, then gravity applied for one step: v = −gΔt on every y-face.
MacVelocity afterGravity(const GridGeometry& grid) {
  MacVelocity u(grid);
  u[1].fill(float(-kGravity * kDt));
  return u;
}

/// Largest |u| over faces the projection marked valid (open, next to liquid).
double maxValidSpeed(const MacVelocity& u, const PressureSolver& solver) {
  double m = 0.0;
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < u[a].values().size(); ++f)
      if (solver.validFaces()[a].values()[f]) m = std::max(m, double(std::abs(u[a].values()[f])));
  return m;
}

/// Largest |p − ρ g (H − y)| over the cells that were unknowns, relative to ρ g H.
double maxHydrostaticError(const Tank& tank, const PressureSolver& solver) {
  double m = 0.0;
  const Index3 n = tank.grid.cells;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        if (tank.liquidPhi(i, j, k) >= 0.0f || solver.pressure()(i, j, k) == 0.0) continue;
        const double depth = tank.surfaceHeight - tank.grid.cellCentre(i, j, k)[1];
        m = std::max(m, std::abs(solver.pressure()(i, j, k) - kDensity * kGravity * depth));
      }
  return m / (kDensity * kGravity * tank.surfaceHeight);
}

void printFigures(const char* name, const PressureReport& r, double speed, double pressure) {
  std::cout << "[ figures  ] " << name << ": " << r << ", max|u|/(gΔt) " << speed
            << ", max hydrostatic error/(ρgH) " << pressure << "\n";
}

/// Fills every face with a uniform random velocity in [−1, 1] m/s (fixed seed).
void randomize(MacVelocity& u, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> speed(-1.0f, 1.0f);
  for (int a = 0; a < 3; ++a)
    for (float& v : u[a].values()) v = speed(random);
}

PressureReport project(PressureSolver& solver, MacVelocity& u, const Tank& tank,
                       const PressureSettings& settings = {}) {
  return solver.project(
      u,
      PressureProblem{tank.liquidPhi, tank.faceOpen, tank.solidVelocity, tank.grid, kDensity, kDt},
      settings);
}

/// One gravity step of a tank at rest, projected: the report, the largest speed on valid faces
/// relative to gΔt, and the largest hydrostatic pressure error relative to ρgH (figures printed).
struct RestingTankResult {
  PressureReport report;
  double relativeSpeed = 0.0;
  double relativePressureError = 0.0;
};

RestingTankResult projectRestingTank(const Tank& tank, const char* name,
                                     const PressureSettings& settings = {}) {
  MacVelocity u = afterGravity(tank.grid);
  PressureSolver solver;
  RestingTankResult result;
  result.report = project(solver, u, tank, settings);
  result.relativeSpeed = maxValidSpeed(u, solver) / (kGravity * kDt);
  result.relativePressureError = maxHydrostaticError(tank, solver);
  printFigures(name, result.report, result.relativeSpeed, result.relativePressureError);
  return result;
}

TEST(PressureSolver, HydrostaticTankStaysAtRest) {
  for (int n : {16, 32}) {
    SCOPED_TRACE(testing::Message() << n << "³ cells");
    // Half full: surface at (n/2 + 0.3)·h, between the centres of the top liquid cell (0.8 h
    // below) and the first air cell (0.2 h above), so θ = 0.8 (not a special value).
    Tank tank(n, (n / 2 + 0.3) * kCell);
    const int layers = n / 2;  // m: liquid cells per column
    const PressureSettings settings{1e-8, 1000};
    const auto [r, speed, pressure] = projectRestingTank(tank, "hydrostatic tank", settings);
    // Claim: liquid at rest under gravity stays at rest, and p = ρ g d at depth d — exactly, for
    // a flat surface, in the discrete ghost-fluid system (v = 0 and p = ρ g d satisfy every face
    // and surface equation). Tolerance: the solve leaves a residual max|r| ≤ tol·max|b| with
    // max|b| = gΔt/h (the bottom layer); the divergence of each cell is −r and the flow is
    // columnar, so |v| ≤ m·h·max|r| = m·tol·gΔt (m ≤ 16 layers: 1.6e-7 at tol = 1e-8), and the
    // pressure, summed from the surface down, is off by ≤ (m + 1/θ)·m·tol·ρgh ≤ 2e-7·ρgH.
    // Both are below the claimed 1e-6; float storage of v adds ~1e-7·|v| only.
    EXPECT_TRUE(r.converged);
    EXPECT_GT(r.iterations, 0);
    EXPECT_EQ(r.unknowns, std::int64_t(n) * n * layers);
    EXPECT_LT(speed, 1e-6);
    EXPECT_LT(pressure, 1e-6);
  }
}

TEST(PressureSolver, OpenTopIsAPressureReleaseSurface) {
  // Claim: a tank full to an open top keeps its liquid at rest with p = 0 on the open face
  // itself: p = ρ g (H − y), H the top of the domain (kOpenBoundarySurfaceFraction = ½ places
  // the air half a cell above the top cell centres). Reference: hydrostatics. Tolerance: as in
  // HydrostaticTankStaysAtRest (m = 16 layers, tol 1e-8).
  constexpr int kSide = 16;
  Tank tank(kSide, 2.0, {}, /*openTop=*/true);  // surface far above: every cell is liquid
  tank.surfaceHeight = kSide * kCell;           // where p = 0: the open face
  const auto [r, speed, pressure] = projectRestingTank(tank, "open-top tank", PressureSettings{1e-8, 1000});
  EXPECT_TRUE(r.converged);
  EXPECT_LT(speed, 1e-6);
  EXPECT_LT(pressure, 1e-6);
}

TEST(PressureSolver, LiquidOnASlopedFloorStaysAtRest) {
  // Claim: liquid at rest on a 25° slope that cuts faces at arbitrary fractions stays at rest:
  // the variational method weights the divergence and the pressure gradient by the same open
  // fractions (Batty, Bertails & Bridson 2007, §3), so p = ρ g d balances gravity on every open
  // face whatever its weight, and no spurious current runs along the cut cells (an unweighted
  // divergence with weighted gradients, or the reverse, fails this). Reference: hydrostatics,
  // p = ρ g d. Tolerance 1e-4·gΔt and 1e-4·ρgH (the acceptance figure):
  // the columnar bound m·tol·gΔt of the flat tank is ≤ 1.7e-5 at the default tol = 1e-6 with
  // m ≤ 17, and 1e-4 leaves 6× for the lateral redistribution around the slope.
  constexpr int kSide = 16;
  constexpr double kSlopeDegrees = 25.0;
  const double length = kSide * kCell;  // domain side [m]
  // A slab thick enough that its underside stays below the domain (else the gap under it holds
  // a closed pocket of "liquid" with no surface), rotated about its centre.
  Solid slope;
  slope.shape = Box{{-length, -0.5 * length, -length}, {2 * length, 0.5 * length, 2 * length}};
  slope.rotateDegrees = {0.0, 0.0, kSlopeDegrees};
  slope.translate = {0.0, -0.25 * length, 0.0};  // top at y ≈ 0.07 L … 0.54 L across the tank
  // Surface at 11.3 h (≈ 0.7 L): θ = 0.8 at the surface, as in the flat tank.
  Tank tank(kSide, 11.3 * kCell, std::span(&slope, 1));
  const auto [r, speed, pressure] = projectRestingTank(tank, "sloped floor");
  EXPECT_TRUE(r.converged);
  EXPECT_LT(speed, 1e-4);
  EXPECT_LT(pressure, 1e-4);
}

TEST(PressureSolver, LiquidInASphericalBowlStaysAtRest) {
  // Claim: as on the slope, liquid resting in a spherical cavity (solid everywhere outside a
  // sphere: nodal distance R − |x − c|, built here by hand) stays at rest; the curved wall cuts
  // faces at every fraction down to slivers. Reference and tolerance as for the sloped floor.
  constexpr int kSide = 16;
  const double length = kSide * kCell;
  const Vec3 centre{0.5 * length, 0.5 * length, 0.5 * length};
  const double radius = 0.45 * length;
  Tank tank(kSide, 6.7 * kCell);  // surface ≈ 0.42 L, 0.2 h above a row of cell centres: θ = 0.2
  for (int k = 0; k <= kSide; ++k)
    for (int j = 0; j <= kSide; ++j)
      for (int i = 0; i <= kSide; ++i) {
        const Vec3 p = tank.grid.worldFromGrid({double(i), double(j), double(k)});
        const double bowl =
            radius - std::hypot(p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]);
        tank.nodeDistance(i, j, k) = std::min(tank.nodeDistance(i, j, k), float(bowl));
      }
  tank.updateWeights();
  const auto [r, speed, pressure] = projectRestingTank(tank, "spherical bowl");
  EXPECT_TRUE(r.converged);
  EXPECT_LT(speed, 1e-4);
  EXPECT_LT(pressure, 1e-4);
}

/// A sphere of radius 0.2 n h through the surface of RandomCase's tank.
Solid submergedBall(int n) {
  Solid s;
  s.shape = Sphere{{0.4 * n * kCell, 0.55 * n * kCell, 0.5 * n * kCell}, 0.2 * n * kCell};
  return s;
}

/// A tank with a free surface and a partly submerged sphere (fractional weights), random flow.
struct RandomCase {
  Solid ball;
  Tank tank;
  MacVelocity velocity;
  RandomCase(int n, unsigned seed)
      : ball(submergedBall(n)),
        tank(n, 0.6 * n * kCell + 0.3 * kCell, std::span(&ball, 1)),
        velocity(tank.grid) {
    randomize(velocity, seed);
  }
};

TEST(PressureSolver, RandomFlowBecomesDivergenceFree) {
  // Claim: after projection the weighted divergence Σ ±[w u + (1 − w) u_solid] of every liquid
  // cell vanishes (Batty 2007, eq. 9): max|div|·h/max|u| < 1e-5 at the default tolerance 1e-6.
  // Reference: the discrete divergence after the update is exactly −r (the solver's residual),
  // so max|div|·h ≤ tol·max|b|·h ≤ tol·6·max|u*| (six faces); max|u| after projection is
  // still ≈ max|u*| (≈ 1 m/s, random), giving ≈ 6e-6 in the worst case, plus ~4e-7 from float
  // storage of u (six faces × 2⁻²⁴).
  RandomCase c(24, 7);
  PressureSolver solver;
  const PressureReport r = project(solver, c.velocity, c.tank);
  const double divergence =
      maxRelativeDivergence(c.velocity, c.tank.liquidPhi, c.tank.faceOpen, c.tank.grid);
  std::cout << "[ figures  ] random flow 24³: " << r << ", max relative divergence " << divergence
            << "\n";
  EXPECT_TRUE(r.converged);
  EXPECT_LT(divergence, 1e-5);
}

TEST(PressureSolver, MovingFloorLiftsTheLiquidAtItsSpeed) {
  // Claim: the solid velocity enters through (1 − w)·u_solid: a floor (top on the plane y = 4h)
  // rising at V = 0.5 m/s under liquid at rest lifts the whole column at V — the only
  // divergence-free field with v = V at the floor, no flow through the walls and a free surface
  // on top. Reference: incompressibility (continuity of the flux up each column). Tolerance:
  // columnar bound m·tol·max|b|·h = m·tol·V with m = 7 layers at tol 1e-8: 7e-8·V; 1e-6·V
  // leaves room for float storage of u.
  constexpr int kSide = 16;
  constexpr double kLift = 0.5;  // V [m/s]
  Solid floor;
  floor.shape = Box{{-1.0, -1.0, -1.0}, {2.0, 4 * kCell, 2.0}};
  floor.path = {PathKey{0.0, {0, 0, 0}}, PathKey{1.0, {0, kLift, 0}}};
  Tank tank(kSide, 11.3 * kCell, std::span(&floor, 1));
  MacVelocity u(tank.grid);
  PressureSolver solver;
  const PressureReport r = project(solver, u, tank, PressureSettings{1e-8, 1000});
  double error = 0.0;
  int checked = 0;
  for (int a = 0; a < 3; ++a)
    for (std::size_t f = 0; f < u[a].values().size(); ++f)
      if (solver.validFaces()[a].values()[f]) {
        ++checked;
        error = std::max(error, std::abs(u[a].values()[f] - (a == 1 ? kLift : 0.0)));
      }
  const double divergence =
      maxRelativeDivergence(u, tank.liquidPhi, tank.faceOpen, tank.solidVelocity, tank.grid);
  std::cout << "[ figures  ] moving floor: " << r << ", max|u − (0, V, 0)|/V " << error / kLift
            << ", max relative divergence " << divergence << "\n";
  EXPECT_TRUE(r.converged);
  EXPECT_GT(checked, 0);
  EXPECT_LT(error, 1e-6 * kLift);
  EXPECT_LT(divergence, 1e-6);
  EXPECT_EQ(u[1](8, 4, 8), float(kLift));  // a closed face in the floor's top: the floor's speed
}

TEST(PressureSolver, ProjectionIsBitIdenticalForAnyThreadCount) {
  // Claim: the same input gives the same bits: twice in a row with one solver (buffers reused),
  // and with one thread and two threads (dot products reduce fixed blocks in a fixed order).
  // 32³ with a 60 % fill gives over 16 000 unknowns: ≥ 5 reduction blocks, so two threads split it.
  const auto run = [](int threads, PressureSolver& solver) {
    RandomCase c(32, 11);
    PressureReport r;
    tbb::task_arena arena(threads);
    arena.execute([&] { r = project(solver, c.velocity, c.tank); });
    return std::tuple{r, c.velocity, solver.pressure()};
  };
  PressureSolver reused, other;
  const auto [r1, u1, p1] = run(1, reused);
  const auto [r2, u2, p2] = run(2, reused);
  const auto [r3, u3, p3] = run(2, other);
  EXPECT_GT(r1.unknowns, std::int64_t(4 * PcgSolver::kReductionBlock));
  EXPECT_EQ(r1, r2);
  EXPECT_EQ(r1, r3);
  for (int a = 0; a < 3; ++a) {
    const std::size_t bytes = u1[a].values().size() * sizeof(float);
    EXPECT_EQ(std::memcmp(u1[a].data(), u2[a].data(), bytes), 0) << "axis " << a;
    EXPECT_EQ(std::memcmp(u1[a].data(), u3[a].data(), bytes), 0) << "axis " << a;
  }
  const std::size_t bytes = p1.values().size() * sizeof(double);
  EXPECT_EQ(std::memcmp(p1.data(), p2.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(p1.data(), p3.data(), bytes), 0);
}

TEST(PressureSolver, ReportsAnUnconvergedSolve) {
  // Claim: an iteration limit too small for the tolerance is reported (converged false, the
  // iterations used), not hidden: a 24³ random field needs more than 3 iterations for 1e-6.
  RandomCase c(24, 3);
  PressureSolver solver;
  const PressureReport r = project(solver, c.velocity, c.tank, PressureSettings{1e-6, 3});
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_GT(r.relativeResidual, 1e-6);
}

TEST(PressureSolver, RejectsArraysOfTheWrongSize) {
  Tank tank(8, 0.04);
  MacVelocity u = afterGravity(tank.grid);
  Array3f wrongPhi(Index3{8, 8, 7});
  PressureSolver solver;
  EXPECT_THROW(
      solver.project(
          u, PressureProblem{wrongPhi, tank.faceOpen, tank.solidVelocity, tank.grid, kDensity, kDt},
          PressureSettings{}),
      std::invalid_argument);
  EXPECT_THROW(solver.project(u,
                              PressureProblem{tank.liquidPhi, tank.faceOpen, tank.solidVelocity,
                                              tank.grid, kDensity, 0.0},
                              PressureSettings{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace fluidsound::sim

namespace fluidsound::sim {
namespace {

TEST(PressureSolver, SealedPocketIsSolvedWithItsVolumeHeld) {
  // Claim: liquid walled in on every side (a closed tank filled to the lid; in a scene, water
  // trapped under a body resting on the floor) has no pressure level fixed by air: its matrix is
  // singular and a rising floor pushes in volume it cannot take. The solver removes the
  // incompatible mean and pins one cell (sealPockets): the solve converges to finite pressures
  // and the only change the pocket's faces see is the divergence-free part. Reference: the
  // closed tank's faces (no flow through walls: the total inflow the rising floor asks for is
  // removed, so every interior face stays finite and the solve's residual meets 1e-8).
  constexpr int kSide = 12;
  Solid floor;
  floor.shape = Box{{-1.0, -1.0, -1.0}, {2.0, 3 * kCell, 2.0}};
  floor.path = {PathKey{0.0, {0, 0, 0}}, PathKey{1.0, {0, 0.5, 0}}};
  Tank tank(kSide, 10.0 * kSide * kCell, std::span(&floor, 1));  // liquid up to and past the lid
  MacVelocity u(tank.grid);
  PressureSolver solver;
  const PressureReport r = project(solver, u, tank, PressureSettings{1e-8, 1000});
  EXPECT_EQ(r.sealedPockets, 1);
  EXPECT_TRUE(r.converged) << r;
  for (double p : solver.pressure().values()) ASSERT_TRUE(std::isfinite(p));
  for (int a = 0; a < 3; ++a)
    for (float v : u[a].values()) ASSERT_TRUE(std::isfinite(v));
  // The open tank of the other tests has none.
  Tank open(kSide, 6.3 * kCell, std::span(&floor, 1), /*openTop=*/true);
  MacVelocity w(open.grid);
  EXPECT_EQ(project(solver, w, open, PressureSettings{1e-8, 1000}).sealedPockets, 0);
}

}  // namespace
}  // namespace fluidsound::sim
