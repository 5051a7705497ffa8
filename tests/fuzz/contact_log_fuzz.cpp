// tests/fuzz/contact_log_fuzz.cpp — libFuzzer harness of io/contact_log_file.h decodeContactLog:
// any bytes are a contact log or a one-line io::InputError naming the file; a log accepted is
// written back to the same bytes (the format has one encoding) and read back as the same log.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "io/contact_log_file.h"
#include "io/input_error.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const std::string kFile = "fuzz.contacts.bin";
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  std::optional<fluidsound::sim::ContactLog> log;
  try {
    log = fluidsound::io::decodeContactLog(bytes, kFile);
  } catch (const fluidsound::io::InputError& error) {
    fluidsound::fuzz::requireOneLineNaming(error, kFile);
    return 0;
  }
  const std::string encoded = fluidsound::io::encodeContactLog(*log);
  if (encoded != bytes) fluidsound::fuzz::fail("an accepted log that encodes to other bytes");
  if (fluidsound::io::decodeContactLog(encoded, kFile) != *log)
    fluidsound::fuzz::fail("an accepted log that reads back as another");
  return 0;
}
