// tests/sim/bodies/domain_walls_test.cpp — the wall boxes behind a domain's closed faces: one
// per closed face, inner face on the domain face, overlapping at closed edges, flush at open ones.
#include "sim/bodies/domain_walls.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace fluidsound::sim {
namespace {

/// Walls are sums and halves of short decimals: exact to a few ulps of 1 m.
constexpr double kRounding = 1e-12;

TEST(DomainWalls, OneWallPerClosedFaceWithItsInnerFaceOnTheDomain) {
  // Claim: an open-topped tank [−1, 1] × [0, 0.5] × [−0.25, 0.25] has five walls (no +y), in
  // face order, each with its inner face on the domain face. Reference: the box's geometry.
  DomainBox tank{{-1.0, 0.0, -0.25}, {1.0, 0.5, 0.25}, {DomainFace::PlusY}};
  const double t = 0.1;
  const std::vector<WallBox> walls = domainWalls(tank, t);
  ASSERT_EQ(walls.size(), 5u);
  const DomainFace expected[] = {DomainFace::MinusX, DomainFace::PlusX, DomainFace::MinusY,
                                 DomainFace::MinusZ, DomainFace::PlusZ};
  for (std::size_t k = 0; k < walls.size(); ++k) {
    const WallBox& w = walls[k];
    EXPECT_EQ(w.face, expected[k]);
    const int axis = static_cast<int>(w.face) / 2;
    const bool upper = static_cast<int>(w.face) % 2 == 1;
    const double inner =
        upper ? w.centre[axis] - w.halfExtents[axis] : w.centre[axis] + w.halfExtents[axis];
    EXPECT_NEAR(inner, upper ? tank.max[axis] : tank.min[axis], kRounding) << "face " << k;
    EXPECT_NEAR(2.0 * w.halfExtents[axis], t, kRounding);
  }
}

TEST(DomainWalls, WallsOverlapAtClosedEdgesAndEndFlushAtOpenFaces) {
  // Claim: the −x wall of the open-topped tank reaches t beyond the floor (−y) and the ±z
  // walls, but ends at y = 0.5 under the open top. Reference: domainWalls' contract.
  DomainBox tank{{-1.0, 0.0, -0.25}, {1.0, 0.5, 0.25}, {DomainFace::PlusY}};
  const double t = 0.1;
  const WallBox w = domainWalls(tank, t).front();
  ASSERT_EQ(w.face, DomainFace::MinusX);
  EXPECT_NEAR(w.centre[1] - w.halfExtents[1], -t, kRounding);
  EXPECT_NEAR(w.centre[1] + w.halfExtents[1], 0.5, kRounding);
  EXPECT_NEAR(w.centre[2] - w.halfExtents[2], -0.25 - t, kRounding);
  EXPECT_NEAR(w.centre[2] + w.halfExtents[2], 0.25 + t, kRounding);
}

TEST(DomainWalls, LogIndicesAndBadBoxes) {
  // Claim: walls are logged as −1 − face; an empty box or a zero thickness is refused.
  EXPECT_EQ(wallBodyIndex(DomainFace::MinusX), -1);
  EXPECT_EQ(wallBodyIndex(DomainFace::PlusX), -2);
  EXPECT_EQ(wallBodyIndex(DomainFace::PlusZ), -6);
  EXPECT_THROW(domainWalls(DomainBox{{0, 0, 0}, {1, 0, 1}, {}}, 0.1), std::invalid_argument);
  EXPECT_THROW(domainWalls(DomainBox{{0, 0, 0}, {1, 1, 1}, {}}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace fluidsound::sim
