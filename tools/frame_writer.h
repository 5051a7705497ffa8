// tools/frame_writer.h — OUTDIR/frames of `simulate` (and `run`'s simulate stage): the folder made
// and cleared of another run's frames, and the simulation's observer that writes each kept frame
// as it is made (VDB, and PLY with --ply), logs a line per frame and shows progress.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>

#include "io/interruption.h"
#include "sim/simulation.h"
#include "tools/progress_display.h"

namespace fluidsound::tools {

/// The frames a simulate writes, first … last inclusive.
struct FrameRange {
  int first = 0, last = 0;
};

/// @brief The frames `--frames A:B` names (empty: 0 … total).
/// @throws CLI::ValidationError (exit 2) unless 0 ≤ A ≤ B ≤ total
FrameRange parseFrameRange(const std::string& text, int total);

/// @brief Makes OUTDIR and OUTDIR/frames, after checking that report.json and bubbles.json can be
///        written there (so a failure leaves nothing new), then clears the frames another run left
///        in frames/ (io/frame_folder.h): it then holds only the frames of `range` (PLY too with
///        `ply`); says what it removed and warns of what it left.
/// @throws io::OutputError
void prepareFrameFolder(const std::filesystem::path& out, const FrameRange& range, bool ply,
                        bool quiet);

/// The simulation's observer for the CLI; a signal (io/interruption.h) interrupts the simulation.
class FrameWriter : public sim::SimulationObserver {
 public:
  /// @param fps  the scene's frame rate, written into each frame's metadata
  FrameWriter(std::filesystem::path frames, bool ply, int last, double fps, bool quiet);

  void onFrame(const sim::FrameView& state, const sim::FrameRecord& record) override;
  void progress(double fraction) override { progress_.update(fraction); }
  bool wasInterrupted() override { return io::interruptionRequested(); }
  void finish() { progress_.finish(); }
  /// The frame whose writing a signal ended, and the signal (the simulation stopped after it).
  const std::optional<std::pair<int, io::Interrupted>>& unwritten() const { return unwritten_; }

 private:
  std::filesystem::path frames_;
  bool ply_;
  int last_;
  double fps_;
  ProgressDisplay progress_;
  std::optional<std::pair<int, io::Interrupted>> unwritten_;
};

}  // namespace fluidsound::tools
