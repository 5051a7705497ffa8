// tests/tools/simulate_errors_test.cpp — the real `fluidsound simulate` on bad input and unusable
// output folders (docs/cli.md, "Exit status"): one line on stderr naming the file (and the JSON
// path), exit 3 for bad input or 4 for an output that cannot be written, and nothing written: no
// frame, no report.json, no temporary file. One table row per top-level block of the scene
// (docs/scene.md; every field is checked at parser level in scene_field_errors_test.cpp), plus the
// missing, unreadable and misspelt scene and each way OUTDIR can be unusable.
#include <gtest/gtest.h>

#include "io/bubble_track_file.h"
#include <unistd.h>

#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "io/scene_documents.h"
#include "support/command_runner.h"

namespace fluidsound::io {
namespace {

using namespace scene_test;
using test::CommandOutcome;
using test::runFluidsound;

constexpr int kExitBadInput = 3;      // docs/cli.md
constexpr int kExitOutputFailed = 4;  // docs/cli.md

/// How the scene file (WORK/scene.json) is made.
enum class Input {
  Scene,   ///< tinyScene() changed as the row says
  Absent,  ///< no such file
  Folder,  ///< a folder of that name
};

/// How OUTDIR is prepared before the run.
enum class Output {
  Fresh,            ///< nothing there: the command would make it
  IsAFile,          ///< a file stands where OUTDIR should be
  UnderAFile,       ///< OUTDIR's parent is a file (`-o blocked/out`)
  FramesIsAFile,    ///< OUTDIR exists; OUTDIR/frames is a file
  ReportIsAFolder,  ///< OUTDIR exists; OUTDIR/report.json is a folder
  ReadOnly,         ///< OUTDIR exists without write permission (skipped as root)
};

struct SimulateCase {
  const char* name;     ///< test name suffix
  Input input;          ///< the scene file
  const char* pointer;  ///< with Input::Scene: the change to tinyScene() (see withChange);
  const char* value;    ///<   nullptr pointer: the scene as it is; nullptr value: key removed
  Output output;        ///< OUTDIR
  const char* outdir;   ///< OUTDIR, relative to the test's folder WORK
  int exitCode;
  const char* named;  ///< the file the message names, relative to WORK
  /// What follows "fluidsound: error: WORK/NAMED: " ({dir} stands for WORK): the whole line for
  /// bad input, its start for output errors (whose end is the system's wording).
  const char* message;
  /// When set: the text of WORK/mesh.obj, written beside the scene (a bad mesh's content).
  const char* meshText = nullptr;
};

/// fullScene() on a grid small and short enough (12 × 6 × 2 cells, frames 0 … 3) that it
/// simulates in a fraction of a second (without emitters: fewer particles).
json tinyScene() {
  json document = fullScene();
  document["domain"]["cell"] = 0.05;
  document["time"]["duration"] = 0.05;
  document.erase("emitters");
  return document;
}

const std::vector<SimulateCase> kSimulateCases = {
    // ---- bad input: one row per top-level block -------------------------------------------------
    {"format", Input::Scene, "/format", R"("fluidsound.scene/2")", Output::Fresh, "out",
     kExitBadInput, "scene.json",
     R"(format: expected "fluidsound.scene/1", found "fluidsound.scene/2")"},
    {"domain", Input::Scene, "/domain/cell", "0", Output::Fresh, "out", kExitBadInput, "scene.json",
     "domain.cell: expected a number > 0 (metres), found 0"},
    {"gravity", Input::Scene, "/gravity", "[0, -9.8]", Output::Fresh, "out", kExitBadInput,
     "scene.json",
     "gravity: expected an array of 3 numbers [x, y, z] (m/s^2), found an array of 2 values"},
    {"time", Input::Scene, "/time/duration", nullptr, Output::Fresh, "out", kExitBadInput,
     "scene.json", "time.duration: expected a number > 0 (seconds), found nothing (required)"},
    {"seed", Input::Scene, "/seed", "-1", Output::Fresh, "out", kExitBadInput, "scene.json",
     "seed: expected an integer >= 0, found -1"},
    {"liquid", Input::Scene, "/liquid/1/sphere/radius", R"("0.02")", Output::Fresh, "out",
     kExitBadInput, "scene.json",
     R"(liquid[1].sphere.radius: expected a number > 0 (metres), found "0.02")"},
    {"emitters", Input::Scene, "/emitters",
     R"([{"disk": {"center": [0.3, 0.25, 0.05], "normal": [0, -1, 0], "radius": 0.004},
          "speed": 1.0, "start": 0.25, "end": 0.1}])",
     Output::Fresh, "out", kExitBadInput, "scene.json",
     "emitters[0].end: expected a number > start = 0.25 (seconds), found 0.1"},
    {"solids", Input::Scene, "/solids/1/path/1/t", "0.0", Output::Fresh, "out", kExitBadInput,
     "scene.json",
     "solids[1].path[1].t: expected a time greater than path[0].t = 0.0 (keys in time order; "
     "seconds), found 0.0"},
    {"solids_missing_mesh", Input::Scene, "/solids/0", R"({"mesh": "glass.obj"})", Output::Fresh,
     "out", kExitBadInput, "scene.json",
     "solids[0].mesh: expected the path of a readable mesh file (OBJ or PLY; relative to the scene "
     R"(file's folder), found "glass.obj" ({dir}/glass.obj: no such file))"},
    // bad meshes (issue 5): empty, a NaN vertex, an open liquid mesh
    {"liquid_empty_mesh", Input::Scene, "/liquid/0", R"({"mesh": "mesh.obj"})", Output::Fresh, "out",
     kExitBadInput, "scene.json",
     "liquid[0].mesh: expected a mesh with at least one triangle, found no faces (0 vertices) ({dir}/mesh.obj)",
     "# nothing\n"},
    {"liquid_nan_vertex", Input::Scene, "/liquid/0", R"({"mesh": "mesh.obj"})", Output::Fresh, "out",
     kExitBadInput, "scene.json",
     "liquid[0].mesh: expected a vertex \"v x y z\" of 3 finite numbers within float range "
     "(|x| <= 3.4e38), found \"nan\" in \"v 0 nan 0\" ({dir}/mesh.obj, line 3)",
     "v 0 0 0\nv 1 0 0\nv 0 nan 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n"},
    {"liquid_open_mesh", Input::Scene, "/liquid/0", R"({"mesh": "mesh.obj"})", Output::Fresh, "out",
     kExitBadInput, "scene.json",
     "liquid[0].mesh: expected a closed triangle mesh (every edge shared by exactly two triangles "
     "that run along it in opposite directions), found 3 boundary edges (holes; the first between "
     "vertices 2 and 3) ({dir}/mesh.obj)",
     "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n"},
    {"listeners", Input::Scene, "/listeners/1/position", nullptr, Output::Fresh, "out",
     kExitBadInput, "scene.json",
     "listeners[1].position: expected an array of 3 numbers [x, y, z] (metres), found nothing "
     "(required)"},
    {"audio", Input::Scene, "/audio/sample_rate", "4000", Output::Fresh, "out", kExitBadInput,
     "scene.json", "audio.sample_rate: expected an integer from 8000 to 768000 (Hz), found 4000"},
    {"solver", Input::Scene, "/solver/particles_per_cell", "0", Output::Fresh, "out", kExitBadInput,
     "scene.json", "solver.particles_per_cell: expected an integer from 1 to 64, found 0"},

    // ---- bad input: a frame that would never end, audio too long (exit 3 before any frame) -------
    {"cfl_tiny", Input::Scene, "/time/cfl", "1e-12", Output::Fresh, "out", kExitBadInput, "scene.json",
     "time.cfl: expected at most 10000 substeps per frame (fastest speed / (time.cfl × domain.cell × time.fps)), "
     "found 2.4e+12 substeps: up to 7.215 m/s (2 from emitters and liquid velocity, 5.215 from gravity over the "
     "domain) / (1e-12 × 0.05 m × 60 fps)"},
    {"gravity_huge", Input::Scene, "/gravity", "[0, -1e30, 0]", Output::Fresh, "out", kExitBadInput, "scene.json",
     "gravity: expected an acceleration of at most 1000 m/s^2 (about 100 g), found |g| = 1e+30 m/s^2"},
    {"emitter_speed_huge", Input::Scene, "/emitters",
     R"([{"disk": {"center": [0.3, 0.25, 0.05], "normal": [0, -1, 0], "radius": 0.004}, "speed": 1e6}])",
     Output::Fresh, "out", kExitBadInput, "scene.json",
     "emitters[0].speed: expected a number > 0 and <= 1000 (m/s; two thirds of the speed of sound in water), found "
     "1000000.0"},
    {"liquid_velocity_huge", Input::Scene, "/liquid/1/velocity", "[0, -1e6, 0]", Output::Fresh, "out", kExitBadInput,
     "scene.json",
     "liquid[1].velocity: expected a velocity of at most 1000 m/s (two thirds of the speed of sound in water), found "
     "|v| = 1000000.0 m/s"},
    {"audio_too_long", Input::Scene, "/time", R"({"duration": 30000, "fps": 30})", Output::Fresh, "out",
     kExitBadInput, "scene.json",
     "time.duration: expected a duration whose audio (duration × audio.sample_rate × channels) is at most 2^31 "
     "samples, found 30000 s × 44100 Hz × 2 = 2.646e+09 samples"},

    // ---- bad input: the file itself, unknown keys, and bad input before bad output --------------
    {"unknown_key", Input::Scene, "/solids/1/sphere/radus", "0.01", Output::Fresh, "out",
     kExitBadInput, "scene.json",
     "solids[1].sphere.radus: expected one of center, radius (did you mean 'radius'?), found an "
     "unknown key"},
    {"missing_scene_file", Input::Absent, nullptr, nullptr, Output::Fresh, "out", kExitBadInput,
     "scene.json", "expected a readable file, found no such file"},
    {"scene_is_a_folder", Input::Folder, nullptr, nullptr, Output::Fresh, "out", kExitBadInput,
     "scene.json", "expected a readable file, found a folder"},
    {"bad_scene_before_unusable_outdir", Input::Scene, "/time/fps", "0", Output::IsAFile, "out",
     kExitBadInput, "scene.json", "time.fps: expected a number > 0 and <= 1000 (frames per second), found 0"},

    // ---- a valid scene, an OUTDIR that cannot be written ----------------------------------------
    {"outdir_is_a_file", Input::Scene, nullptr, nullptr, Output::IsAFile, "out", kExitOutputFailed,
     "out", "cannot create the folder"},
    {"outdir_under_a_file", Input::Scene, nullptr, nullptr, Output::UnderAFile, "blocked/out",
     kExitOutputFailed, "blocked/out", "cannot create the folder"},
    {"outdir_frames_is_a_file", Input::Scene, nullptr, nullptr, Output::FramesIsAFile, "out",
     kExitOutputFailed, "out/frames", "cannot create the folder"},
    {"outdir_report_is_a_folder", Input::Scene, nullptr, nullptr, Output::ReportIsAFolder, "out",
     kExitOutputFailed, "out/report.json", "cannot write: it is a folder"},
    {"outdir_read_only", Input::Scene, nullptr, nullptr, Output::ReadOnly, "out", kExitOutputFailed,
     "out/report.json", "cannot write: folder"},
};

