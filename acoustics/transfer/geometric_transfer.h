// acoustics/transfer/geometric_transfer.h — the transfer stage's geometric model (shared
// transfer.md): every track sample's transfer through its frame's real liquid and solids, by
// reciprocity. Per frame and listener: p_L on the surface from a unit source at the listener
// (air side, first model: free field over a rigid liquid surface, rigid_surface_air_field.h), the
// water-side Helmholtz solve (water_helmholtz.h), u read at every bubble. Either one solve per band
// and listener for all the frame's bubbles (reciprocal route), or one per sample at its own
// frequency (adjoint route), whichever needs fewer factorisations. docs/transfer.md.
#pragma once

#include <cstddef>
#include <optional>

#include "acoustics/transfer/transfer_stage.h"
#include "acoustics/transfer/water_grid.h"
#include "acoustics/transfer/wave_air_field.h"

namespace fluidsound::acoustics {

/// Settings of the geometric model (the scene's "transfer" block).
struct GeometricTransferOptions {
  /// Upper limit of bands per frame, 2 … kMaxTransferBands: where the band rule asks for more,
  /// the spacing widens to fit and the frame counts as widened in the stats.
  int maxBands = 256;
  /// η of k_w² = (ω/c_w)²(1 − iη), > 0 and ≤ 0.1. Default: 2ρ_a c_a/(ρ_w c_w), the order of the
  /// energy a resonant water body radiates into air per radian (docs/transfer.md).
  double lossFactor = 5.59e-4;
  /// Bands per radian of the air phase's spread: a frame whose samples span [ω_lo, ω_hi] gets
  /// ⌈bandPhaseFactor·τ⌉ + 12 Chebyshev bands, τ = (ω_hi − ω_lo)·ΔR/(2c_a), ΔR the spread of path
  /// lengths from a listener to the liquid's surface (docs/transfer.md, "Bands and routes").
  double bandPhaseFactor = 1.5;
  /// Highest sample frequency [Hz] the water grid answers; samples above it take the image-source
  /// value under the level plane (counted). 0: the grid's own limit c_a/(4h), four surface
  /// crossings per air wavelength (above it the crossings cannot sample p_L's phase). Else
  /// > 0 and ≤ kMaxTransferFrequency.
  double maxFrequency = 0.0;
  /// The air side: nothing, the rigid-surface field (free field doubled by the liquid surface,
  /// nothing in the way); else a wave solve of the air with the frame's liquid and solids in
  /// place (wave_air_field.h) up to its grid's limit, the rigid-surface field above it.
  std::optional<WaveAirOptions> waveAir;
};

inline constexpr double kMaxTransferFrequency = 100000.0;  // [Hz]

inline constexpr int kMaxTransferBands = 4096;

/// @brief The geometric model's transfer, with the same contract as computeTransfer (transfer
///        values, observer calls, errors, thread-count independence); result.geometric holds the
///        solver statistics.
/// @throws TransferInputError as computeTransfer, and for options out of range
///         (TransferInput::Options, field "transfer.max_bands" or "transfer.loss_factor");
///         TransferSolveError naming the frame when a solve fails or gives a non-finite value
TransferResult computeGeometricTransfer(BubbleTrackSet tracks, const FrameWaterGrids& frames,
                                        const TransferSetup& setup,
                                        const GeometricTransferOptions& options,
                                        StageObserver& observer);

}  // namespace fluidsound::acoustics
