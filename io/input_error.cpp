// io/input_error.cpp — composes the one-line messages of InputError.
#include "io/input_error.h"

#include <utility>

namespace fluidsound::io {
namespace {

/// Replaces control characters (newlines, tabs, …) by spaces, so what() stays on one line even
/// when a part quotes text from a file or a library message.
std::string oneLine(std::string text) {
  for (char& c : text) {
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  }
  return text;
}

/// `FILE: FIELD: expected EXPECTED, found FOUND`; an empty file, field or found is left out.
std::string composeMessage(const std::string& file, const std::string& field,
                           const std::string& expected, const std::string& found) {
  std::string message;
  if (!file.empty()) message += file + ": ";
  if (!field.empty()) message += field + ": ";
  message += "expected " + expected;
  if (!found.empty()) message += ", found " + found;
  return oneLine(std::move(message));
}

}  // namespace

InputError::InputError(std::string file, std::string field, std::string expected, std::string found)
    : std::runtime_error(composeMessage(file, field, expected, found)),
      file_(std::move(file)),
      field_(std::move(field)),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

}  // namespace fluidsound::io
