// tests/fuzz/frame_vdb_fuzz.cpp — libFuzzer harness of the VDB frame reader (io/frame_surface.h
// FrameLevelSet, the transfer stage's reader of frames/NNNN.vdb): any file loads, or is refused
// with a one-line io::InputError; a loaded surface answers a query above a point.
#include <cstddef>
#include <cstdint>

#include "acoustics/transfer/level_set_surface.h"
#include "io/frame_surface.h"
#include "io/input_error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fluidsound::fuzz::InputFile input("fuzz.vdb");
  const std::filesystem::path& path = input.write(data, size);
  try {
    const fluidsound::io::FrameLevelSet level(path);
    // A bubble 1 cm deep at the origin, gravity along −y (the seed frames hold liquid there).
    (void)fluidsound::acoustics::localSurfacePlane(level, {0.0, 0.0, 0.0}, 0.01, {0.0, 1.0, 0.0});
  } catch (const fluidsound::io::InputError& error) {
    fluidsound::fuzz::requireOneLineNaming(error, path.string());
  } catch (const fluidsound::io::OutputError& error) {
    fluidsound::fuzz::requireOneLineNaming(error, path.string());
  }
  return 0;
}
