// acoustics/transfer/air_column_rings.h — the geometric transfer's part of the air column's ring
// (docs/transfer.md, "The air column's ring"): for a frame whose air solves found resonances, the
// free ring each bubble born in the frame leaves in each (resonator_ring.h).
#pragma once

#include "acoustics/bubble/bubble_track.h"
#include "acoustics/transfer/air_solves.h"
#include "acoustics/transfer/frame_samples.h"
#include "acoustics/transfer/transfer_stage.h"
#include "acoustics/transfer/water_helmholtz.h"

namespace fluidsound::acoustics {

/// @brief Gives every bubble whose birth sample is among `work` a ResonatorRing per resonance of
///        the frame's air solves (those of the listener whose solve found the strongest, up to
///        kMaxResonances). Per resonance Ω, β_r: one factorisation at Ω and one solve per listener
///        with p_L the wave field minus the rigid-surface field, read at each birth sample as
///        T_res; the residue R = β_r·T_res and the bubble's ω, β at birth give ringAmplitude.
///        Adds the factorisations, solves and rings to `stats`.
void addAirColumnRings(BubbleTrackSet& tracks, const FrameSamples& work, const WaterHelmholtz& water,
                       const TransferSetup& setup, const FrameAirFields& air, GeometricTransferStats& stats);

}  // namespace fluidsound::acoustics
