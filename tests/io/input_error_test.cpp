// tests/io/input_error_test.cpp — InputError's message is one line: file, field, expected, found.
#include "io/input_error.h"

#include <gtest/gtest.h>

#include <string>

namespace fluidsound::io {
namespace {

TEST(InputError, MessageNamesFileFieldExpectationAndFinding) {
  const InputError error("drip.json", "bubbles[3].radius", "a number > 0 (metres)", "-0.001");
  EXPECT_STREQ(error.what(),
               "drip.json: bubbles[3].radius: expected a number > 0 (metres), found -0.001");
  EXPECT_EQ(error.file(), "drip.json");
  EXPECT_EQ(error.field(), "bubbles[3].radius");
  EXPECT_EQ(error.expected(), "a number > 0 (metres)");
  EXPECT_EQ(error.found(), "-0.001");
}

TEST(InputError, FileLevelErrorOmitsTheField) {
  const InputError error("drip.json", "", "a readable file", "no such file");
  EXPECT_STREQ(error.what(), "drip.json: expected a readable file, found no such file");
}

TEST(InputError, EmptyFindingIsOmitted) {
  const InputError error("drip.json", "bubbles[0].radus", "one of radius, birth");
  EXPECT_STREQ(error.what(), "drip.json: bubbles[0].radus: expected one of radius, birth");
}

TEST(InputError, MessageStaysOnOneLineWhenPartsContainNewlines) {
  const InputError error("a.json", "key", "valid JSON", "line one\nline two\r\n");
  const std::string message = error.what();
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.find('\r'), std::string::npos) << message;
  EXPECT_EQ(error.found(), "line one\nline two\r\n");  // the accessor keeps the original text
}

}  // namespace
}  // namespace fluidsound::io
