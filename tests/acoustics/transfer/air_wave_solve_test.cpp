// tests/acoustics/transfer/air_wave_solve_test.cpp — the air side's wave solve (air_wave_solve.h):
// over a flat rigid liquid surface it gives the source and its image, and a rigid tube closed by
// the liquid resonates at its quarter wave with the open end's correction (issue 20; shared
// transfer.md §3–4).
#include "acoustics/transfer/air_wave_solve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "tests/support/water_grid_shapes.h"

namespace fluidsound::acoustics {
namespace {

constexpr double kPi = std::numbers::pi;

/// A grid of `cells` at `h` from `origin` with the liquid below y = surface and every face open.
WaterGrid flatSurface(std::array<int, 3> cells, double h, const Vec3& origin, double surface) {
  WaterGrid g;
  g.cells = cells;
  g.cellSize = h;
  g.origin = origin;
  g.phi.resize(g.cellCount());
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i)
        g.phi[g.cellIndex(i, j, k)] = static_cast<float>(g.cellCentre(i, j, k)[1] - surface);
  return g;
}

std::complex<double> freeField(const Vec3& x, const Vec3& source, double w, const AirProperties& air) {
  const double r = std::hypot(x[0] - source[0], x[1] - source[1], x[2] - source[2]);
  return std::complex<double>(0.0, w * air.density) * std::polar(1.0, -w / air.soundSpeed * r) /
         (4.0 * kPi * r);
}

// Reference: a rigid plane under a monopole gives the monopole plus its mirror image, exactly
// (shared transfer.md §1, "rigid-surface doubling" on the plane itself). The liquid's level here
// is 3 mm above the cell faces, so the grid's rigid surface is the face plane y = 0, 3 mm below
// it; the known field is the image in the level (AirWaveOptions::groundHeight), and the solve must
// turn it into the image in y = 0 (a correction of 3–16 % from 0.3 to 3 kHz). Read at the first
// air cell above the surface, listener 1 m away overhead and at 45°: 3 % allowed, the issue's
// tolerance.
TEST(AirWaveSolve, AFlatRigidSurfaceGivesTheSourceAndItsImage) {
  const AirProperties air;
  const double surface = 0.003;
  const WaterGrid grid = flatSurface({16, 8, 16}, 0.01, {-0.08, -0.02, -0.08}, surface);
  const std::vector<double> hz{300, 700, 1500, 3000};
  std::vector<double> w;
  for (double f : hz) w.push_back(2.0 * kPi * f);
  const Vec3 probe{0.005, 0.005, 0.005};
  AirWaveOptions options;
  options.ringTime = 0.01;
  options.absorbingCells = 10;
  options.groundHeight = surface;
  for (const Vec3& listener : {Vec3{0.005, 1.0, 0.005}, Vec3{0.712, 0.712, 0.005}}) {
    const auto p = airSidePressure(grid, listener, std::span(&probe, 1), w, air, options);
    const Vec3 image{listener[0], -listener[1], listener[2]};  // in the grid's surface, y = 0
    for (std::size_t q = 0; q < w.size(); ++q) {
      const std::complex<double> exact =
          freeField(probe, listener, w[q], air) + freeField(probe, image, w[q], air);
      EXPECT_NEAR(std::abs(p[0][q] - exact) / std::abs(exact), 0.0, 0.03)
          << hz[q] << " Hz, listener at x = " << listener[0];
    }
  }
}

// Reference: the direct Fourier sum of the same run (airSidePressure) at the bins' own
// frequencies; the FFT is the same sum, so they agree to rounding (1e-9 relative).
TEST(AirWaveSolve, TheFastTransformGivesTheDirectSumAtItsBins) {
  const AirProperties air;
  const WaterGrid grid = flatSurface({8, 6, 8}, 0.01, {-0.04, -0.02, -0.04}, 0.003);
  AirWaveOptions options;
  options.ringTime = 0.005;
  options.absorbingCells = 6;
  options.groundHeight = 0.003;
  const std::vector<Vec3> probes{{0.005, 0.005, 0.005}, {-0.025, 0.015, 0.015}};
  const Vec3 listener{0.3, 0.5, 0.1};
  const AirSideSpectra fast = airSideSpectra(grid, listener, probes, air, options);
  ASSERT_EQ(fast.pressure.size(), 2u);
  ASSERT_GT(fast.pressure[0].size(), 100u);
  const std::vector<std::size_t> bins{3, 40, fast.pressure[0].size() - 1};
  std::vector<double> w;
  for (std::size_t q : bins) w.push_back(2.0 * kPi * fast.binSpacing * static_cast<double>(q));
  const auto direct = airSidePressure(grid, listener, probes, w, air, options);
  for (std::size_t s = 0; s < probes.size(); ++s)
    for (std::size_t b = 0; b < bins.size(); ++b)
      EXPECT_NEAR(std::abs(fast.pressure[s][bins[b]] - direct[s][b]) / std::abs(direct[s][b]), 0.0, 1e-9)
          << "probe " << s << " bin " << bins[b];
}

// Reference: a tube closed at one end resonates first at c_a/(4(L + 0.6133 r)) (the unflanged
// open end's correction, Levine & Schwinger 1948; shared transfer.md §3, "glass air column"). The
// air-side transfer to the liquid surface at the bottom of a tube of radius 3.5 cm, its air column
// L = 12, 9, 6 and 3 cm (an empty glass and three fill levels), peaks there (its strongest
// response within ±50 % of it, where the next resonance, 3× higher, cannot be) within 5 % (the issue's
// tolerance; 1 cm cells resolve the shortest wavelength, 20 cm at 1.7 kHz, with 20 cells). r is
// the radius of the circle with the staircase tube's area, the tube the grid holds.
TEST(AirWaveSolve, AClosedTubeResonatesAtItsQuarterWaveWithTheEndCorrection) {
  const AirProperties air;
  const double radius = 0.035;
  std::vector<double> w;
  for (double f = 300.0; f <= 3000.0; f += 5.0) w.push_back(2.0 * kPi * f);
  AirWaveOptions options;
  options.groundHeight = 0.0;
  options.ringTime = 0.04;
  options.absorbingCells = 10;
  const Vec3 probe{0.005, 0.005, 0.005}, listener{0.005, 0.4, 0.005};
  for (const double column : {0.12, 0.09, 0.06, 0.03}) {
    const WaterGrid tube = test::tubeOnLiquid(radius, column, 0.01);
    double area = 0.0;  // the staircase tube's cross-section [m²]
    for (int k = 0; k < tube.cells[2]; ++k)
      for (int i = 0; i < tube.cells[0]; ++i) {
        const Vec3 x = tube.cellCentre(i, 0, k);
        if (std::hypot(x[0], x[2]) < radius) area += tube.cellSize * tube.cellSize;
      }
    const double equivalentRadius = std::sqrt(area / kPi);
    const auto p = airSidePressure(tube, listener, std::span(&probe, 1), w, air, options)[0];
    const double expected = air.soundSpeed / (4.0 * (column + 0.6133 * equivalentRadius));
    std::size_t peak = 0;  // the strongest response between 0.5 and 1.5 times the expected
    for (std::size_t q = 0; q < p.size(); ++q) {
      const double f = w[q] / (2.0 * kPi);
      if (f > 0.5 * expected && f < 1.5 * expected && std::abs(p[q]) > std::abs(p[peak])) peak = q;
    }
    const double hz = w[peak] / (2.0 * kPi);
    EXPECT_NEAR(hz / expected, 1.0, 0.05) << "air column " << column << " m: " << hz << " Hz";
  }
}

/// flatSurface with a thin rigid wall: every face normal to x at face index `wallFace` shut.
WaterGrid flatSurfaceWithWall(std::array<int, 3> cells, double h, const Vec3& origin, double surface,
                              int wallFace) {
  WaterGrid g = flatSurface(cells, h, origin, surface);
  for (int a = 0; a < 3; ++a) {
    std::array<int, 3> f = cells;
    ++f[a];
    g.faceOpen[a].assign(static_cast<std::size_t>(f[0]) * f[1] * f[2], 1.0f);
  }
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j) g.faceOpen[0][g.faceIndex(0, wallFace, j, k)] = 0.0f;
  return g;
}

