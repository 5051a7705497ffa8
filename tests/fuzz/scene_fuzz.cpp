// tests/fuzz/scene_fuzz.cpp — libFuzzer harness of io/scene_file.h readScene: any file is a
// scene or a one-line io::InputError; anything else escaping (another exception, a crash, a
// sanitizer report, a hang, a huge allocation) is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/input_error.h"
#include "io/scene_file.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

/// A closed unit cube (OBJ), the mesh the seed scenes name (`"mesh": "cube.obj"`): the reader
/// requires a named mesh to exist and be readable, so without it every scene with a mesh would
/// stop at that check.
constexpr std::string_view unitCube =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

const fluidsound::fuzz::InputFile& sceneInput() {
  static const fluidsound::fuzz::InputFile input("fuzz.scene.json");
  static const bool cubeWritten = (input.writeBeside("cube.obj", unitCube), true);
  (void)cubeWritten;
  return input;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fluidsound::fuzz::InputFile& input = sceneInput();
  const std::filesystem::path& path = input.write(data, size);
  try {
    (void)fluidsound::io::readScene(path);
  } catch (const fluidsound::io::InputError& error) {
    fluidsound::fuzz::requireOneLineNaming(error, path.string());
  } catch (const fluidsound::io::OutputError& error) {
    fluidsound::fuzz::requireOneLineNaming(error, path.string());
  }
  return 0;
}
