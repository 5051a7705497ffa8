// tests/io/scene_documents.h — shared by the scene-file tests: example documents (every field;
// only the required ones) and the error checks for tank.json.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "io/input_error.h"
#include "io/scene_file.h"
#include "support/input_error_expectations.h"
#include "support/temp_folder.h"

namespace fluidsound::io::scene_test {

namespace fs = std::filesystem;
using nlohmann::json;
using test::TempFolder;

/// The repository root, for the example scenes (CMake defines it; else relative to this file).
inline fs::path sourceDir() {
#ifdef FLUIDSOUND_SOURCE_DIR
  return FLUIDSOUND_SOURCE_DIR;
#else
  return fs::path(__FILE__).parent_path().parent_path().parent_path();
#endif
}

/// A scene using every field except meshes (which need files; see the TempFolder tests).
inline json fullScene() {
  return json::parse(R"({
    "format": "fluidsound.scene/1",
    "domain": { "min": [0, 0, 0], "max": [0.6, 0.3, 0.1], "cell": 0.005, "open": ["+y", "-x"] },
    "gravity": [0, -9.8, 0.5],
    "time": { "duration": 2.0, "fps": 60, "cfl": 2.5 },
    "seed": 42,
    "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.1, 0.2, 0.1] } },
                { "sphere": { "center": [0.3, 0.05, 0.05], "radius": 0.02 },
                  "velocity": [0, -2, 0] } ],
    "emitters": [ { "disk": { "center": [0.3, 0.25, 0.05], "normal": [0, -2, 0],
                              "radius": 0.004 },
                    "speed": 1.0, "start": 0.25, "end": 1.5 },
                  { "disk": { "center": [0.1, 0.25, 0.05], "normal": [3, 0, 4],
                              "radius": 0.002 },
                    "speed": 0.5 } ],
    "solids": [ { "box": { "min": [0.2, 0, 0], "max": [0.25, 0.05, 0.1] },
                  "scale": 2, "translate": [0.01, 0, 0], "rotate": [0, 0, 15] },
                { "sphere": { "center": [0.3, 0.2, 0.05], "radius": 0.01 },
                  "path": [ { "t": 0.0, "translate": [0, 0, 0] },
                            { "t": 0.5, "translate": [0, -0.15, 0] } ] } ],
    "listeners": [ { "name": "left", "position": [0.25, 0.4, 0.3] },
                   { "name": "right", "position": [0.35, 0.4, 0.3] } ],
    "audio": { "sample_rate": 44100 },
    "solver": { "transfer": "flip", "flip_ratio": 0.9, "particles_per_cell": 4,
                "pressure_tolerance": 1e-5, "max_pressure_iterations": 200, "surface": "level_set" }
  })");
}

/// Only what is required.
inline json minimalScene() {
  return json::parse(R"({
    "format": "fluidsound.scene/1",
    "domain": { "min": [-0.1, 0, 0], "max": [0.3, 0.2, 0.1], "cell": 0.01 },
    "time": { "duration": 1.5 }
  })");
}

/// `document` with one change: the value at the JSON pointer `pointer` (RFC 6901,
/// `/solids/1/path/0/t`) replaced by the JSON text `value` (a key that is not there is added), or
/// that key removed when `value` is nullptr. The pointer's parent must exist, and so must a key
/// to remove, so that a typo in a test cannot pass as some other error.
inline json withChange(json document, const std::string& pointer, const char* value) {
  const json::json_pointer at(pointer);
  const json::json_pointer parent = at.parent_pointer();
  EXPECT_TRUE(document.contains(parent)) << "no parent for " << pointer;
  if (value == nullptr) {
    EXPECT_TRUE(document.contains(at)) << "nothing to remove at " << pointer;
    if (document.contains(at)) document.at(parent).erase(at.back());
  } else {
    document[at] = json::parse(value);
  }
  return document;
}

/// The InputError that parsing `text` as tank.json throws (a test failure if none).
inline InputError parseError(const std::string& text) {
  return test::inputErrorOf([](const std::string& t) { parseScene(t, "tank.json"); }, text);
}

/// The error is one line that names tank.json, exactly `field`, and contains `expected`.
inline void expectError(const InputError& error, const std::string& field,
                        const std::string& expected) {
  test::expectInputError(error, "tank.json", field, expected, test::ExpectedAt::RightAfterHead);
}

inline void writeFile(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

}  // namespace fluidsound::io::scene_test
