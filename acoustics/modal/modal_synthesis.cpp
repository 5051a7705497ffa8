// acoustics/modal/modal_synthesis.cpp — see modal_synthesis.h.
#include "acoustics/modal/modal_synthesis.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "acoustics/modal/hertz_contact.h"

namespace fluidsound::acoustics {
namespace {

/// Samples between two truncation checks: short beside any mode's decay time at 48 kHz (the
/// fastest audible decay, wood at 20 kHz, loses 0.5 % of its amplitude in 256 samples).
constexpr std::size_t kCheckSamples = 256;

/// The complex amplitude A that a mode's state gets from an impact: q = Im(A·e^{(−d+iω_d)(t − t₀)})
/// with t₀ the pulse's centre, A real.
double impactAmplitude(const ModalModel& model, std::size_t mode, double modalImpulse, double contactDuration) {
  const double omegaD = 2.0 * std::numbers::pi * model.dampedFrequency[mode];
  if (!(omegaD > 0.0)) return 0.0;  // critically damped or more: no ring
  const double omega = 2.0 * std::numbers::pi * model.frequency[mode];
  const double pulse = contactDuration > 0.0 ? halfSinePulseFactor(omega, contactDuration) : 1.0;
  return modalImpulse * pulse / omegaD;
}

}  // namespace

Eigen::VectorXd modalImpulses(const ModalModel& model, const ModalImpact& impact) {
  if (impact.surfaceNode >= model.surfaceNodes.size())
    throw std::invalid_argument("modalImpulses: surface node out of range");
  const auto row = static_cast<Eigen::Index>(3 * impact.surfaceNode);
  return model.surfaceShapes.middleRows(row, 3).cast<double>().transpose() * impact.impulse;
}

double modalDisplacement(const ModalModel& model, std::size_t mode, const ModalImpact& impact, double time) {
  const double centre = impact.time + 0.5 * impact.contactDuration;
  if (time < centre) return 0.0;
  const double amplitude =
      impactAmplitude(model, mode, modalImpulses(model, impact)[static_cast<Eigen::Index>(mode)], impact.contactDuration);
  const double t = time - centre;
  return amplitude * std::exp(-model.decayRate[mode] * t) * std::sin(2.0 * std::numbers::pi * model.dampedFrequency[mode] * t);
}

std::vector<float> synthesizeModalImpacts(const ModalModel& model, std::span<const ModalImpact> impacts,
                                          std::span<const std::complex<double>> gains, std::size_t samples,
                                          double delay, const ModalSynthesisSettings& settings,
                                          ModalSynthesisStatistics* statistics) {
  const std::size_t modes = model.frequency.size();
  if (gains.size() != modes) throw std::invalid_argument("synthesizeModalImpacts: one gain per mode");
  if (!(settings.sampleRate > 0.0) || !(delay >= 0.0) || !(settings.truncation >= 0.0))
    throw std::invalid_argument("synthesizeModalImpacts: sample rate > 0, delay and truncation >= 0");
  if (settings.compression && settings.compression->group.size() != modes)
    throw std::invalid_argument("synthesizeModalImpacts: the compression's groups do not cover the modes");
  const double dt = 1.0 / settings.sampleRate;

  // The oscillators: one per group (its lead's frequency and decay), or one per mode.
  std::vector<std::size_t> voiceOf(modes), lead;
  for (std::size_t j = 0; j < modes; ++j) voiceOf[j] = settings.compression ? settings.compression->group[j] : j;
  if (settings.compression) {
    lead = settings.compression->first;
  } else {
    lead.resize(modes);
    for (std::size_t j = 0; j < modes; ++j) lead[j] = j;
  }
  const std::size_t voices = lead.size();
  const auto rotor = [&](std::size_t v) {
    return std::complex<double>(-model.decayRate[lead[v]], 2.0 * std::numbers::pi * model.dampedFrequency[lead[v]]);
  };

  // Impacts in time order (stable: equal times keep their given order), each at its pulse centre.
  std::vector<std::size_t> order(impacts.size());
  for (std::size_t e = 0; e < order.size(); ++e) order[e] = e;
  const auto centre = [&](std::size_t e) { return impacts[e].time + 0.5 * impacts[e].contactDuration + delay; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return centre(a) < centre(b); });

  // State z_v with the gain folded in: the output is Im z_v.
  std::vector<std::complex<double>> state(voices), step(voices), coherent(voices);
  std::vector<double> energy(voices), floor(voices, 0.0);
  std::vector<char> active(voices, 0);
  for (std::size_t v = 0; v < voices; ++v) step[v] = std::exp(rotor(v) * dt);

