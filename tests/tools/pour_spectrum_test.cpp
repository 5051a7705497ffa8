// End-to-end check of issue 6 through the real executable: `fluidsound run` renders a short pour,
// and its spectrum carries its energy where the bubbles' Minnaert frequencies say, with no line at
// the frame rate or its harmonics (docs/synthesis.md, "What the spectrum shows").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "acoustics/analysis/centroid_prediction.h"
#include "acoustics/analysis/power_spectrum.h"
#include "acoustics/analysis/spectrum_statistics.h"
#include "acoustics/synthesis/synthesizer.h"
#include "io/audio_file.h"
#include "io/bubble_track_file.h"
#include "support/command_runner.h"
#include "support/frame_rate_lines.h"
#include "support/temp_folder.h"

namespace fluidsound::test {
namespace {

namespace fs = std::filesystem;
using acoustics::FrequencyBand;

/// scenes/pour_tank.scene.json made short and coarse: the same tank, pool and listeners, a
/// 2 m/s jet from a 1 cm nozzle for 0.6 s on 1.25 cm cells (16³), 30 fps.
constexpr const char* kScene = R"({
  "format": "fluidsound.scene/1",
  "domain": { "min": [0, 0, 0], "max": [0.2, 0.2, 0.2], "cell": 0.0125 },
  "time": { "duration": 0.6, "fps": 30 },
  "seed": 1,
  "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.2, 0.06, 0.2] } } ],
  "emitters": [ { "disk": { "center": [0.1, 0.18, 0.1], "normal": [0, -1, 0], "radius": 0.01 },
                  "speed": 2.0, "start": 0.0, "end": 0.6 } ],
  "listeners": [ { "name": "left",  "position": [0.0, 0.5, 0.1] },
                 { "name": "right", "position": [0.2, 0.5, 0.1] } ],
  "audio": { "sample_rate": 48000 }
})";
constexpr double kFrameRate = 30.0;  // the scene's fps [Hz]

/// The band of the centroid: the audible range (all rendered bubbles ring inside it but the
/// smallest, R < 0.165 mm, above 20 kHz; the prediction restricts to the same band).
constexpr FrequencyBand kBand{20.0, 20000.0};
/// Issue 6: the measured centroid within 10 % of the predicted one.
constexpr double kCentroidTolerance = 0.10;
/// Welch segment of the centroid: the frame-rate check's (2.93 Hz bins); any length gives the
/// same centroid to well under 0.1 % (Parseval: the spectrum holds the record's whole energy).
constexpr std::size_t kSegment = kFrameLineSegment;

acoustics::SynthesisSettings synthSettings(const acoustics::BubbleTrackSet& tracks) {
  acoustics::SynthesisSettings s;  // the default model, as `fluidsound run` renders
  s.sampleRate = tracks.sampleRate;
  s.duration = tracks.duration;
  return s;
}

