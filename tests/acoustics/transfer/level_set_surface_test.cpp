// tests/acoustics/transfer/level_set_surface_test.cpp — the local plane above a bubble from a level
// set given as a sampler: a tilted plane level set gives that plane, and each fallback (beyond the
// band, a weak gradient, a surface below the bubble) gives the horizontal plane at the track's
// depth.
#include "acoustics/transfer/level_set_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace fluidsound::acoustics {
namespace {

/// φ = slope·(n·x − offset), clamped to ±band: a plane level set (slope 1: a distance).
class PlaneLevelSet : public LevelSetSampler {
 public:
  PlaneLevelSet(Vec3 normal, double offset, double slope = 1.0)
      : n_(normal), offset_(offset), slope_(slope) {}
  double phi(const Vec3& x) const override {
    const double d = slope_ * (n_[0] * x[0] + n_[1] * x[1] + n_[2] * x[2] - offset_);
    return std::clamp(d, -kBand, kBand);
  }
  double bandHalfWidth() const override { return kBand; }
  double voxelSize() const override { return 0.01; }
  static constexpr double kBand = 0.03;  // [m]

 private:
  Vec3 n_;
  double offset_, slope_;
};

const Vec3 kUp{0.0, 1.0, 0.0};

// Claim: under a tilted plane surface the local plane is that plane: normal n, depth the distance
// from the centre to the plane along n, the point centre + depth·n. Reference: the plane's closed
// form. Tolerance: 1e-12 (central differences are exact on a linear φ).
TEST(LevelSetSurface, TiltedPlaneGivesItsNormalAndDepth) {
  const double t = 0.3;
  const Vec3 n{std::sin(t), std::cos(t), 0.0};
  const PlaneLevelSet level(n, 0.05);
  const Vec3 centre{0.02, 0.03, 0.01};
  const double expected = 0.05 - (n[0] * centre[0] + n[1] * centre[1]);
  // The track's depth is 3 mm off: the Newton step corrects it.
  const LocalSurface s = localSurfacePlane(level, centre, expected + 0.003, kUp);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.normal[a], n[a], 1e-12);
  EXPECT_NEAR(s.depth, expected, 1e-12);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(s.point[a], centre[a] + s.depth * n[a], 1e-12);
}

// Claim: the three fallbacks give the horizontal plane at the track's depth. Reference: the
// inputs. Tolerance: exact.
TEST(LevelSetSurface, FallsBackToTheHorizontalPlane) {
  const Vec3 centre{0.0, 0.0, 0.0};
  const LocalSurface flat{{0.0, 0.02, 0.0}, kUp, 0.02};
  // Beyond the band: the surface is 10 cm above, the point 2 cm above the bubble.
  EXPECT_EQ(localSurfacePlane(PlaneLevelSet(kUp, 0.1), centre, 0.02, kUp), flat);
  // A weak gradient: |∇φ| = 0.4 < ½.
  EXPECT_EQ(localSurfacePlane(PlaneLevelSet(kUp, 0.025, 0.4), centre, 0.02, kUp), flat);
  // The surface is below the bubble: the projected depth is negative.
  EXPECT_EQ(localSurfacePlane(PlaneLevelSet(kUp, -0.005), centre, 0.02, kUp), flat);
}

// Claim: the frame surface the transfer stage opens answers with localSurfacePlane over its level
// set. Reference: localSurfacePlane. Tolerance: exact.
TEST(LevelSetSurface, FrameSurfaceIsThePlaneOfItsLevelSet) {
  const Vec3 n{0.0, 1.0, 0.0};
  const LevelSetFrameSurface frame(std::make_unique<PlaneLevelSet>(n, 0.05));
  const Vec3 centre{0.01, 0.02, 0.03};
  EXPECT_EQ(frame.surfaceAbove(centre, 0.028, kUp),
            localSurfacePlane(PlaneLevelSet(n, 0.05), centre, 0.028, kUp));
}

}  // namespace
}  // namespace fluidsound::acoustics
