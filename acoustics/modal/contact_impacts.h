// acoustics/modal/contact_impacts.h — the impacts a body's modes hear in the rigid-body stage's
// contact log (sim/core/contact_record.h, re-expressed on the sounding body): a touch that
// closes faster than a threshold after not doing so in the substep before is one impact, its
// points' impulses summed (docs/solids.md, Impacts). Resting, sliding and rolling contacts are
// not impacts: a steady load makes no sound, and their continuous excitation is another model.
#pragma once

#include <functional>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "acoustics/modal/modal_analysis.h"
#include "acoustics/modal/modal_synthesis.h"

namespace fluidsound::acoustics {

/// One logged contact point of one substep, on the body that sounds, in its own frame (the frame
/// of its mesh, which is its modal model's).
struct BodyContactPoint {
  double time = 0.0;                                      ///< end of the substep [s]
  int other = 0;                                          ///< the body or wall touched (the log's index)
  Eigen::Vector3d localPoint = Eigen::Vector3d::Zero();  ///< on this body [m]
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();     ///< on this body this substep [N·s]
  double normalSpeed = 0.0;                               ///< closing speed before the solve [m/s]
  double normalImpulse = 0.0;                             ///< its normal part [N·s], ≥ 0
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();     ///< unit, into this body [-]
  double tangentialSpeed = 0.0;                           ///< sliding speed at the point [m/s]
  /// the rolling rate times the other body's radius at the point: how fast a rolling contact
  /// moves over this body's surface [m/s]
  double rollingSpeed = 0.0;
  /// Where the body was in the substep (for its radiation): its world-from-body rotation and
  /// its reference point's world position [m].
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

/// The points one substep of the log holds with one other body.
struct SubstepTouch {
  long long substep = 0;                        ///< its index: round(time / substep length)
  int other = 0;                                ///< the body or wall touched
  std::vector<const BodyContactPoint*> points;  ///< in the log's order
};

/// @brief The log's points grouped by substep (in time order) and, within one, by other body
///        (ascending: deterministic).
/// @throws std::invalid_argument if the points are out of time order or the substep is not > 0
std::vector<SubstepTouch> substepTouches(std::span<const BodyContactPoint> points, double substep);

struct ImpactDetection {
  /// ε_imp: a touch closing slower than this is no impact [m/s] (the sample-playback paper's
  /// 0.02 m/s, shared solids.md §1.4).
  double minimumSpeed = 0.02;
  double substep = 1e-3;  ///< the log's substep [s]
};

/// @brief The impacts on a body in its contact points (in time order, any order within a
///        substep). For each substep and other body: an impact when some point closes faster
///        than minimumSpeed and no point of that pair did in the substep before. Its impulse is
///        the sum of the pair's points' impulses in that substep, applied at the surface node
///        nearest their impulse-weighted mean point, at the substep's start (the solve's
///        contact), lasting contactDuration(first point, closing speed) [s] (Hertz: hertz_contact.h).
std::vector<ModalImpact> impactsFromContacts(std::span<const BodyContactPoint> points, const ModalModel& model,
                                             const ImpactDetection& detection,
                                             const std::function<double(const BodyContactPoint&, double)>& contactDuration);

/// The index of the surface node of `model` nearest `point` [m] (the model's frame).
std::size_t nearestSurfaceNode(const ModalModel& model, const Eigen::Vector3d& point);

}  // namespace fluidsound::acoustics
