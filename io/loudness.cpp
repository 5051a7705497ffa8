// io/loudness.cpp — BS.1770 loudness through libebur128 (see loudness.h).
#include "io/loudness.h"

#include <ebur128.h>
#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>
#include <new>
#include <stdexcept>

namespace fluidsound::io {
namespace {

/// Frames handed to libebur128 per call by measureLoudness: bounds its interleaved scratch.
constexpr std::size_t kBlockFrames = 8192;

double decibels(double amplitude) {
  return amplitude > 0 ? 20.0 * std::log10(amplitude) : -std::numeric_limits<double>::infinity();
}

}  // namespace

/// One libebur128 meter, destroyed with its owner.
struct Ebur128Meter {
  ebur128_state* state = nullptr;
  Ebur128Meter(std::size_t channels, double sampleRate, int mode)
      : state(ebur128_init(static_cast<unsigned>(channels), static_cast<unsigned long>(sampleRate),
                           mode)) {
    if (state == nullptr) throw std::bad_alloc();
  }
  ~Ebur128Meter() { ebur128_destroy(&state); }
  Ebur128Meter(const Ebur128Meter&) = delete;
  Ebur128Meter& operator=(const Ebur128Meter&) = delete;
  void add(const float* frames, std::size_t count) {
    if (ebur128_add_frames_float(state, frames, count) != EBUR128_SUCCESS)
      throw std::bad_alloc();  // its only failure: no memory for the block history
  }
};

/// The integrated loudness needs all channels in one meter; the true peak (4× oversampling, five
/// times the cost of the loudness) is per channel, so each channel has its own mono meter and
/// they run in parallel. Every meter sees the same samples in the same order whatever the
/// thread count, so the measurement is the same bits.
struct LoudnessMeter::State {
  std::unique_ptr<Ebur128Meter> loudness;
  std::vector<std::unique_ptr<Ebur128Meter>> truePeaks;  ///< one per channel
};

LoudnessMeter::LoudnessMeter(std::size_t channels, double sampleRate)
    : state_(std::make_unique<State>()), channels_(channels) {
  if (channels == 0 || channels > UINT_MAX)
    throw std::invalid_argument("loudness meter: expected at least one channel");
  if (!(sampleRate >= 1 && sampleRate <= INT_MAX) || sampleRate != std::floor(sampleRate))
    throw std::invalid_argument("loudness meter: expected a whole sample rate in Hz, found " +
                                std::to_string(sampleRate));
  state_->loudness = std::make_unique<Ebur128Meter>(channels, sampleRate, EBUR128_MODE_I);
  // libebur128's default map leaves channel 3 out (LFE) and weights 4 and 5 as surrounds.
  for (std::size_t c = 0; c < channels; ++c)
    ebur128_set_channel(state_->loudness->state, static_cast<unsigned>(c), EBUR128_CENTER);
  for (std::size_t c = 0; c < channels; ++c)
    state_->truePeaks.push_back(
        std::make_unique<Ebur128Meter>(1, sampleRate, EBUR128_MODE_TRUE_PEAK));
}

LoudnessMeter::~LoudnessMeter() = default;

void LoudnessMeter::addInterleaved(std::span<const float> interleaved) {
  if (interleaved.size() % channels_ != 0)
    throw std::invalid_argument("loudness meter: samples are not a whole number of frames");
  const std::size_t frames = interleaved.size() / channels_;
  // Task c < channels: channel c's true peak; task `channels`: the loudness of all of them.
  tbb::parallel_for(std::size_t{0}, channels_ + 1, [&](std::size_t task) {
    if (task == channels_) {
      state_->loudness->add(interleaved.data(), frames);
      return;
    }
    std::vector<float> channel(frames);
    for (std::size_t i = 0; i < frames; ++i) channel[i] = interleaved[i * channels_ + task];
    state_->truePeaks[task]->add(channel.data(), frames);
  });
}

LoudnessMeasurement LoudnessMeter::measurement() const {
  LoudnessMeasurement m;
  double lufs = 0.0;
  // ebur128 reports −HUGE_VAL when no block passes the gates.
  if (ebur128_loudness_global(state_->loudness->state, &lufs) == EBUR128_SUCCESS &&
      std::isfinite(lufs))
    m.integratedLufs = lufs;
  double peak = 0.0;
  for (std::size_t c = 0; c < channels_; ++c) {
    double channelPeak = 0.0;
    ebur128_true_peak(state_->truePeaks[c]->state, 0, &channelPeak);
    peak = std::max(peak, channelPeak);
  }
  m.truePeakDbtp = decibels(peak);
  return m;
}

LoudnessMeasurement measureLoudness(std::span<const std::vector<float>> channels, double sampleRate,
                                    double gain) {
  if (channels.empty()) throw std::invalid_argument("loudness: no channels");
  const std::size_t frames = channels.front().size();
  for (const std::vector<float>& channel : channels)
    if (channel.size() != frames)
      throw std::invalid_argument("loudness: channels of unequal length");
  LoudnessMeter meter(channels.size(), sampleRate);
  std::vector<float> block;
  for (std::size_t start = 0; start < frames; start += kBlockFrames) {
    const std::size_t count = std::min(kBlockFrames, frames - start);
    block.resize(count * channels.size());
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t c = 0; c < channels.size(); ++c)
        block[i * channels.size() + c] = static_cast<float>(channels[c][start + i] * gain);
    meter.addInterleaved(block);
  }
  return meter.measurement();
}

std::optional<LoudnessGain> loudnessNormalisationGain(const LoudnessMeasurement& measured,
                                                      const LoudnessTarget& target) {
  if (!measured.integratedLufs) return std::nullopt;
  LoudnessGain gain;
  gain.gainDecibels = target.integratedLufs - *measured.integratedLufs;
  const double headroom = target.truePeakCeilingDbtp - measured.truePeakDbtp;
  if (gain.gainDecibels > headroom) {
    gain.gainDecibels = headroom;
    gain.limitedByTruePeak = true;
  }
  return gain;
}

std::string loudnessLibraryVersion() {
  int major = 0, minor = 0, patch = 0;
  ebur128_get_version(&major, &minor, &patch);
  return std::to_string(major) + "." + std::to_string(minor) + "." + std::to_string(patch);
}

}  // namespace fluidsound::io
