// tests/support/falling_column_scene.h — a small scene the command tests run end to end: a column
// of water falling over in a 12 × 8 × 2 cell box for 0.4 s. It splashes, so it makes bubbles over
// many frames, in about a second; two listeners in air.
#pragma once

namespace fluidsound::test {

inline constexpr const char* kFallingColumnScene = R"({
  "format": "fluidsound.scene/1",
  "domain": { "min": [0, 0, 0], "max": [0.24, 0.16, 0.04], "cell": 0.02 },
  "time": { "duration": 0.4, "fps": 30 },
  "liquid": [ { "box": { "min": [0, 0, 0], "max": [0.08, 0.14, 0.04] } } ],
  "listeners": [ { "name": "left", "position": [0.06, 0.4, 0.02] },
                 { "name": "right", "position": [0.18, 0.4, 0.02] } ]
})";

}  // namespace fluidsound::test