// Claim (issue 6, end to end): for each listener's channel of the rendered pour, (1) the spectral
// centroid over 20 Hz … 20 kHz is within 10 % of the centroid predicted from bubbles.json (each
// bubble's energy at that listener, A²·transfer² over its decay, at its depth-shifted Minnaert
// frequency, with the rendered line's shape: centroid_prediction.h), and so is the energy in the
// band (the level: amplitudes and transfers rendered as the file says, which the centroid alone
// would not notice if all were scaled alike); (2) no line at 30 Hz (the
// frame rate) or its harmonics up to 300 Hz stands out — none more than 12 dB above its
// neighbours, and their mean less than 6 dB — in the envelope spectrum (where births or gains tied
// to frames would show) nor in the spectrum itself (where clicks at frame boundaries, or bubbles
// starting in phase at the frame instants, would); (3) the same check fails on the same bubbles
// with their births moved to the frame instants, so (2) can fail. Tolerances: 10 % is the
// issue's (for the energy too: interference between bubbles, which the prediction leaves out,
// moves this pour's energy by < 1 % and its centroid by < 1 %, docs/synthesis.md); the line limits
// are justified in tests/support/frame_rate_lines.h.
TEST(PourSpectrum, CentroidFollowsTheBubblesAndNoFrameRateLine) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "pour.scene.json", out = folder.path() / "out";
  { std::ofstream(scene) << kScene; }
  // The image-source model: with the geometric one (issue 19) the control (3) no longer shows the
  // frame comb in the envelope (+0.4 dB against the 6 dB it needs), its per-frame transfers
  // changing by orders of magnitude; to be judged with the geometric model's acceptance.
  const CommandOutcome run = runFluidsound(
      {"run", scene.string(), "-o", out.string(), "--quiet", "--transfer", "image"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const io::AudioBuffer audio = io::readAudio(out / "pour.wav");
  const acoustics::BubbleTrackSet tracks = io::readBubbleTracks(out / "bubbles.json");
  ASSERT_EQ(audio.channels.size(), 2u);
  ASSERT_GT(tracks.bubbles.size(), 100u) << "the pour must make a crowd of bubbles to measure";

  const acoustics::SynthesisSettings settings = synthSettings(tracks);
  const std::vector<acoustics::PredictedSpectrum> predicted =
      acoustics::predictedSpectra(tracks, settings, kBand);
  for (std::size_t l = 0; l < audio.channels.size(); ++l) {
    const std::vector<float>& x = audio.channels[l];
    const double measured = acoustics::spectralCentroid(
        acoustics::welchPowerSpectrum(x, audio.sampleRate, kSegment), kBand);
    EXPECT_NEAR(measured, predicted[l].centroid, kCentroidTolerance * predicted[l].centroid)
        << "channel " << l << ": measured " << measured << " Hz, predicted "
        << predicted[l].centroid << " Hz";
    const acoustics::PowerSpectrum spectrum =
        acoustics::welchPowerSpectrum(x, audio.sampleRate, kSegment);
    double bandEnergy = 0.0;  // ∫ p² dt within the band [Pa²·s]: mean power × duration (Parseval)
    for (std::size_t k = 0; k < spectrum.power.size(); ++k)
      if (spectrum.frequency(k) >= kBand.low && spectrum.frequency(k) <= kBand.high)
        bandEnergy += spectrum.power[k] * spectrum.binWidth * static_cast<double>(x.size()) /
                      audio.sampleRate;
    EXPECT_NEAR(bandEnergy, predicted[l].bandEnergy, kCentroidTolerance * predicted[l].bandEnergy)
        << "channel " << l << ": measured " << bandEnergy << " Pa²s, predicted "
        << predicted[l].bandEnergy << " Pa²s";
    const FrameRateLines lines = frameRateLines(x, audio.sampleRate, kFrameRate);
    for (const auto& [name, found] :
         {std::pair{"envelope", &lines.envelope}, std::pair{"spectrum", &lines.spectrum}}) {
      EXPECT_LT(largestProminence(*found), kFrameLineLimitDecibels)
          << "channel " << l << ", " << name << ": " << describeLines(*found);
      EXPECT_LT(acoustics::meanProminenceDecibels(*found), kFrameCombLimitDecibels)
          << "channel " << l << ", " << name << ": " << describeLines(*found);
    }
    std::cout << "[ measured ] channel " << l << ": " << predicted[l].bubbles
              << " bubbles rendered, centroid " << measured << " Hz measured, "
              << predicted[l].centroid << " Hz predicted ("
              << 100.0 * (measured / predicted[l].centroid - 1.0) << " %); band energy "
              << bandEnergy << " Pa²s measured, " << predicted[l].bandEnergy
              << " predicted\n[ measured ]   envelope: " << describeLines(lines.envelope)
              << "\n[ measured ]   spectrum: " << describeLines(lines.spectrum) << "\n";
  }

  // The counterfactual: the same bubbles, each born at the frame instant before its birth.
  acoustics::BubbleTrackSet quantised = tracks;
  for (acoustics::BubbleTrack& b : quantised.bubbles)
    b.birth = std::floor(b.birth * kFrameRate) / kFrameRate;
  const acoustics::SynthesisResult render = acoustics::synthesize(quantised, settings);
  for (std::size_t l = 0; l < render.channels.size(); ++l) {
    const FrameRateLines lines = frameRateLines(render.channels[l], audio.sampleRate, kFrameRate);
    for (const auto& [name, found] :
         {std::pair{"envelope", &lines.envelope}, std::pair{"spectrum", &lines.spectrum}})
      EXPECT_GT(acoustics::meanProminenceDecibels(*found), kFrameCombLimitDecibels)
          << "channel " << l << ", births quantised to frames, " << name << ": "
          << describeLines(*found);
    std::cout << "[ measured ] channel " << l << ", births quantised to frames: envelope "
              << describeLines(lines.envelope)
              << "\n[ measured ]   spectrum: " << describeLines(lines.spectrum) << "\n";
  }
}

}  // namespace
}  // namespace fluidsound::test
