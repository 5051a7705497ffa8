// acoustics/transfer/resonator_ring.h — the free ring a bubble leaves in a resonator on its way to
// a listener (a vessel's air column). The transfer weights a bubble at its own frequency, the
// forced part of the listener's sound; a resonant transfer T(s) ≈ R/(s − p) + R*/(s − p*) near
// its pole p = −β_r + iΩ also answers the bubble's onset at Ω: by the residue theorem the
// listener's sound holds 2 Re[R·S(p)·e^{pτ}], S(s) = A ω_b/((s + β_b)² + ω_b²) the Laplace
// transform of the bubble's A e^{−β_b τ} sin ω_b τ (docs/transfer.md, "The air column's ring").
#pragma once

#include <complex>

namespace fluidsound::acoustics {

/// @brief 2 R S(p)/A: the ring's complex amplitude per unit bubble amplitude, the ring being
///        A·Re[value·e^{pτ}]. R the transfer's residue at p (R = β_r·T_res, T_res the resonant
///        part of the transfer at ω = Ω), `bubbleAngularFrequency` ω_b [rad/s], `bubbleDecayRate`
///        β_b [1/s].
std::complex<double> ringAmplitude(std::complex<double> residue, std::complex<double> pole,
                                   double bubbleAngularFrequency, double bubbleDecayRate);

}  // namespace fluidsound::acoustics
