// tools/run_solids.cpp — see run_solids.h.
#include "tools/run_solids.h"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>

#include "acoustics/modal/solid_sound.h"
#include "acoustics/binaural/hrir_convolution.h"
#include "acoustics/binaural/hrir_table.h"
#include "acoustics/modal/body_contact_points.h"
#include "io/contact_log_file.h"
#include "io/hrir_file.h"
#include "io/input_error.h"
#include "io/interruption.h"
#include "io/scene_meshes.h"
#include "sim/bodies/body_segment.h"
#include "sim/body_motion.h"
#include "tools/body_modes.h"
#include "tools/stage_progress.h"

namespace fluidsound::tools {

sim::ContactLog readRunContactLog(const sim::Scene& scene, const std::filesystem::path& out) {
  const std::filesystem::path file = out / "contacts.bin";
  sim::ContactLog log = io::readContactLog(file);
  if (log.bodies.size() != scene.bodies.size())
    throw io::InputError(file.string(), "bodies",
                         std::to_string(scene.bodies.size()) + " bodies, the scene's (run simulate again)",
                         std::to_string(log.bodies.size()));
  return log;
}

std::vector<std::array<double, 3>> channelPositions(const sim::Scene& scene) {
  std::vector<std::array<double, 3>> positions;
  for (const sim::Listener& l : scene.listeners) {
    positions.push_back({l.position[0], l.position[1], l.position[2]});
    if (l.head) positions.push_back(positions.back());
  }
  return positions;
}

namespace {

/// Where body `b` is heard from: a static body's centre, a moving one's place at its first contact.
Eigen::Vector3d heardFrom(const sim::Scene& scene, const sim::ContactLog& log, std::size_t b) {
  const sim::RigidBodySpec spec = sim::rigidBodySpec(scene.bodies[b]);
  if (!spec.isStatic) {
    const std::vector<acoustics::BodyContactPoint> points = acoustics::bodyContactPoints(log, static_cast<int>(b));
    if (!points.empty()) return points.front().origin;
  }
  return {spec.position[0], spec.position[1], spec.position[2]};
}

}  // namespace

HeadStems hearWithHead(const sim::Scene& scene, const sim::ContactLog& log,
                       const std::vector<acoustics::SoundingBody>& bodies, const acoustics::SolidSoundSettings& settings,
                       const sim::Listener& listener, const acoustics::HrirTable& table) {
  const double gain = acoustics::freeFieldGain(table);
  const Eigen::Vector3d centre(listener.position[0], listener.position[1], listener.position[2]);
  const std::size_t n = settings.samples;
  std::array<std::vector<double>, 3> left, right;  // impacts, rolling, friction
  for (std::size_t k = 0; k < 3; ++k) left[k].assign(n, 0.0), right[k].assign(n, 0.0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!bodies[b].model || bodies[b].model->frequency.empty()) continue;
    // This body alone at the head's centre, then through the pair of the direction it is in.
    std::vector<acoustics::SoundingBody> alone = bodies;
    for (std::size_t other = 0; other < alone.size(); ++other)
      if (other != b) alone[other].model = nullptr;
    acoustics::SolidSoundSettings atCentre = settings;
    atCentre.listeners = {centre};
    StageObserver quiet;
    const acoustics::SolidStems heard = acoustics::renderSolidSound(log, alone, atCentre, quiet);
    const Eigen::Vector3d towards = heardFrom(scene, log, b) - centre;
    const std::size_t direction = acoustics::nearestDirection(
        table, acoustics::headDirection({towards.x(), towards.y(), towards.z()}, listener.head->facing,
                                        listener.head->up));
    const std::array<const std::vector<float>*, 3> mono = {&heard.impacts[0], &heard.rolling[0], &heard.friction[0]};
    for (std::size_t k = 0; k < 3; ++k) acoustics::addHeardFrom(table, direction, *mono[k], gain, left[k], right[k]);
  }
  HeadStems ears;
  for (std::size_t k = 0; k < 3; ++k) {
    ears.left[k].assign(left[k].begin(), left[k].end());
    ears.right[k].assign(right[k].begin(), right[k].end());
  }
  return ears;
}