// Reference: a rigid wall x = x_w beside the bubble and the rigid liquid surface y = 0 under it:
// the image solution, the listener and its images in both planes (4 monopoles), and in the far
// field the factor 2|cos(k_a x₀ sinθ cosφ)| on the surface's doubling, x₀ the probe's distance
// from the wall, θ the listener's angle from the vertical and φ its azimuth from the wall's normal
// (shared transfer.md §3). The known field holds the wall where the grid has it (walls lie on
// faces) and the ground at the liquid's level, 3 mm above the faces, so the solve must move the
// ground's images (a phase of 2k·3 mm, up to 0.33 rad at 3 kHz) with the wall in place. Listener 10 m away, where the
// far-field factor is within 1 % of the image solution. The 5 % on the factor wherever it
// is at least 0.5, at probes 5–45 mm from the wall and 0.3–3 kHz (measured ≤ 3.8 %); near a null
// (0.32 at 3 kHz, 45 mm) a relative error means little, so every point is also held against the
// open surface's field: 12 % allowed, twice the measured 6.2 % (3 kHz has 11 cells per wavelength).
// With the wall's plane told 3 mm off the grid's, the factor's error reaches 6.5 % at 3 kHz.
TEST(AirWaveSolve, ARigidWallBesideTheBubbleGivesTheImageSolutionsFactor) {
  const AirProperties air;
  const double surface = 0.003, h = 0.01;
  const Vec3 origin{-0.08, -0.02, -0.08};
  const int wallFace = 4;
  const double wallX = origin[0] + wallFace * h;  // −0.04
  const WaterGrid grid = flatSurfaceWithWall({16, 8, 16}, h, origin, surface, wallFace);
  const std::vector<double> hz{300, 700, 1500, 3000};
  std::vector<double> w;
  for (double f : hz) w.push_back(2.0 * kPi * f);
  AirWaveOptions options;
  options.ringTime = 0.01;
  options.absorbingCells = 10;
  options.groundHeight = surface;
  options.walls = {{0, wallX + 0.0}};
  const std::vector<Vec3> probes{{wallX + 0.005, 0.005, 0.005}, {wallX + 0.025, 0.005, 0.005},
                                 {wallX + 0.045, 0.005, 0.005}};
  int checked = 0;
  double worst = 0.0, worstAbsolute = 0.0;
  for (const double theta : {0.6, 1.1}) {
    for (const double phi : {0.0, 0.8}) {
      const double R = 10.0;
      const Vec3 listener{R * std::sin(theta) * std::cos(phi), R * std::cos(theta), R * std::sin(theta) * std::sin(phi)};
      const auto p = airSidePressure(grid, listener, probes, w, air, options);
      for (std::size_t s = 0; s < probes.size(); ++s) {
        const Vec3& x = probes[s];
        const double x0 = x[0] - wallX;
        for (std::size_t q = 0; q < w.size(); ++q) {
          std::complex<double> exact(0.0), surfaceOnly(0.0);
          for (const Vec3& y : {listener, Vec3{listener[0], -listener[1], listener[2]}}) {
            surfaceOnly += freeField(x, y, w[q], air);
            exact += freeField(x, y, w[q], air) + freeField(x, {2.0 * wallX - y[0], y[1], y[2]}, w[q], air);
          }
          // Everywhere, nulls included: the error against the open surface's own field.
          worstAbsolute = std::max(worstAbsolute, std::abs(p[s][q] - exact) / std::abs(surfaceOnly));
          EXPECT_LT(std::abs(p[s][q] - exact) / std::abs(surfaceOnly), 0.12)
              << hz[q] << " Hz, x0 " << x0 << ", θ " << theta << ", φ " << phi;
          const double factor = 2.0 * std::abs(std::cos(w[q] / air.soundSpeed * x0 * std::sin(theta) * std::cos(phi)));
          ASSERT_NEAR(std::abs(exact) / std::abs(surfaceOnly), factor, 0.01 * 2.0);  // the far field holds
          if (factor < 0.5) continue;  // near a null a relative error means little
          EXPECT_NEAR(std::abs(p[s][q]) / std::abs(surfaceOnly) / factor, 1.0, 0.05)
              << hz[q] << " Hz, x0 " << x0 << ", θ " << theta << ", φ " << phi;
          ++checked;
          worst = std::max(worst, std::abs(std::abs(p[s][q]) / std::abs(surfaceOnly) / factor - 1.0));
        }
      }
    }
  }
  EXPECT_GT(checked, 30);
  std::printf("wall factor: %d points, largest error %.1f %%; against the open surface's field %.1f %%\n",
              checked, 100.0 * worst, 100.0 * worstAbsolute);
}

