// acoustics/modal/solid_sound.h — the solids' stage as one call: the contact log of a run and each
// sounding body's modal model in, the pressure at every listener channel out, in three stems by
// source kind — impacts, rolling, friction (sliding rubbing and stick–slip) — that `run` mixes with
// the bubbles (docs/solids.md, "Bodies in run").
//
// Per body that has modes: its contact points in its frame (body_contact_points.h); impacts
// (contact_impacts.h, Hertz durations from the two bodies' materials, masses and radii); rubbing
// forces (contact_rubbing.h, surface_roughness.h) of the points that do not close faster than the
// impact threshold (a closing point's impulse is its impact's), split by their substeps into
// rolling and sliding; stick–slip breaks of the sliding substeps (stick_slip.h); each radiated to each listener by the
// compact multipoles of mode_radiation.h from where the body was, shadowed by the other bodies
// in the way (sound_occlusion.h). A body that moves is heard from
// its pose at the first contact of each `radiationWindow` (each window's events rung with that
// pose's gains and delay to their end): a body turning during one ring is not followed.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "acoustics/bubble/liquid_properties.h"
#include "acoustics/modal/contact_impacts.h"
#include "acoustics/modal/modal_analysis.h"
#include "acoustics/modal/solid_material.h"
#include "acoustics/modal/sound_occlusion.h"
#include "acoustics/modal/stick_slip.h"
#include "acoustics/modal/surface_roughness.h"
#include "sim/core/contact_record.h"
#include "sim/core/stage_observer.h"

namespace fluidsound::acoustics {

/// One body of the log as the stage hears it.
struct SoundingBody {
  /// Its modes in its own frame (sim::rigidBodySpec's); null or none: the body is silent (its
  /// contacts still set the other bodies' Hertz durations).
  const ModalModel* model = nullptr;
  SolidMaterial material;
};

struct SolidSoundSettings {
  double sampleRate = 48000.0;             ///< [Hz]
  std::size_t samples = 0;                 ///< length of each stem [samples]
  std::vector<Eigen::Vector3d> listeners;  ///< one per output channel, world [m]
  AirProperties air;
  double truncation = 1e-5;       ///< ModalSynthesisSettings::truncation (and the forces' ring-out)
  bool compress = true;           ///< group indistinguishable modes (mode_compression.h)
  double radiationWindow = 0.01;  ///< [s]: how often a moving body's pose is taken again
  /// The walls of the domain, for Hertz durations: taken as this body's own material, flat.
  /// Bodies that shadow the others (sound_occlusion.h): the static ones, where they stand.
  std::vector<Occluder> occluders;
  ImpactDetection impacts;                 ///< substep taken from the log
  RubbingSettings rubbing;                 ///< sampleRate and substep taken from here and the log
  StickSlipSettings stickSlip;             ///< substep taken from the log
  /// The surfaces' roughness (surface_roughness.h): spacing [m], samples, exponent β, shortest
  /// and longest wavelength [m], seed (each body's profile seeded with seed + its index).
  double roughnessSpacing = 25e-6;
  std::size_t roughnessSamples = std::size_t(1) << 16;
  double roughnessExponent = 2.0;
  double roughnessShortest = 1e-3, roughnessLongest = 0.05;
  std::uint64_t roughnessSeed = 1;
};

/// What the stage heard of one body.
struct SolidBodyReport {
  std::size_t modes = 0, oscillators = 0;  ///< modes, and oscillators after compression
  std::size_t impacts = 0;                 ///< impacts found
  std::size_t rubbingContacts = 0;         ///< rubbing touches (runs of substeps)
  std::size_t rollingSubsteps = 0, slidingSubsteps = 0;
  std::size_t stickSlipBreaks = 0;
  std::size_t oscillatorSamples = 0;       ///< impacts' and breaks' mode-samples (the cost)
};

/// The three stems, each one vector per listener channel [Pa].
struct SolidStems {
  std::vector<std::vector<float>> impacts, rolling, friction;
  std::vector<SolidBodyReport> bodies;  ///< one per log body
};

/// @brief Renders the sound of the bodies' contacts in `log` at each listener.
/// @param bodies  one per log.bodies, in order
/// @param observer  progress per body; wasInterrupted() between bodies stops with
///        StageInterrupted("solids body N")
/// @throws std::invalid_argument if bodies and log.bodies differ in count or settings are out of range
/// @note Deterministic: bodies, windows and listeners in a fixed order, one thread.
SolidStems renderSolidSound(const sim::ContactLog& log, std::span<const SoundingBody> bodies,
                            const SolidSoundSettings& settings, StageObserver& observer);

}  // namespace fluidsound::acoustics
