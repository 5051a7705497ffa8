// sim/bodies/body_segment.h — whether a straight segment passes through a rigid body where its spec
// places it (sphere, box, or closed mesh): the line of sight the solids' radiation checks for
// other bodies in the way (acoustics/modal/sound_occlusion.h).
#pragma once

#include "sim/bodies/rigid_body.h"
#include "sim/core/vec3.h"

namespace fluidsound::sim {

/// @brief True when the segment a → b (world [m]) enters the body: a sphere or box it meets, a
///        mesh one of whose triangles it crosses (Möller & Trumbore 1997).
bool segmentCrossesBody(const RigidBodySpec& body, const Vec3& a, const Vec3& b);

/// @brief True when `local` (the body's own frame [m]) lies inside the body: a sphere's or box's
///        interior, or for a mesh an odd number of its triangles crossed by the ray from the point
///        along +x (the mesh is closed: io checks it when the scene is read).
bool bodyContainsPoint(const RigidBodySpec& body, const Vec3& local);

/// @brief The half sides of the body's bounding box about its reference point, in its frame [m]
///        (a mesh's: the largest |coordinate| of its vertices on each axis).
Vec3 boundingHalfExtents(const RigidBodySpec& body);

/// @brief The radius of the body's bounding sphere about its reference point [m].
double boundingRadius(const RigidBodySpec& body);

}  // namespace fluidsound::sim
