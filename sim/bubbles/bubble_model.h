// sim/bubbles/bubble_model.h — the bubble model stage (DESIGN.md pipeline; docs/bubbles.md): called by
// the liquid solver once per substep on its in-memory state, it finds where the liquid entrains
// air, creates bubbles there, carries them with the liquid as they rise, ends them at the
// surface, and records each bubble's track once per frame.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "sim/bubbles/bubble_entrainment.h"
#include "sim/bubbles/bubble_history.h"
#include "sim/bubbles/bubble_rise.h"
#include "sim/bubbles/bubble_settings.h"
#include "sim/bubbles/bubble_size_distribution.h"
#include "sim/bubbles/bubble_spawning.h"
#include "sim/bubbles/liquid_distance.h"
#include "sim/fluid/liquid_state.h"
#include "sim/fluid/mac_velocity.h"
#include "sim/fluid/velocity_range.h"

namespace fluidsound::sim {

/// What one step of the bubble model did (for the run report and tests).
struct BubbleStepReport {
  std::size_t taggedParticles = 0;  ///< particles within the tagging band
  std::size_t newSeeds = 0;         ///< particles that became seeds in this step
  std::size_t seeds = 0;            ///< live seeds after the step
  SpawnCounts spawn;                ///< Σ potential, Poisson mean, attempts, created, rejections
  std::size_t endedAtSurface = 0;   ///< depth reached the radius (or φ ≥ 0)
  std::size_t endedOutside = 0;     ///< left the grid
  std::size_t endedInSolid = 0;     ///< carried into a solid (solid distance < 0 at the centre)
  std::size_t alive = 0;            ///< live bubbles after the step
  bool operator==(const BubbleStepReport&) const = default;
};

/// @brief The bubble model of Zheng & James (2009), after their structure [memory]: surface
///        particles are tagged; those carried under the surface become seeds whose creation
///        potential decays; each step makes Poisson(rate·Σpotential·dt) attempts, each a radius
///        from the size distribution and a position sampled from the seeds' density, rejected
///        in air, in solids or where seeds are sparse; bubbles rise by buoyancy against drag,
///        carried by the liquid (bubble_rise.h), and end at the free surface.
///
/// Call `step` once per fluid substep, not once per frame: the depth-growth window (20 ms by
/// default) is shorter than a frame (33 ms at 30 fps), the liquid acceleration that carries a
/// bubble is the change of the grid velocity over one substep, and a bubble follows the same
/// CFL-limited velocity fields as the particles. Call `sampleFrame` after the last substep of
/// each frame.
///
/// @par Example
/// @code
///   BubbleModel bubbles(settings, scene.seed, scene.gravity);
///   // in the solver, after each substep (t, t + dt]:
///   bubbles.step(LiquidState{...}, t, dt);
///   // after the frame's last substep, at frame time T:
///   bubbles.sampleFrame(T);
///   // at the end: bubbles.bubbles() → io writes fluidsound.bubbles/1
/// @endcode
/// @note Deterministic: the same inputs and seed give bit-identical bubbles for any thread count
///       and any order of the particle arrays.
class BubbleModel {
 public:
  /// @param seed     the scene seed; the model's random streams derive from it and the step count
  /// @param gravity  g [m/s²], the scene's
  /// @throws std::invalid_argument as validateBubbleSettings, or for a non-finite gravity
  BubbleModel(const BubbleSettings& settings, std::uint64_t seed, const Vec3& gravity);

  /// @brief Advances the model over the step (t, t + dt], whose end state `liquid` describes.
  ///        First the solver's φ is redistanced (SurfaceDistance): every depth below is the
  ///        distance to the free surface. Then (1) moves the live bubbles with bubble_rise (liquid velocity from the grid, material
  ///        acceleration (u(x) − u_prev(x − u·dt))/dt from the previous step's grid velocity) and
  ///        ends those whose depth reaches their radius, that leave the grid or enter a solid;
  ///        (2) tags surface particles and updates the seeds (detectEntrainment); (3) draws and
  ///        tests creation attempts (spawnBubbles); new bubbles start with the liquid's velocity
  ///        at their position and a first sample at their birth.
  ///        The redistancing runs in a task while the bubbles move (their motion reads only the
  ///        solver's state); the result is that of this serial order for any thread count.
  /// @param t   start of the step [s]: the end of the previous step (checked, 1e-9 relative)
  /// @param dt  [s], > 0
  /// @throws std::invalid_argument for a bad dt, a t that does not continue the previous step,
  ///         inconsistent LiquidState arrays or duplicate particle ids
  BubbleStepReport step(const LiquidState& liquid, double t, double dt);

