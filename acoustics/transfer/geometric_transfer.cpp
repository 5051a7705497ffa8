// acoustics/transfer/geometric_transfer.cpp — see geometric_transfer.h.
#include "acoustics/transfer/geometric_transfer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "acoustics/bubble/minnaert.h"
#include "acoustics/transfer/frame_samples.h"
#include "acoustics/transfer/rigid_surface_air_field.h"
#include "acoustics/transfer/water_helmholtz.h"

namespace fluidsound::acoustics {

namespace {

/// One track sample of the frame being solved.
struct FrameSample {
  std::size_t bubble = 0, sample = 0;
  double omega = 0.0;  ///< the bubble's natural angular frequency at the sample's depth [rad/s]
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
  if (!(o.bandSpacingFactor > 0.0 && o.bandSpacingFactor <= 10.0))
    throw TransferInputError(TransferInput::Options, "transfer.band_spacing_factor",
                             "a number in (0, 10]", std::to_string(o.bandSpacingFactor));
}

/// p_L at every air point of the frame for one listener and frequency.
std::vector<Complex> airPressures(const WaterHelmholtz& water, const Vec3& listener, double omega,
                                  const AirProperties& air) {
  std::vector<Complex> p;
  p.reserve(water.airPoints().size());
  for (const AirPoint& point : water.airPoints())
    p.push_back(rigidSurfaceAirPressure(point.position, listener, omega, air));
  return p;
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

/// The reciprocal route: one factorisation per band, one solve per band and listener; each
/// sample interpolates between the two bands around its frequency, with the phase e^{−ik_a R}
/// from the listener to the point above the bubble factored out (shared transfer.md §2 factors
/// out the phase to the liquid's centre; the bubble's own surface point leaves only the phase
/// differences across the surface near it, which vary slower with frequency).
void reciprocalRoute(BubbleTrackSet& tracks, const std::vector<FrameSample>& samples,
                     const WaterHelmholtz& water, const TransferSetup& setup, int bands,
                     GeometricTransferStats& stats) {
  double lo = samples.front().omega, hi = lo;
  for (const FrameSample& s : samples) lo = std::min(lo, s.omega), hi = std::max(hi, s.omega);
  const std::size_t listeners = setup.listeners.size(), count = samples.size();
  const double step = bands > 1 ? (hi - lo) / (bands - 1) : 0.0;
  std::vector<Complex> values(static_cast<std::size_t>(bands) * listeners * count);
  for (int j = 0; j < bands; ++j) {
    const double omega = lo + j * step;
    const std::unique_ptr<HelmholtzFactor> factor = water.factorise(omega);
    ++stats.factorisations;
    for (std::size_t l = 0; l < listeners; ++l) {
      const Vec3& x = setup.listeners[l].position;
      const std::vector<Complex> p = airPressures(water, x, omega, setup.air);
      const Eigen::VectorXcd u = factor->solve(water.rightHandSide(p));
      ++stats.solves;
      const double ka = omega / setup.air.soundSpeed;
      for (std::size_t s = 0; s < count; ++s) {
        const Vec3& y = samples[s].surfacePoint;
        const double r = std::hypot(y[0] - x[0], y[1] - x[1], y[2] - x[2]);
        values[(j * listeners + l) * count + s] =
            water.evaluate(samples[s].stencil, u, p) * std::polar(1.0 / omega, ka * r);
      }
    }
  }
  for (std::size_t s = 0; s < count; ++s) {
    const double x = step > 0.0 ? (samples[s].omega - lo) / step : 0.0;
    const int j0 = bands > 1 ? std::clamp(static_cast<int>(std::floor(x)), 0, bands - 2) : 0;
    const double t = bands > 1 ? x - j0 : 0.0;
    std::vector<double> transfer;
    for (std::size_t l = 0; l < listeners; ++l) {
      Complex v = values[(j0 * listeners + l) * count + s];
      if (bands > 1) v = (1.0 - t) * v + t * values[((j0 + 1) * listeners + l) * count + s];
      transfer.push_back(std::abs(v) * 4.0 * std::numbers::pi / setup.liquid.density);
    }
    tracks.bubbles[samples[s].bubble].track[samples[s].sample].transfer = std::move(transfer);
  }
}

/// The adjoint route: per sample one factorisation at its own frequency and one solve, whose
/// surface weights give every listener's value.
void adjointRoute(BubbleTrackSet& tracks, const std::vector<FrameSample>& samples,
                  const WaterHelmholtz& water, const TransferSetup& setup,
                  GeometricTransferStats& stats) {
  for (const FrameSample& s : samples) {
    const std::unique_ptr<HelmholtzFactor> factor = water.factorise(s.omega);
    ++stats.factorisations;
    ++stats.solves;
    const std::vector<Complex> weights = water.airWeights(s.stencil, factor->adjoint(s.stencil));
    std::vector<double> transfer;
    for (const TransferListener& listener : setup.listeners) {
      const std::vector<Complex> p = airPressures(water, listener.position, s.omega, setup.air);
      Complex u(0.0);
      for (std::size_t a = 0; a < p.size(); ++a) u += weights[a] * p[a];
      transfer.push_back(transferFromReciprocalPressure(u, s.omega, setup.liquid));
    }
    tracks.bubbles[s.bubble].track[s.sample].transfer = std::move(transfer);
  }
}

/// Bands for the frame's liquid and frequency range (shared transfer.md §2).
int bandCount(double lo, double hi, double liquidSize, const TransferSetup& setup,
              const GeometricTransferOptions& options, bool& widened) {
  if (!(hi > lo) || !(liquidSize > 0.0)) return 1;
  const double spacing = options.bandSpacingFactor * setup.air.soundSpeed / liquidSize;  // [rad/s]
  const double wanted = std::ceil((hi - lo) / spacing) + 1.0;
  widened = wanted > options.maxBands;
  return widened ? options.maxBands : std::max(2, static_cast<int>(wanted));
}

GeometricTransferStats transferOfFrame(BubbleTrackSet& tracks, int frame,
                                       const FrameSamples& work, const FrameWaterGrids& grids,
                                       const TransferSetup& setup,
                                       const GeometricTransferOptions& options) {
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
    samples.push_back({b, s, omega, std::move(stencil), above});
  }
  try {
    if (!samples.empty()) {
      double lo = samples.front().omega, hi = lo;
      for (const FrameSample& s : samples) lo = std::min(lo, s.omega), hi = std::max(hi, s.omega);
      bool widened = false;
      const int bands = bandCount(lo, hi, water.liquidSize(), setup, options, widened);
      if (static_cast<std::size_t>(bands) < samples.size()) {
        reciprocalRoute(tracks, samples, water, setup, bands, stats);
        ++stats.reciprocalFrames;
        stats.bands += bands;
        stats.widenedFrames += widened ? 1 : 0;
      } else {
        adjointRoute(tracks, samples, water, setup, stats);
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
  total.bands += frame.bands;
  total.factorisations += frame.factorisations;
  total.solves += frame.solves;
  total.maxUnknowns = std::max(total.maxUnknowns, frame.maxUnknowns);
  total.maxFrequency = std::max(total.maxFrequency, frame.maxFrequency);
  total.samplesOutsideLiquid += frame.samplesOutsideLiquid;
  total.samplesAboveLimit += frame.samplesAboveLimit;
  total.solveSeconds += frame.solveSeconds;
}

}  // namespace

TransferResult computeGeometricTransfer(BubbleTrackSet tracks, const FrameWaterGrids& frames,
                                        const TransferSetup& setup,
                                        const GeometricTransferOptions& options,
                                        StageObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  checkOptions(options);
  const std::vector<std::pair<int, FrameSamples>> work = samplesByFrame(tracks, setup);
  std::vector<GeometricTransferStats> frameStats(work.size());
  forEachFrameInChunks(work, observer, [&](std::size_t f) {
    frameStats[f] = transferOfFrame(tracks, work[f].first, work[f].second, frames, setup, options);
  });
  TransferResult result;
  for (const GeometricTransferStats& s : frameStats) addStats(result.geometric, s);
  result.bubbles = tracks.bubbles.size();
  for (const auto& frame : work) result.samples += frame.second.size();
  result.framesRead = work.size();
  result.tracks = std::move(tracks);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace fluidsound::acoustics