ExtraStems renderRunSolids(const sim::Scene& read, const std::filesystem::path& out, std::size_t frames,
                           double sampleRate, bool quiet) {
  sim::Scene scene = read;
  io::loadSceneMeshes(scene);
  const sim::ContactLog log = readRunContactLog(scene, out);
  nlohmann::ordered_json report;
  report["contact_records"] = log.records.size();
  std::vector<BodyModes> modes;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    io::throwIfInterrupted("solids, modes of body " + std::to_string(i));
    modes.push_back(bodyModes(scene, i, out / "modes", std::min(20000.0, 0.5 * sampleRate)));
    const BodyModes& m = modes.back();
    if (!quiet)
      std::fprintf(stderr, "run: solids: %s: %zu modes (%zu voxels of %.3g mm; cache %s) in %.1f s\n",
                   scene.bodies[i].name.c_str(), m.model.frequency.size(), m.voxels, m.voxelSize * 1e3,
                   m.cache.c_str(), m.seconds);
  }
  std::vector<acoustics::SoundingBody> bodies;
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
    bodies.push_back({&modes[i].model, scene.bodies[i].material});
  acoustics::SolidSoundSettings settings;
  settings.sampleRate = sampleRate;
  settings.samples = frames;
  // The plain listeners here; each head's ears below (hearWithHead), each body rendered once per listener.
  for (const sim::Listener& l : scene.listeners)
    if (!l.head) settings.listeners.emplace_back(l.position[0], l.position[1], l.position[2]);
  // The static bodies shadow the others where they stand.
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    if (!scene.bodies[i].isStatic) continue;
    const sim::RigidBodySpec spec = sim::rigidBodySpec(scene.bodies[i]);
    settings.occluders.push_back(
        {static_cast<int>(i),
         {spec.position[0], spec.position[1], spec.position[2]},
         sim::boundingRadius(spec),
         [spec](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
           return sim::segmentCrossesBody(spec, {a.x(), a.y(), a.z()}, {b.x(), b.y(), b.z()});
         }});
  }
  StageProgress observer("solids", "bodies", quiet);
  acoustics::SolidStems stems;
  try {
    stems = acoustics::renderSolidSound(log, bodies, settings, observer);
    observer.finish();
  } catch (const StageInterrupted& e) {
    throw io::Interrupted(io::interruptionSignal(), e.what());
  }
  // The channels in the bubbles' order: a plain listener's, then a head's left and right ear.
  std::array<std::vector<std::vector<float>>, 3> channels;
  const std::array<std::vector<std::vector<float>>*, 3> plain = {&stems.impacts, &stems.rolling, &stems.friction};
  std::optional<acoustics::HrirTable> table;
  std::size_t next = 0;
  for (const sim::Listener& l : scene.listeners) {
    if (!l.head) {
      for (std::size_t k = 0; k < 3; ++k) channels[k].push_back(std::move((*plain[k])[next]));
      ++next;
      continue;
    }
    if (!table) table = io::readHrirTable(scene.hrtf.value_or(io::defaultHrirFile()), sampleRate);
    HeadStems ears = hearWithHead(scene, log, bodies, settings, l, *table);
    for (std::size_t k = 0; k < 3; ++k) {
      channels[k].push_back(std::move(ears.left[k]));
      channels[k].push_back(std::move(ears.right[k]));
    }
  }
  report["bodies"] = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
    const acoustics::SolidBodyReport& r = stems.bodies[i];
    const BodyModes& m = modes[i];
    report["bodies"].push_back({{"name", scene.bodies[i].name},
                                {"static", scene.bodies[i].isStatic},
                                {"mass_kg", log.bodies[i].mass},
                                {"voxels", m.voxels},
                                {"voxel_size_m", m.voxelSize},
                                {"modes", r.modes},
                                {"lowest_mode_hz", m.model.frequency.empty() ? 0.0 : m.model.frequency.front()},
                                {"oscillators", r.oscillators},
                                {"modes_cache", m.cache},
                                {"modes_seconds", m.seconds},
                                {"impacts", r.impacts},
                                {"rubbing_contacts", r.rubbingContacts},
                                {"rolling_substeps", r.rollingSubsteps},
                                {"sliding_substeps", r.slidingSubsteps},
                                {"stick_slip_breaks", r.stickSlipBreaks},
                                {"oscillator_samples", r.oscillatorSamples}});
  }
  return {{"impacts", "rolling", "friction"},
          {std::move(channels[0]), std::move(channels[1]), std::move(channels[2])},
          std::move(report)};
}

}  // namespace fluidsound::tools