/// Makes the row's scene file (and mesh file).
void prepareInput(const SimulateCase& row, const fs::path& scene) {
  if (row.meshText != nullptr) writeFile(scene.parent_path() / "mesh.obj", row.meshText);
  switch (row.input) {
    case Input::Scene:
      writeFile(scene, (row.pointer == nullptr ? tinyScene()
                                               : withChange(tinyScene(), row.pointer, row.value))
                           .dump(2));
      break;
    case Input::Absent:
      break;
    case Input::Folder:
      fs::create_directories(scene);
      break;
  }
}

/// Makes what stands at (or in) OUTDIR before the run.
void prepareOutput(Output output, const fs::path& work, const fs::path& outdir) {
  switch (output) {
    case Output::Fresh:
      break;
    case Output::IsAFile:
      writeFile(outdir, "a file, not a folder");
      break;
    case Output::UnderAFile:
      writeFile(work / "blocked", "a file, not a folder");
      break;
    case Output::FramesIsAFile:
      fs::create_directories(outdir);
      writeFile(outdir / "frames", "a file, not a folder");
      break;
    case Output::ReportIsAFolder:
      fs::create_directories(outdir / "report.json");
      break;
    case Output::ReadOnly:
      fs::create_directories(outdir);
      fs::permissions(outdir, fs::perms::owner_read | fs::perms::owner_exec);
      break;
  }
}

