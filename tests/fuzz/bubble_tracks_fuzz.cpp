// tests/fuzz/bubble_tracks_fuzz.cpp — libFuzzer harness of io/bubble_track_file.h
// readBubbleTracks, with `transfer` optional (the transfer stage's input) and required (synthesis):
// any file is a track set or a one-line io::InputError; a file accepted with transfer required is
// accepted with it optional, as the same set.
#include <cstddef>
#include <cstdint>
#include <optional>

#include "io/bubble_track_file.h"
#include "io/input_error.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

using fluidsound::acoustics::BubbleTrackSet;
using fluidsound::io::TransferValues;

std::optional<BubbleTrackSet> readOrRefuse(const std::filesystem::path& path,
                                           TransferValues transfer) {
  try {
    return fluidsound::io::readBubbleTracks(path, transfer);
  } catch (const fluidsound::io::InputError& error) {
    fluidsound::fuzz::requireOneLineNaming(error, path.string());
  } catch (const fluidsound::io::OutputError& error) {
    fluidsound::fuzz::requireOneLineNaming(error, path.string());
  }
  return std::nullopt;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const fluidsound::fuzz::InputFile input("fuzz.bubbles.json");
  const std::filesystem::path& path = input.write(data, size);
  const std::optional<BubbleTrackSet> optional = readOrRefuse(path, TransferValues::Optional);
  const std::optional<BubbleTrackSet> required = readOrRefuse(path, TransferValues::Required);
  if (required && !optional)
    fluidsound::fuzz::fail("accepted with transfer required, refused with it optional");
  if (required && *required != *optional)
    fluidsound::fuzz::fail("two different sets from one file");
  return 0;
}
