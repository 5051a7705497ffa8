// acoustics/transfer/air_solves.cpp — see air_solves.h.
#include "acoustics/transfer/air_solves.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace fluidsound::acoustics {

AirSolves::AirSolves(const std::vector<std::pair<int, FrameSamples>>& work,
                     const FrameWaterGrids& grids, const TransferSetup& setup,
                     const WaveAirOptions& options)
    : fps_(setup.fps), interval_(options.interval) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<int> indices;
  for (const auto& [frame, samples] : work) indices.push_back(indexOf(frame));
  std::sort(indices.begin(), indices.end());
  indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
  const std::size_t listeners = setup.listeners.size();
  std::vector<std::unique_ptr<WaveAirField>> fields(indices.size() * listeners);
  tbb::parallel_for(std::size_t{0}, fields.size(), [&](std::size_t n) {
    const int index = indices[n / listeners];
    const int frame =
        std::clamp(static_cast<int>(std::lround(index * interval_ * fps_)), 0, setup.lastFrame);
    fields[n] = std::make_unique<WaveAirField>(
        grids.open(frame), setup.listeners[n % listeners].position, setup.air, options);
  });
  for (std::size_t i = 0; i < indices.size(); ++i) {
    FrameAirFields& entry = byIndex_[indices[i]];
    for (std::size_t l = 0; l < listeners; ++l) entry.push_back(fields[i * listeners + l].get());
  }
  fields_ = std::move(fields);
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::size_t AirSolves::bytes() const {
  std::size_t total = 0;
  for (const auto& field : fields_) total += field->bytes();
  return total;
}

const FrameAirFields& AirSolves::forFrame(int frame) const {
  const auto found = byIndex_.find(indexOf(frame));
  return found == byIndex_.end() ? none_ : found->second;
}

int AirSolves::indexOf(int frame) const {
  return interval_ > 0.0 ? static_cast<int>(std::lround(frame / fps_ / interval_)) : 0;
}

}  // namespace fluidsound::acoustics
