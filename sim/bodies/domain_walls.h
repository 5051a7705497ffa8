// sim/bodies/domain_walls.h — the closed faces of the domain box as thick static wall boxes for
// the rigid-body stage, and how the contact log names them.
#pragma once

#include <vector>

#include "sim/core/vec3.h"

namespace fluidsound::sim {

/// The six faces of an axis-aligned box, in the contact log's order.
enum class DomainFace { MinusX = 0, PlusX = 1, MinusY = 2, PlusY = 3, MinusZ = 4, PlusZ = 5 };

/// @brief The box that holds the bodies: every face not listed as open is a static wall.
/// @note A wall's material pairs with a body's by RigidBodySpec's rules: the defaults μ = 1,
///       e = 1 and δ = 0 let the body's own values act.
struct DomainBox {
  Vec3 min{};                         ///< lower corner, world [m]
  Vec3 max{};                         ///< upper corner, world [m], > min on every axis
  std::vector<DomainFace> openFaces;  ///< faces without a wall (e.g. the top of a tank)
  double friction = 1.0;              ///< Coulomb μ of the walls
  double restitution = 1.0;           ///< restitution e of the walls
  double rollingFriction = 0.0;       ///< rolling-resistance arm δ of the walls [m]
};

/// @return the contact log's index of the wall on `face`: −1 − face (−1 for −x … −6 for +z)
constexpr int wallBodyIndex(DomainFace face) { return -1 - static_cast<int>(face); }

/// @brief A solid wall behind one closed face: a box whose inner face is the domain face.
struct WallBox {
  DomainFace face = DomainFace::MinusX;
  Vec3 centre{};       ///< world [m]
  Vec3 halfExtents{};  ///< [m]
};

/// @brief The walls of the closed faces, in face order.
/// @details Each wall is `thickness` deep behind its face. Across its face it reaches
///          `thickness` beyond each neighbouring closed face, so the walls overlap at closed
///          edges and corners and nothing slips between them; at an open neighbouring face it
///          ends flush with the domain, so an open face is open over its whole area.
/// @param thickness  wall depth [m], > 0; thick walls keep fast bodies from tunnelling through
/// @throws std::invalid_argument if max ≤ min on an axis or thickness ≤ 0
std::vector<WallBox> domainWalls(const DomainBox& domain, double thickness);

}  // namespace fluidsound::sim
