// tools/run_inputs.cpp — see run_inputs.h.
#include "tools/run_inputs.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <variant>

#include "io/file_digest.h"
#include "io/frame_folder.h"
#include "io/text_file.h"
#include "tools/run_report.h"

namespace fluidsound::tools {

std::string fileBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string inputHash(const sim::Scene& scene) {
  std::uint64_t h = io::fnv1a64(fileBytes(scene.file));
  char cell[40];
  std::snprintf(cell, sizeof cell, "cell %.17g m", scene.domain.cell);
  h = io::fnv1a64(cell, h);
  const auto addMesh = [&h](const sim::Shape& shape) {
    if (const auto* mesh = std::get_if<sim::MeshFile>(&shape))
      h = io::fnv1a64(fileBytes(mesh->file), h);
  };
  for (const sim::LiquidRegion& r : scene.liquid) addMesh(r.shape);
  for (const sim::Solid& s : scene.solids) addMesh(s.shape);
  return io::hexDigits(io::fnv1a64(versionText(), h));
}

std::vector<std::string> frameFiles(const sim::Scene& scene) {
  const int last = static_cast<int>(std::lround(scene.time.duration * scene.time.fps));
  std::vector<std::string> files;
  for (int f = 0; f <= last; ++f) files.push_back("frames/" + io::frameFileName(f, "vdb"));
  return files;
}

std::string audioName(const std::filesystem::path& scene, const AudioOutputOptions& audio) {
  std::string stem = scene.stem().string();
  if (stem.size() > 6 && stem.ends_with(".scene")) stem.resize(stem.size() - 6);
  const bool flac = audio.format == "flac" || audio.format == "FLAC";
  return stem + (flac ? ".flac" : ".wav");
}

void requireRunOutputs(const std::filesystem::path& out, const std::string& audio) {
  std::error_code ec;
  if (!std::filesystem::is_directory(out, ec)) return;
  for (const std::string& name :
       {std::string("stages.json"), std::string("report.json"), std::string("bubbles.json"),
        std::string("transfer.report.json"), audio, std::string("spectrogram.png"),
        std::string("synth.report.json")})
    io::requireWritableFolder(out / name);
}

}  // namespace fluidsound::tools