/// Fresnel–Kirchhoff knife-edge factor F(v) = (1+i)/2 ∫_v^∞ e^{−iπt²/2} dt: the field behind a
/// straight edge over the free field, v > 0 in the shadow (Born & Wolf, Principles of Optics §8.7;
/// 1/2 on the shadow's boundary). ∫_0^v by Simpson's rule, ∫_0^∞ = (1 − i)/2.
std::complex<double> knifeEdgeFactor(double v) {
  const int n = 4000;
  const double dt = v / n;
  std::complex<double> sum(0.0);
  for (int m = 0; m <= n; ++m) {
    const double t = m * dt, weight = (m == 0 || m == n) ? 1.0 : (m % 2 == 1 ? 4.0 : 2.0);
    sum += weight * std::polar(1.0, -kPi * t * t / 2.0);
  }
  const std::complex<double> toV = sum * dt / 3.0;
  return std::complex<double>(0.5, 0.5) * (std::complex<double>(0.5, -0.5) - toV);
}

// Reference: a thin rigid screen of height H standing on the rigid ground between the listener
// and the bubble, its edge straight: the knife-edge estimate. By images in the ground the screen is
// a strip from −H to H lit by the listener and its image; each passes over both edges, its free
// field times F(v), v = h_e √(2(d₁+d₂)/(λd₁d₂)), h_e the edge's distance from the path's line of
// sight (Fresnel–Kirchhoff: Born & Wolf §8.7; Maekawa's 1968 barrier chart rests on it).
// Attenuation = |p| over the field without the screen. The 3 dB, the bubble 3.5 and 7.5 cm
// behind a 10 cm screen, the listener 2 m in front, at 1–4 kHz, where the screen is at least a
// third of a wavelength tall (kH ≥ 1.8) and the grid has at least 11 cells per wavelength
// (measured ≤ 2.7 dB). Kirchhoff's estimate is for screens large against the wavelength: at 500 Hz
// (kH = 0.9) the solve gives +1.3 dB, the estimate −4.5; at 4 kHz (8.6 cells per wavelength) the
// solve is 3.2 dB deeper than the estimate 3.5 cm behind the screen.
TEST(AirWaveSolve, AListenerBehindARigidScreenIsAttenuatedAsTheKnifeEdgeSays) {
  const AirProperties air;
  const double h = 0.01, surface = 0.0, height = 0.10;
  const int nz = 20;
  const Vec3 origin{-0.10, -0.02, -0.10};
  const int screenFace = 10;  // x = 0
  WaterGrid grid = flatSurfaceWithWall({20, 18, nz}, h, origin, surface, screenFace);
  for (int k = 0; k < nz; ++k)  // the wall only up to the screen's height
    for (int j = 0; j < 18; ++j)
      if (grid.cellCentre(0, j, 0)[1] > height) grid.faceOpen[0][grid.faceIndex(0, screenFace, j, k)] = 1.0f;
  const std::vector<double> hz{1000, 2000, 3000};
  std::vector<double> w;
  for (double f : hz) w.push_back(2.0 * kPi * f);
  AirWaveOptions options;
  options.maxFrequency = 5000.0;
  options.ringTime = 0.01;
  options.absorbingCells = 10;
  options.groundHeight = surface;
  const Vec3 listener{-2.0, 0.3, 0.005};
  const std::vector<Vec3> probes{{0.035, 0.005, 0.005}, {0.075, 0.005, 0.005}};
  const auto p = airSidePressure(grid, listener, probes, w, air, options);
  for (std::size_t s = 0; s < probes.size(); ++s) {
    const Vec3& x = probes[s];
    for (std::size_t q = 0; q < w.size(); ++q) {
      const double lambda = air.soundSpeed / hz[q];
      // By images in the ground the screen is a strip from −H to H in free space, lit by the
      // listener and its image; each passes over the top edge and under the bottom one.
      std::complex<double> open(0.0), estimate(0.0);
      for (const Vec3& y : {listener, Vec3{listener[0], -listener[1], listener[2]}}) {
        const std::complex<double> free = freeField(x, y, w[q], air);
        const double sight = y[1] + (x[1] - y[1]) * (0.0 - y[0]) / (x[0] - y[0]);  // line's height at the screen
        for (const double edge : {height, -height}) {
          const double d1 = std::hypot(y[0], y[1] - edge), d2 = std::hypot(x[0], x[1] - edge);
          const double v = std::abs(edge - sight) * std::sqrt(2.0 * (d1 + d2) / (lambda * d1 * d2));
          estimate += knifeEdgeFactor(v) * free;
        }
        open += free;
      }
      const double solved = 20.0 * std::log10(std::abs(p[s][q]) / std::abs(open));
      const double knifeEdge = 20.0 * std::log10(std::abs(estimate) / std::abs(open));
      EXPECT_LT(knifeEdge, -4.0);  // the bubble is in the shadow
      EXPECT_NEAR(solved, knifeEdge, 3.0) << hz[q] << " Hz, " << x[0] << " m behind";
    }
  }
}

}  // namespace
}  // namespace fluidsound::acoustics