  /// @brief Appends a sample {time, centre, depth} to every live bubble: the state at the end of
  ///        the last step, which must end at `time` (1e-9 relative; before any step, any time).
  ///        A bubble born exactly at `time` already has that sample and gets no second one.
  /// @throws std::invalid_argument when `time` is not the end of the last step
  void sampleFrame(double time);

  /// @brief Adds a bubble by hand (a scripted source; tests), at rest relative to the liquid,
  ///        with a first sample at `birth`; it moves from the next step on. Redistances φ as step.
  /// @param radius  [m], > 0;  @param position  centre [m];  @param birth  [s]
  /// @return false (nothing added) where spawnBubbles would reject the position: outside the
  ///         grid, solid distance < radius, or depth ≤ radius
  /// @throws std::invalid_argument for a radius ≤ 0 or a non-finite position or birth
  bool insertBubble(double radius, const Vec3& position, double birth, const LiquidState& liquid);

  /// Every bubble made so far, live and ended, in creation order.
  const std::vector<BubbleHistory>& bubbles() const { return histories_; }
  std::size_t aliveCount() const { return live_.size(); }
  std::size_t seedCount() const { return seedCount_; }
  /// Totals over all steps so far.
  const SpawnCounts& totalSpawnCounts() const { return totals_; }
  const BubbleSettings& settings() const { return settings_; }
  /// The distance to the surface at the end of the last step (its bands are the model's).
  const SurfaceDistance& surfaceDistance() const { return surface_; }

 private:
  struct LiveBubble {
    std::size_t history = 0;  ///< index into histories_
    BubbleMotion motion;
    double depth = 0.0;       ///< −(band field) at the centre at the end of the last step [m]
  };
  /// Moves every live bubble over the step (bubble_rise.h) in the solver's grid velocity.
  void moveLiveBubbles(const LiquidState& solverState, double dt);
  /// Ends the moved bubbles whose depth (in liquid's true distance) reached their radius, that
  /// left the grid or entered a solid; updates the others' depth.
  void endLiveBubbles(const LiquidState& liquid, double t, double dt, BubbleStepReport& report);
  void addBubble(double radius, double birth, const Vec3& position, double depth, const LiquidState& liquid);
  /// What happened to a live bubble in endLiveBubbles.
  enum class Fate : std::uint8_t { Lives, Surface, Outside, Solid };
  /// Rebuilds surface_ from the solver's φ.
  void rebuildDistance(const LiquidState& solverState);
  /// `solverState` with φ replaced by surface_.field().
  LiquidState withDistanceField(const LiquidState& solverState) const;

  BubbleSettings settings_;
  BubbleSizeSampler sizes_;
  Vec3 gravity_;
  std::uint64_t streamRoot_;   ///< the scene seed mixed with the bubble model's key
  std::uint64_t steps_ = 0;    ///< steps taken: the key of each step's stream
  double stateTime_ = 0.0;     ///< end of the last step [s]
  MacVelocity previousVelocity_;  ///< grid velocity of the last step (material acceleration)
  SurfaceDistance surface_;       ///< distance to the surface at the end of the last step
  EntrainmentTagTable tags_;
  std::size_t seedCount_ = 0;
  SpawnCounts totals_;
  std::vector<LiveBubble> live_;  ///< in creation order
  std::vector<BubbleHistory> histories_;
  std::optional<VelocityRange> range_;   ///< the grid velocity's range, rebuilt each step
  std::vector<Fate> fates_;              ///< per live bubble, work array of endLiveBubbles
  std::vector<double> deathTimes_;       ///< per live bubble [s], work array of endLiveBubbles
};

}  // namespace fluidsound::sim
