// tools/run_playback.cpp — see run_playback.h.
#include "tools/run_playback.h"

#include <cstdio>
#include <string>

#include "io/audio_file.h"
#include "io/input_error.h"
#include "tools/run_solids.h"

namespace fluidsound::tools {

namespace {

/// One recording as a mono sound: the mean of its channels.
acoustics::RecordedSound recording(const sim::Scene& scene, const std::filesystem::path& file,
                                   const std::string& field) {
  const std::string expected = "a recording (WAV or FLAC) at the scene's sample rate, " +
                               std::to_string(static_cast<long>(scene.sampleRate)) + " Hz";
  io::AudioBuffer audio;
  try {
    audio = io::readAudio(file);
  } catch (const io::InputError& e) {
    throw io::InputError(scene.file.string(), field, expected, e.what());
  }
  if (audio.frameCount() == 0)
    throw io::InputError(scene.file.string(), field, expected, file.string() + ": no samples");
  if (audio.sampleRate != scene.sampleRate)
    throw io::InputError(scene.file.string(), field, expected,
                         file.string() + " at " + std::to_string(static_cast<long>(audio.sampleRate)) + " Hz");
  acoustics::RecordedSound sound;
  sound.sampleRate = audio.sampleRate;
  sound.samples.assign(audio.frameCount(), 0.0f);
  for (const auto& channel : audio.channels)
    for (std::size_t i = 0; i < channel.size(); ++i)
      sound.samples[i] += channel[i] / static_cast<float>(audio.channels.size());
  return sound;
}

/// A body's material name for the pairs: its table name, "domain" for a wall, "" when the scene
/// gives its constants as numbers (no recording matches it).
std::string materialOf(const sim::Scene& scene, int body) {
  return body < 0 ? std::string("domain") : scene.bodies[static_cast<std::size_t>(body)].materialName;
}

}  // namespace

std::vector<acoustics::CollisionRecordings> readCollisionRecordings(const sim::Scene& scene) {
  std::vector<acoustics::CollisionRecordings> out;
  for (std::size_t i = 0; i < scene.collisionSamples.size(); ++i) {
    const sim::CollisionSamples& pair = scene.collisionSamples[i];
    const std::string path = "collision_samples[" + std::to_string(i) + "].";
    acoustics::CollisionRecordings r;
    r.peakPascals = pair.peakPascals;
    if (!pair.impact.empty()) r.impact = recording(scene, pair.impact, path + "impact");
    if (!pair.slide.empty()) r.slide = recording(scene, pair.slide, path + "slide");
    if (!pair.roll.empty()) r.roll = recording(scene, pair.roll, path + "roll");
    out.push_back(std::move(r));
  }
  return out;
}

ExtraStems renderRunPlayback(const sim::Scene& scene, const std::filesystem::path& out, std::size_t frames,
                             double sampleRate, bool quiet) {
  const std::vector<acoustics::CollisionRecordings> recordings = readCollisionRecordings(scene);
  const sim::ContactLog log = readRunContactLog(scene, out);
  const auto recordingsOf = [&](int a, int b) -> const acoustics::CollisionRecordings* {
    const std::string first = materialOf(scene, a), second = materialOf(scene, b);
    for (std::size_t i = 0; i < scene.collisionSamples.size(); ++i) {
      const auto& m = scene.collisionSamples[i].materials;
      if ((m[0] == first && m[1] == second) || (m[0] == second && m[1] == first)) return &recordings[i];
    }
    return nullptr;
  };
  acoustics::CollisionPlaybackSettings settings;
  settings.sampleRate = sampleRate;
  settings.samples = frames;
  settings.listeners = channelPositions(scene);
  acoustics::PlaybackStems stems = acoustics::renderCollisionPlayback(log, recordingsOf, settings);
  if (!quiet)
    std::fprintf(stderr, "run: solids by sample playback: %zu impacts, %zu slide and %zu roll substeps played\n",
                 stems.impactsPlayed, stems.slideSubsteps, stems.rollSubsteps);
  nlohmann::ordered_json report = {{"method", "samples"},
                                   {"contact_records", log.records.size()},
                                   {"impacts_played", stems.impactsPlayed},
                                   {"slide_substeps", stems.slideSubsteps},
                                   {"roll_substeps", stems.rollSubsteps}};
  return {{"impacts", "rolling", "friction"},
          {std::move(stems.impacts), std::move(stems.rolling), std::move(stems.friction)},
          std::move(report)};
}

}  // namespace fluidsound::tools
