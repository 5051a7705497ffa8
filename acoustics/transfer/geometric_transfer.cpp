// acoustics/transfer/geometric_transfer.cpp — see geometric_transfer.h.
#include "acoustics/transfer/geometric_transfer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>

#include "acoustics/bubble/instantaneous_frequency.h"
#include "acoustics/bubble/minnaert.h"
#include "acoustics/transfer/air_column_rings.h"
#include "acoustics/transfer/air_pressures.h"
#include "acoustics/transfer/air_solves.h"
#include "acoustics/transfer/chebyshev_bands.h"
#include "acoustics/transfer/frame_samples.h"
#include "acoustics/transfer/rigid_surface_air_field.h"
#include "acoustics/transfer/water_helmholtz.h"
#include "acoustics/transfer/water_modes.h"

namespace fluidsound::acoustics {

namespace {

/// The reciprocal route takes out every water mode below kModalCut times the frame's highest
/// sample frequency, so the remainder's nearest resonance lies that far above the band range.
constexpr double kModalCut = 1.5;
/// More modes than this below the cut (a large, deep body of water): the frame takes the
/// adjoint route, exact at each sample's own frequency, instead.
constexpr int kMaxModes = 160;

double distance(const Vec3& a, const Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

/// One track sample of the frame being solved.
struct FrameSample {
  std::size_t bubble = 0, sample = 0;
  double omega = 0.0;  ///< the bubble's natural angular frequency at the sample's depth [rad/s]
  double damping = 0.0;  ///< δ = 2β/ω₀ [-], the bubble's own damping constant in free water
  PointSample stencil;
  Vec3 surfacePoint{};  ///< the point `depth` above the bubble along `up` [m]
};

void checkOptions(const GeometricTransferOptions& o) {
  if (o.maxBands < 2 || o.maxBands > kMaxTransferBands)
    throw TransferInputError(TransferInput::Options, "transfer.max_bands",
                             "an integer from 2 to " + std::to_string(kMaxTransferBands),
                             std::to_string(o.maxBands));
  if (!(o.lossFactor > 0.0 && o.lossFactor <= 0.1))
    throw TransferInputError(TransferInput::Options, "transfer.loss_factor",
                             "a number in (0, 0.1]", std::to_string(o.lossFactor));
  if (!(o.maxFrequency == 0.0 || (o.maxFrequency > 0.0 && o.maxFrequency <= kMaxTransferFrequency)))
    throw TransferInputError(TransferInput::Options, "transfer.max_frequency",
                             "0 (the grid's limit) or a frequency in (0, " +
                                 std::to_string(static_cast<int>(kMaxTransferFrequency)) + "] Hz",
                             std::to_string(o.maxFrequency));
  if (o.waveAir && !(o.waveAir->interval > 0.0 && o.waveAir->interval <= 10.0))
    throw TransferInputError(TransferInput::Options, "transfer.air_interval",
                             "a time > 0 and <= 10 s", std::to_string(o.waveAir->interval));
  if (o.waveAir && !(o.waveAir->cellSize > 0.0 && o.waveAir->cellSize <= 0.1))
    throw TransferInputError(TransferInput::Options, "transfer.air_cell",
                             "a length > 0 and <= 0.1 m", std::to_string(o.waveAir->cellSize));
  if (!(o.bandPhaseFactor > 0.0 && o.bandPhaseFactor <= 10.0))
    throw TransferInputError(TransferInput::Options, "transfer.band_phase_factor",
                             "a number in (0, 10]", std::to_string(o.bandPhaseFactor));
}

/// The flat-surface value for a sample the frame's liquid cells do not reach (a drop or a sheet
/// thinner than a cell): the image-source model under the level plane at the track's depth.
std::vector<double> levelPlaneTransfer(const Vec3& centre, double depth, double omega,
                                       const TransferSetup& setup) {
  LocalSurface level{centre, setup.up, depth};
  for (int a = 0; a < 3; ++a) level.point[a] += depth * setup.up[a];
  std::vector<double> transfer;
  for (std::size_t l = 0; l < setup.listeners.size(); ++l) {
    try {
      transfer.push_back(imageSourceTransferAmplitude(centre, level, setup.listeners[l].position,
                                                      omega, setup.liquid, setup.air));
    } catch (const std::invalid_argument& e) {
      throw TransferInputError(TransferInput::Listeners,
                               "listeners[" + std::to_string(l) + "].position",
                               "a listener away from every bubble and its surface point", e.what());
    }
  }
  return transfer;
}

/// 1/(λ_j − k_w²) of every mode for one sample: the water's modes as the bubble drives them. A
/// mode below kModalCut times the sample's own frequency is broadened by the bubble's bandwidth,
/// k_w² = (ω/c_w)²(1 − i(η + δ)); the rest, as the operator has them, (ω/c_w)²(1 − iη)
/// (docs/transfer.md, "Resonances"). The cut is the sample's own, so that both routes broaden the
/// same modes whatever else their frame holds.
Eigen::VectorXcd modalResponse(const FrameSample& sample, const Eigen::VectorXd& eigenvalues,
                               const TransferSetup& setup, double lossFactor) {
  const double c = setup.liquid.soundSpeed, cut = std::pow(kModalCut * sample.omega / c, 2);
  const Complex plain = lossyWavenumberSquared(sample.omega, c, lossFactor),
                broadened = lossyWavenumberSquared(sample.omega, c, lossFactor + sample.damping);
  Eigen::VectorXcd response(eigenvalues.size());
  for (Eigen::Index j = 0; j < eigenvalues.size(); ++j)
    response[j] = 1.0 / (eigenvalues[j] - (eigenvalues[j] < cut ? broadened : plain));
  return response;
}

/// A frame's lowest water modes as the reciprocal route uses them: Φ and MΦ for the solves
/// outside them, and each mode's value φ_j(x_s) at every sample.
struct ModalPart {
  WaterModes modes;
  ExcludedModes excluded;
  std::vector<std::vector<double>> atSample;  ///< [sample][mode]

  ModalPart(WaterModes m, const WaterHelmholtz& water, const std::vector<FrameSample>& samples)
      : modes(std::move(m)), excluded(modes.shape, water.mass()) {
    const Eigen::Index count = modes.eigenvalue.size();
    for (const FrameSample& s : samples) {
      std::vector<double> values(static_cast<std::size_t>(count), 0.0);
      for (Eigen::Index j = 0; j < count; ++j)
        for (const auto& [cell, weight] : s.stencil.cells) values[j] += weight * modes.shape(cell, j);
      atSample.push_back(std::move(values));
    }
  }
  std::size_t count() const { return static_cast<std::size_t>(modes.eigenvalue.size()); }
};

/// The reciprocal route (docs/transfer.md, "Bands and routes"): one factorisation per band, one
/// solve per band and listener for all the frame's samples. The water's resonances below the cut
/// (the frame's modes) are kept out of each band's solve, u = Σ_j φ_j (φ_jᵀb)/(λ_j − k_w²) + r
/// with b = B·p_L, and added back in closed form at each sample's own frequency. What remains,
/// r at the sample with the phase e^{−ik_a R} from the listener to the point above the bubble
/// factored out, is smooth in ω and read between Chebyshev bands by barycentric interpolation;
/// the modal numerators φ_jᵀb are read between the same bands with the phase to the liquid's
/// centre factored out.
void reciprocalRoute(BubbleTrackSet& tracks, const std::vector<FrameSample>& samples,
                     const WaterHelmholtz& water, const ModalPart& modal,
                     const ChebyshevBands& bands, const TransferSetup& setup, double lossFactor,
                     GeometricTransferStats& stats) {
  const std::size_t listeners = setup.listeners.size(), count = samples.size(),
                    modes = modal.count(), nodes = static_cast<std::size_t>(bands.count());
  const double ca = setup.air.soundSpeed;
  const Vec3 centre = water.liquidCentre();
  std::vector<double> path(listeners * count), toCentre(listeners);  // [m], listener to surface
  for (std::size_t l = 0; l < listeners; ++l) {
    toCentre[l] = distance(centre, setup.listeners[l].position);
    for (std::size_t s = 0; s < count; ++s)
      path[l * count + s] = distance(samples[s].surfacePoint, setup.listeners[l].position);
  }
  std::vector<Complex> remainder(nodes * listeners * count), numerator(nodes * listeners * modes);
  for (std::size_t q = 0; q < nodes; ++q) {
    const double omega = bands.node(static_cast<int>(q));
    const std::unique_ptr<HelmholtzFactor> factor = water.factorise(omega);
    ++stats.factorisations;
    for (std::size_t l = 0; l < listeners; ++l) {
      const Vec3& x = setup.listeners[l].position;
      const std::vector<Complex> p = airPressures(water, x, omega, setup.air);
      Eigen::VectorXcd rhs = water.rightHandSide(p);
      const Eigen::VectorXcd n = modal.excluded.deflate(rhs);
      const Eigen::VectorXcd r = factor->solveOutside(rhs, modal.excluded);
      ++stats.solves;
      const Complex centrePhase = std::polar(1.0 / omega, omega / ca * toCentre[l]);
      for (std::size_t j = 0; j < modes; ++j)
        numerator[(q * listeners + l) * modes + j] = n[static_cast<Eigen::Index>(j)] * centrePhase;
      for (std::size_t s = 0; s < count; ++s)
        remainder[(q * listeners + l) * count + s] =
            water.evaluate(samples[s].stencil, r, p) *
            std::polar(1.0 / omega, omega / ca * path[l * count + s]);
    }
  }
  std::vector<double> weights(nodes);
  for (std::size_t s = 0; s < count; ++s) {
    const double omega = samples[s].omega;
    const Eigen::VectorXcd response = modalResponse(samples[s], modal.modes.eigenvalue, setup, lossFactor);
    bands.weightsAt(omega, weights);
    std::vector<double> transfer;
    for (std::size_t l = 0; l < listeners; ++l) {
      Complex v(0.0);
      for (std::size_t q = 0; q < nodes; ++q) v += weights[q] * remainder[(q * listeners + l) * count + s];
      const Complex shift = std::polar(1.0, omega / ca * (path[l * count + s] - toCentre[l]));
      for (std::size_t j = 0; j < modes; ++j) {
        Complex n(0.0);
        for (std::size_t q = 0; q < nodes; ++q) n += weights[q] * numerator[(q * listeners + l) * modes + j];
        v += modal.atSample[s][j] * n * shift * response[static_cast<Eigen::Index>(j)];
      }
      transfer.push_back(std::abs(v) * 4.0 * std::numbers::pi / setup.liquid.density);
    }
    tracks.bubbles[samples[s].bubble].track[samples[s].sample].transfer = std::move(transfer);
  }
}

/// The adjoint solution w = K⁻¹s of one sample, with the frame's modes as the reciprocal route
/// has them: w = r + Σ_j φ_j (φ_jᵀs)·modalResponse_j, r the solve outside the modes at the loss
/// η. Without the modes (more below the frame's cut than kMaxModes) the whole operator takes the
/// loss η + δ.
Eigen::VectorXcd adjointSolution(const FrameSample& s, const WaterHelmholtz& water,
                                 const ModalPart* modal, const TransferSetup& setup,
                                 GeometricTransferStats& stats) {
  ++stats.factorisations;
  ++stats.solves;
  if (!modal) return water.factorise(s.omega, HelmholtzMethod::Fast, s.damping)->adjoint(s.stencil);
  Eigen::VectorXcd source = water.pointSource(s.stencil);
  const Eigen::VectorXcd n = modal->excluded.deflate(source);
  Eigen::VectorXcd w = water.factorise(s.omega)->solveOutside(source, modal->excluded);
  w += modal->excluded.shapes *
       n.cwiseProduct(modalResponse(s, modal->modes.eigenvalue, setup, water.lossFactor()));
  return w;
}

/// The adjoint route: per sample one factorisation at its own frequency and one solve, whose
/// surface weights give every listener's value.
void adjointRoute(BubbleTrackSet& tracks, const std::vector<FrameSample>& samples,
                  const WaterHelmholtz& water, const ModalPart* modal, const TransferSetup& setup,
                  const FrameAirFields& air, GeometricTransferStats& stats) {
  for (const FrameSample& s : samples) {
    const std::vector<Complex> weights =
        water.airWeights(s.stencil, adjointSolution(s, water, modal, setup, stats));
    std::vector<double> transfer;
    for (std::size_t l = 0; l < setup.listeners.size(); ++l) {
      const std::vector<Complex> p = airPressures(water, setup.listeners[l].position, s.omega,
                                                  setup.air, air.empty() ? nullptr : air[l]);
      Complex u(0.0);
      for (std::size_t a = 0; a < p.size(); ++a) u += weights[a] * p[a];
      transfer.push_back(transferFromReciprocalPressure(u, s.omega, setup.liquid));
    }
    tracks.bubbles[s.bubble].track[s.sample].transfer = std::move(transfer);
  }
}

/// The spread [m] of path lengths from any listener to the frame's open surface: the air phase
/// e^{−ik_a R} varies across the surface by k_a times it.
double pathSpread(const WaterHelmholtz& water, const TransferSetup& setup) {
  double spread = 0.0;
  for (const TransferListener& listener : setup.listeners) {
    double lo = std::numeric_limits<double>::max(), hi = 0.0;
    for (const AirPoint& point : water.airPoints()) {
      if (point.enclosed) continue;
      const double r = distance(point.position, listener.position);
      lo = std::min(lo, r), hi = std::max(hi, r);
    }
    if (hi >= lo) spread = std::max(spread, hi - lo);
  }
  return spread;
}

/// Chebyshev bands over [ω_lo, ω_hi]. With the resonances below kModalCut·ω_hi taken out, the
/// remainder is e^{iτx}-like on x ∈ [−1, 1], τ = (ω_hi − ω_lo)·spread/(2c_a) the half-range's
/// phase spread across the surface, times a function whose nearest pole lies at x ≥ 2 (ρ ≥
/// 2 + √3). Chebyshev coefficients of e^{iτx} are Bessel values J_n(τ), below 10⁻⁷ for n ≥ 1.5τ + 12;
/// those of the pole part fall as ρ⁻ⁿ, 10⁻⁷ at n = 12 (Trefethen, ATAP, Thm 8.2).
int chebyshevBandCount(double lo, double hi, double spread, const TransferSetup& setup,
                       const GeometricTransferOptions& options, bool& widened) {
  if (!(hi > lo)) return 1;
  const double tau = (hi - lo) * spread / (2.0 * setup.air.soundSpeed);
  const double wanted = std::ceil(options.bandPhaseFactor * tau + 12.0);
  widened = wanted > options.maxBands;
  return widened ? options.maxBands : static_cast<int>(wanted);
}

GeometricTransferStats transferOfFrame(BubbleTrackSet& tracks, int frame,
                                       const FrameSamples& work, const FrameWaterGrids& grids,
                                       const TransferSetup& setup,
                                       const GeometricTransferOptions& options,
                                       const FrameAirFields& air) {
  const auto start = std::chrono::steady_clock::now();
  GeometricTransferStats stats;
  const WaterHelmholtz water(grids.open(frame), setup.liquid.soundSpeed, options.lossFactor);
  stats.maxUnknowns = water.unknowns();
  for (std::size_t l = 0; l < setup.listeners.size(); ++l)
    if (water.inLiquid(setup.listeners[l].position))
      throw TransferInputError(TransferInput::Listeners,
                               "listeners[" + std::to_string(l) + "].position",
                               "a listener in air for the geometric model (--transfer image "
                               "hears a listener in water)",
                               "a point in frame " + std::to_string(frame) + "'s liquid");
  const double limitHz = options.maxFrequency > 0.0
                             ? options.maxFrequency
                             : setup.air.soundSpeed / (4.0 * water.cellSize());
  std::vector<FrameSample> samples;
  for (const auto& [b, s] : work) {
    const Vec3& position = samplePosition(tracks, b, s);
    TrackSample& sample = tracks.bubbles[b].track[s];
    const double pressure = ambientPressureAt(sample.depth, setup.liquid, setup.model);
    const double omega =
        naturalAngularFrequency(tracks.bubbles[b].radius, pressure, setup.liquid, setup.model);
    stats.maxFrequency = std::max(stats.maxFrequency, omega / (2.0 * std::numbers::pi));
    if (omega > 2.0 * std::numbers::pi * limitHz) {
      sample.transfer = levelPlaneTransfer(position, sample.depth, omega, setup);
      ++stats.samplesAboveLimit;
      continue;
    }
    PointSample stencil = water.sampleAt(position);
    if (stencil.cells.empty()) {
      sample.transfer = levelPlaneTransfer(position, sample.depth, omega, setup);
      ++stats.samplesOutsideLiquid;
      continue;
    }
    Vec3 above = position;
    for (int a = 0; a < 3; ++a) above[a] += sample.depth * setup.up[a];
    const double damping =
        ringingBubble(tracks.bubbles[b], setup.liquid, setup.model).deep.dampingConstant;
    samples.push_back({b, s, omega, damping, std::move(stencil), above});
  }
  // Samples the air side's wave solve answers take the adjoint route, exact at their own
  // frequency: the air column's resonances are narrower than the bands.
  std::vector<FrameSample> airSamples;
  if (!air.empty()) {
    const double limit = 2.0 * std::numbers::pi * air.front()->maxFrequency();
    const auto solved = std::stable_partition(samples.begin(), samples.end(),
                                              [&](const FrameSample& s) { return s.omega > limit; });
    airSamples.assign(std::make_move_iterator(solved), std::make_move_iterator(samples.end()));
    samples.erase(solved, samples.end());
  }
  try {
    std::optional<ModalPart> modal;
    if (!samples.empty() || !airSamples.empty()) {
      double hi = 0.0;
      for (const auto* list : {&samples, &airSamples})
        for (const FrameSample& s : *list) hi = std::max(hi, s.omega);
      const double cut = kModalCut * hi / setup.liquid.soundSpeed;
      WaterModes modes = lowestWaterModes(water, cut * cut, kMaxModes);
      ++stats.factorisations;
      stats.solves += static_cast<std::size_t>(modes.operations);
      if (modes.complete) {
        modal.emplace(std::move(modes), water, samples);
        stats.modes += modal->count();
      } else {
        ++stats.modeLimitedFrames;
      }
    }
    if (!air.empty()) addAirColumnRings(tracks, work, water, setup, air, stats);
    if (!airSamples.empty()) {
      adjointRoute(tracks, airSamples, water, modal ? &*modal : nullptr, setup, air, stats);
      stats.airSamples += airSamples.size();
    }
    if (!samples.empty()) {
      double lo = samples.front().omega, hi = lo;
      for (const FrameSample& s : samples) lo = std::min(lo, s.omega), hi = std::max(hi, s.omega);
      bool widened = false;
      const int bands =
          chebyshevBandCount(lo, hi, pathSpread(water, setup), setup, options, widened);
      if (modal && static_cast<std::size_t>(bands) < samples.size()) {
        reciprocalRoute(tracks, samples, water, *modal, ChebyshevBands(lo, hi, bands), setup,
                        options.lossFactor, stats);
        ++stats.reciprocalFrames;
        stats.bands += bands;
        stats.widenedFrames += widened ? 1 : 0;
      } else {
        adjointRoute(tracks, samples, water, modal ? &*modal : nullptr, setup, {}, stats);
        ++stats.adjointFrames;
      }
    }
  } catch (const std::runtime_error& e) {
    throw TransferSolveError(frame, e.what());
  }
  stats.solveSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

void addStats(GeometricTransferStats& total, const GeometricTransferStats& frame) {
  total.reciprocalFrames += frame.reciprocalFrames;
  total.adjointFrames += frame.adjointFrames;
  total.widenedFrames += frame.widenedFrames;
  total.modeLimitedFrames += frame.modeLimitedFrames;
  total.modes += frame.modes;
  total.bands += frame.bands;
  total.factorisations += frame.factorisations;
  total.solves += frame.solves;
  total.maxUnknowns = std::max(total.maxUnknowns, frame.maxUnknowns);
  total.maxFrequency = std::max(total.maxFrequency, frame.maxFrequency);
  total.samplesOutsideLiquid += frame.samplesOutsideLiquid;
  total.samplesAboveLimit += frame.samplesAboveLimit;
  total.airSamples += frame.airSamples;
  total.rings += frame.rings;
  total.solveSeconds += frame.solveSeconds;
}

}  // namespace

TransferResult computeGeometricTransfer(BubbleTrackSet tracks, const FrameWaterGrids& frames,
                                        const TransferSetup& setup,
                                        const GeometricTransferOptions& options,
                                        StageObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  checkOptions(options);
  for (BubbleTrack& b : tracks.bubbles) b.rings.clear();  // an earlier run's; this one sets its own
  const std::vector<std::pair<int, FrameSamples>> work = samplesByFrame(tracks, setup);
  std::vector<GeometricTransferStats> frameStats(work.size());
  const AirSolves air = options.waveAir ? AirSolves(work, frames, setup, *options.waveAir) : AirSolves();
  forEachFrameInChunks(work, observer, [&](std::size_t f) {
    frameStats[f] = transferOfFrame(tracks, work[f].first, work[f].second, frames, setup, options,
                                    air.forFrame(work[f].first));
  });
  TransferResult result;
  result.geometric.airSolves = air.count();
  result.geometric.airSeconds = air.seconds();
  result.geometric.airBytes = air.bytes();
  for (const GeometricTransferStats& s : frameStats) addStats(result.geometric, s);
  result.bubbles = tracks.bubbles.size();
  for (const auto& frame : work) result.samples += frame.second.size();
  result.framesRead = work.size();
  result.tracks = std::move(tracks);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace fluidsound::acoustics
