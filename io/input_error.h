// io/input_error.h — the one exception type for bad input files: it names the file, the field
// (JSON path, e.g. `bubbles[3].radius`), what was expected and what was found.
#pragma once

#include <stdexcept>
#include <string>

namespace fluidsound::io {

/// @brief A file that cannot be used as input. what() is one line:
///        `FILE: FIELD: expected EXPECTED, found FOUND` (FIELD and found omitted when empty).
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string field, std::string expected, std::string found = {});

  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  std::string file_, field_, expected_, found_;
};

/// @brief An output that cannot be written (unwritable folder, full disk). what() names the file.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace fluidsound::io