  std::vector<float> out(samples, 0.0f);
  ModalSynthesisStatistics stats;
  std::size_t next = 0;  // the next impact in `order`
  for (std::size_t start = 0; start < samples;) {
    // Impacts whose centre is at or before this sample join the states exactly at it.
    while (next < order.size() && centre(order[next]) <= static_cast<double>(start) * dt) {
      const ModalImpact& impact = impacts[order[next]];
      const Eigen::VectorXd impulse = modalImpulses(model, impact);
      std::fill(coherent.begin(), coherent.end(), 0.0);
      std::fill(energy.begin(), energy.end(), 0.0);
      for (std::size_t j = 0; j < modes; ++j) {
        const std::complex<double> c =
            gains[j] * impactAmplitude(model, j, impulse[static_cast<Eigen::Index>(j)], impact.contactDuration);
        coherent[voiceOf[j]] += c;
        energy[voiceOf[j]] += std::norm(c);
      }
      const double since = static_cast<double>(start) * dt - centre(order[next]);
      // The event's peak: its loudest oscillator. Quieter than truncation × peak, an oscillator
      // is not excited by it; one it excites stops below truncation × the loudest event's peak.
      double peak = 0.0;
      for (double e : energy) peak = std::max(peak, e);
      const double eventFloor = settings.truncation * std::sqrt(peak);
      for (std::size_t v = 0; v < voices; ++v) {
        if (energy[v] == 0.0) continue;
        const double size = std::sqrt(energy[v]);  // = |coherent| for a group of one
        if (size < eventFloor) {
          ++stats.modesSkipped;
          continue;
        }
        const std::complex<double> phase = std::abs(coherent[v]) > 0.0 ? coherent[v] / std::abs(coherent[v]) : 1.0;
        state[v] += size * phase * std::exp(rotor(v) * since);
        floor[v] = std::max(floor[v], eventFloor);
        active[v] = 1;
      }
      ++next;
    }
    // Up to the next impact or check, whichever is first.
    std::size_t end = std::min(samples, start + kCheckSamples);
    if (next < order.size())
      end = std::min(end, std::max(start + 1, static_cast<std::size_t>(std::ceil(centre(order[next]) / dt))));
    for (std::size_t v = 0; v < voices; ++v) {
      if (!active[v]) continue;
      std::complex<double> z = state[v];
      const std::complex<double> r = step[v];
      for (std::size_t n = start; n < end; ++n) {
        out[n] += static_cast<float>(z.imag());
        z *= r;
      }
      state[v] = z;
      stats.oscillatorSamples += end - start;
      if (std::abs(z) < floor[v]) {  // below the floor: silent from here
        state[v] = 0.0;
        active[v] = 0;
        floor[v] = 0.0;
        ++stats.modesTruncated;
      }
    }
    start = end;
  }
  if (statistics) *statistics = stats;
  return out;
}

std::vector<float> synthesizeModalForces(const ModalModel& model, std::span<const ModalForce> forces,
                                         std::span<const std::complex<double>> gains, std::size_t samples,
                                         double delay, const ModalSynthesisSettings& settings) {
  const std::size_t modes = model.frequency.size();
  if (gains.size() != modes) throw std::invalid_argument("synthesizeModalForces: one gain per mode");
  if (!(settings.sampleRate > 0.0) || !(delay >= 0.0))
    throw std::invalid_argument("synthesizeModalForces: sample rate > 0 and delay >= 0");
  const double dt = 1.0 / settings.sampleRate;
  for (const ModalForce& force : forces) {
    if (force.surfaceNodes.size() != 1 && force.surfaceNodes.size() != force.force.size())
      throw std::invalid_argument("synthesizeModalForces: one surface node, or one per force sample");
    for (std::size_t node : force.surfaceNodes)
      if (node >= model.surfaceNodes.size()) throw std::invalid_argument("synthesizeModalForces: surface node out of range");
  }
  std::vector<float> out(samples, 0.0f);
  std::vector<double> drive(samples);  // mode j's force at each output sample, all forces summed: φ_j(x_n)·F_n
  for (std::size_t j = 0; j < modes; ++j) {
    const double omegaD = 2.0 * std::numbers::pi * model.dampedFrequency[j];
    if (!(omegaD > 0.0)) continue;
    std::fill(drive.begin(), drive.end(), 0.0);
    long long first = static_cast<long long>(samples);  // the earliest driven sample
    long long last = -1;                                // the latest
    for (const ModalForce& force : forces) {
      const auto start = static_cast<long long>(std::llround((force.startTime + delay) * settings.sampleRate));
      for (std::size_t i = 0; i < force.force.size(); ++i) {
        const long long n = start + static_cast<long long>(i);
        if (n < 0) continue;
        if (n >= static_cast<long long>(samples)) break;
        const std::size_t node = force.surfaceNodes[force.surfaceNodes.size() == 1 ? 0 : i];
        const Eigen::Vector3f shape =
            model.surfaceShapes.block<3, 1>(static_cast<Eigen::Index>(3 * node), static_cast<Eigen::Index>(j));
        drive[static_cast<std::size_t>(n)] += static_cast<double>(shape.dot(force.force[i]));
        first = std::min(first, n);
        last = std::max(last, n);
      }
    }
    const std::complex<double> s(-model.decayRate[j], omegaD), r = std::exp(s * dt);
    const std::complex<double> step = gains[j] * (r - 1.0) / (s * omegaD);  // the gain folded in
    std::complex<double> z = 0.0;
    // One pass per mode, driven by every force, ringing out after the last until its output
    // falls below `truncation` of its largest while driven (checked every 64 samples).
    double peak = 0.0;
    for (std::size_t n = static_cast<std::size_t>(first); n < samples; ++n) {
      out[n] += static_cast<float>(z.imag());
      z = z * r + step * drive[n];
      const double size = std::norm(z);
      if (static_cast<long long>(n) <= last) {
        peak = std::max(peak, size);
      } else if (settings.truncation > 0.0 && n % 64 == 0 &&
                 size < settings.truncation * settings.truncation * peak) {
        break;
      }
    }
  }
  return out;
}

}  // namespace fluidsound::acoustics