/// Every entry under `folder` (relative path → is a folder).
std::map<std::string, bool> entriesUnder(const fs::path& folder) {
  std::map<std::string, bool> entries;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    entries[fs::relative(entry.path(), folder).string()] = entry.is_directory();
  return entries;
}

/// `text` with each "{dir}" replaced by `dir`.
std::string withDir(std::string text, const std::string& dir) {
  for (std::size_t at = text.find("{dir}"); at != std::string::npos; at = text.find("{dir}", at)) {
    text.replace(at, 5, dir);
    at += dir.size();
  }
  return text;
}

/// gtest prints a failing row by its name.
void PrintTo(const SimulateCase& row, std::ostream* out) { *out << row.name; }

class SimulateCommand : public ::testing::TestWithParam<SimulateCase> {};

TEST_P(SimulateCommand, FailsWithOneLineAndWritesNothing) {
  const SimulateCase& row = GetParam();
  if (row.output == Output::ReadOnly && ::geteuid() == 0)
    GTEST_SKIP() << "permissions do not stop root";
  const TempFolder folder;
  const fs::path work = folder.path();
  const fs::path scene = work / "scene.json";
  const fs::path outdir = work / row.outdir;
  prepareInput(row, scene);
  prepareOutput(row.output, work, outdir);
  const std::map<std::string, bool> before = entriesUnder(work);

  const CommandOutcome result =
      runFluidsound({"simulate", scene.string(), "-o", outdir.string(), "--quiet"});
  if (row.output == Output::ReadOnly) fs::permissions(outdir, fs::perms::owner_all);

  EXPECT_EQ(result.exitCode, row.exitCode) << result.err;
  const std::string head = "fluidsound: error: " + (work / row.named).string() + ": " +
                           withDir(row.message, work.string());
  EXPECT_TRUE(result.err.starts_with(head)) << result.err << " does not start with\n" << head;
  if (row.exitCode == kExitBadInput) {
    EXPECT_EQ(result.err, head + "\n");
  }
  EXPECT_EQ(result.err.find('\n'), result.err.size() - 1) << "not one line: " << result.err;

  // Nothing written: bad input is found before OUTDIR is touched; an unusable OUTDIR leaves no
  // file anywhere (no frame, no report.json, no temporary file), at most an empty folder.
  const std::map<std::string, bool> after = entriesUnder(work);
  for (const auto& [name, isFolder] : after) {
    if (before.contains(name)) continue;
    if (row.exitCode == kExitBadInput) {
      ADD_FAILURE() << "written although the input is bad: " << name;
    } else if (!isFolder || !fs::is_empty(work / name)) {
      ADD_FAILURE() << "left behind: " << name;
    }
  }
  EXPECT_FALSE(fs::is_regular_file(outdir / "report.json"));
  if (fs::is_directory(outdir / "frames")) {
    EXPECT_TRUE(fs::is_empty(outdir / "frames"));
  }
}

