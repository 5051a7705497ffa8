// tools/frame_writer.cpp — see frame_writer.h.
#include "tools/frame_writer.h"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/frame_files.h"
#include "io/frame_folder.h"
#include "io/input_error.h"
#include "io/text_file.h"

namespace fluidsound::tools {

namespace {

void createFolder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw io::OutputError(folder.string() + ": cannot create the folder: " + ec.message());
}

/// Clears the frames another run left in `frames`, says what it removed and warns of what it left.
void clearOtherRunsFrames(const std::filesystem::path& frames, const FrameRange& range, bool ply,
                          bool quiet) {
  const io::FrameFolderCleanup cleanup =
      io::clearStaleFrames(frames, [&](int frame, std::string_view extension) {
        return frame >= range.first && frame <= range.last && (extension == "vdb" || ply);
      });
  if (!cleanup.removed.empty() && !quiet)
    std::fprintf(stderr, "fluidsound: note: %s: removed %zu stale frame file(s) of another run\n",
                 frames.string().c_str(), cleanup.removed.size());
  if (!cleanup.foreign.empty()) {
    std::string names;
    for (std::size_t i = 0; i < cleanup.foreign.size() && i < 3; ++i)
      names += (i > 0 ? ", " : "") + cleanup.foreign[i].filename().string();
    std::fprintf(
        stderr, "fluidsound: warning: %s: left %zu entr%s that %s not frames of this run: %s%s\n",
        frames.string().c_str(), cleanup.foreign.size(), cleanup.foreign.size() == 1 ? "y" : "ies",
        cleanup.foreign.size() == 1 ? "is" : "are", names.c_str(),
        cleanup.foreign.size() > 3 ? ", ..." : "");
  }
}

}  // namespace

FrameRange parseFrameRange(const std::string& text, int total) {
  if (text.empty()) return {0, total};
  const auto colon = text.find(':');
  try {
    if (colon == std::string::npos) throw std::invalid_argument(text);
    const int a = std::stoi(text.substr(0, colon)), b = std::stoi(text.substr(colon + 1));
    if (a < 0 || b < a || b > total) throw std::invalid_argument(text);
    return {a, b};
  } catch (const std::exception&) {
    throw CLI::ValidationError(
        "--frames", "expected A:B with 0 ≤ A ≤ B ≤ " + std::to_string(total) + ", found " + text);
  }
}

void prepareFrameFolder(const std::filesystem::path& out, const FrameRange& range, bool ply,
                        bool quiet) {
  const std::filesystem::path frames = out / "frames";
  createFolder(out);
  io::requireWritableFolder(out / "report.json");
  io::requireWritableFolder(out / "bubbles.json");
  createFolder(frames);
  io::requireWritableFolder(frames / "0000.vdb");
  clearOtherRunsFrames(frames, range, ply, quiet);
}

FrameWriter::FrameWriter(std::filesystem::path frames, bool ply, int last, double fps, bool quiet)
    : frames_(std::move(frames)),
      ply_(ply),
      last_(last),
      fps_(fps),
      progress_("simulate", last + 1, "frames", quiet) {}

void FrameWriter::onFrame(const sim::FrameView& state, const sim::FrameRecord& record) {
  const auto t0 = std::chrono::steady_clock::now();
  if (state.kept) {
    try {  // a frame for a FIFO waits for its reader, until a signal
      io::writeFrameVdb(frames_ / io::frameFileName(record.frame, "vdb"), state.grid,
                        state.particles, state.velocity, {state.particleRadius},
                        {record.frame, record.time, fps_, std::string("fluidsound ") + FLUIDSOUND_VERSION});
      if (ply_)
        io::writeParticlesPly(frames_ / io::frameFileName(record.frame, "ply"), state.particles);
    } catch (const io::Interrupted& signal) {
      unwritten_.emplace(record.frame, signal);
      return;
    }
  }
  const double seconds =
      record.simulationSeconds +
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  char line[160];  // through the display, which clears its line first on a terminal
  std::snprintf(line, sizeof line,
                "frame %4d/%d  t %.3f s  substeps %2d  cg %4d (res %.1e)  particles %zu  %.2f s",
                record.frame, last_, record.time, record.fluid.substeps,
                record.fluid.pressureIterations, record.fluid.pressureResidual, record.particles,
                seconds);
  progress_.log(line);
}

}  // namespace fluidsound::tools
