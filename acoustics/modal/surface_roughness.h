// acoustics/modal/surface_roughness.h — the force a rolling or sliding contact puts on a body's
// modes: the normal load modulated by a rough surface's height read at the distance the contact
// has travelled, so that the force's spectrum is the surface's spatial spectrum at f = v·k and
// follows the contact's speed (after FoleyAutomatic, van den Doel, Kry & Pai 2001; shared
// solids.md §6 item 3). docs/solids.md, Rolling and sliding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <Eigen/Core>

namespace fluidsound::acoustics {

/// A periodic random surface profile with a power-law spatial spectrum, |H(k)|² ∝ k^−β between
/// two wavelengths, zero mean and unit RMS (heights in units of its RMS).
class RoughnessProfile {
 public:
  /// @param spacing   sample spacing along the path [m], > 0
  /// @param samples   a power of two ≥ 16: the profile repeats after samples·spacing
  /// @param exponent  β [-] (2: Brownian, the fractal surfaces of FoleyAutomatic)
  /// @param shortest, longest  wavelengths [m] of the band that holds roughness
  /// @param seed      the same seed gives the same profile
  RoughnessProfile(double spacing, std::size_t samples, double exponent, double shortest, double longest,
                   std::uint64_t seed);
  /// Height at path position s [m] (linear between samples), in units of the RMS.
  double height(double s) const;
  double spacing() const { return spacing_; }
  double length() const { return spacing_ * static_cast<double>(heights_.size()); }

 private:
  double spacing_;
  std::vector<double> heights_;
};

/// One substep of a sliding or rolling contact on the sounding body (from the contact log).
struct RubbingSample {
  double time = 0.0;                                    ///< end of the substep [s]
  double normalForce = 0.0;                             ///< mean normal force over it [N], ≥ 0
  double speed = 0.0;                                   ///< the contact's speed over the surface [m/s]
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();  ///< into the sounding body, its frame
  Eigen::Vector3d friction = Eigen::Vector3d::Zero();  ///< mean friction force on the body [N], its frame
  std::size_t surfaceNode = 0;                          ///< where it touches (ModalModel::surfaceNodes)
  bool rolling = false;                                 ///< rolling (true) or sliding: which stem it sounds in
};

struct RubbingSettings {
  double sampleRate = 48000.0;  ///< [Hz]
  double substep = 1e-3;        ///< the contact log's substep [s]
  /// The force's fluctuation per unit load and unit RMS height [-]: F = F_n·(1 + κ·h(s)).
  double roughness = 0.1;
  /// Speed at which the rubbing is half its full strength: the fluctuation is weighted by
  /// v/(v + v₀), so a contact at rest (Bullet's v ~1e-7 m/s) is silent [m/s].
  double quietSpeed = 1e-3;
};

/// The force of one rubbing contact, sample by sample.
struct RubbingForce {
  double startTime = 0.0;                 ///< time of the first sample [s]: the first substep's start
  std::vector<Eigen::Vector3f> force;     ///< [N] on the body, its frame
  std::vector<std::size_t> surfaceNodes;  ///< where, per sample (its substep's node)
  std::vector<char> rolling;              ///< per sample: its substep rolls (1) or slides (0)
};

/// @brief The fluctuating part of the force [N] on the body over the substeps (consecutive, in
///        time order): κ·F_n(t)·v/(v + v₀)·h(s(t))·n, with F_n and v linear between the substeps'
///        midpoints and s = ∫v dt from 0. The steady load is left out (it makes no sound).
RubbingForce rubbingForce(std::span<const RubbingSample> substeps, const RoughnessProfile& surface,
                          const RubbingSettings& settings);

}  // namespace fluidsound::acoustics
