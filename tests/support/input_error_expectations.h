// tests/support/input_error_expectations.h — checks shared by the io readers' tests: the one-line
// InputError that names the file, the exact JSON path and what was expected.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "io/input_error.h"

namespace fluidsound::test {

/// The InputError that `parse(text)` throws (a test failure if none).
template <typename Parse>
io::InputError inputErrorOf(Parse parse, const std::string& text) {
  try {
    parse(text);
  } catch (const io::InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return io::InputError("", "", "");
}

/// Where `expected` must stand in the message.
enum class ExpectedAt {
  RightAfterHead,  ///< "FILE: FIELD: expected " + expected …
  Anywhere,        ///< anywhere in the message
};

/// The error is one line that names `file`, exactly `field`, and contains `expected`.
inline void expectInputError(const io::InputError& error, const std::string& file, const std::string& field,
                             const std::string& expected, ExpectedAt where) {
  const std::string message = error.what();
  EXPECT_EQ(error.file(), file) << message;
  EXPECT_EQ(error.field(), field) << message;
  const std::string head = file + ": " + (field.empty() ? "" : field + ": ") + "expected ";
  EXPECT_TRUE(message.starts_with(head)) << message << "\n does not start with: " << head;
  const std::string wanted = where == ExpectedAt::RightAfterHead ? head + expected : expected;
  EXPECT_NE(message.find(wanted), std::string::npos) << message << "\n lacks: " << wanted;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

}  // namespace fluidsound::test