INSTANTIATE_TEST_SUITE_P(SimulateErrors, SimulateCommand, ::testing::ValuesIn(kSimulateCases),
                         [](const ::testing::TestParamInfo<SimulateCase>& info) {
                           return std::string(info.param.name);
                         });

// The control for the rows above: the unchanged scene in a fresh OUTDIR simulates, so each
// failure is the row's doing.
TEST(SimulateErrors, TinySceneSimulates) {
  const TempFolder folder;
  const fs::path scene = folder.path() / "scene.json", outdir = folder.path() / "out";
  writeFile(scene, tinyScene().dump(2));
  const CommandOutcome result =
      runFluidsound({"simulate", scene.string(), "-o", outdir.string(), "--quiet"});
  EXPECT_EQ(result.exitCode, 0) << result.err;
  for (const char* name : {"frames/0000.vdb", "frames/0003.vdb", "report.json", "bubbles.json"})
    EXPECT_TRUE(fs::is_regular_file(outdir / name)) << name;
  // The bubble tracks are a valid fluidsound.bubbles/1 file (transfer comes later)…
  EXPECT_NO_THROW(readBubbleTracks(outdir / "bubbles.json", TransferValues::Optional));
  // …which `transfer` fills from the frames alone: one value per listener in every sample.
  const CommandOutcome transfer = runFluidsound({"transfer", scene.string(), "-o", outdir.string(), "--quiet"});
  EXPECT_EQ(transfer.exitCode, 0) << transfer.err;
  EXPECT_NO_THROW(readBubbleTracks(outdir / "bubbles.json", TransferValues::Required));
  EXPECT_TRUE(fs::is_regular_file(outdir / "transfer.report.json"));
}

}  // namespace
}  // namespace fluidsound::io
