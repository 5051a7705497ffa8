// tests/fuzz/bubble_tracks_fast_fuzz.cpp — libFuzzer harness of io/bubble_track_fast_reader.h
// parsePlainBubbleTracks, which takes the text (its caller, parseBubbleTracks, has read the file):
// any text gives a set or std::nullopt, never an exception or a crash; a text accepted with
// `transfer` required is accepted with it optional, as the same set.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

#include "io/bubble_track_fast_reader.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using fluidsound::io::TransferValues;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto optional = fluidsound::io::parsePlainBubbleTracks(text, TransferValues::Optional);
  const auto required = fluidsound::io::parsePlainBubbleTracks(text, TransferValues::Required);
  if (required && !optional)
    fluidsound::fuzz::fail("accepted with transfer required, refused with it optional");
  if (required && *required != *optional)
    fluidsound::fuzz::fail("two different sets from one text");
  return 0;
}
