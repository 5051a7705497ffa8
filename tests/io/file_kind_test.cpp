// tests/io/file_kind_test.cpp — the words of the errors that refuse what is not a regular file.
#include <gtest/gtest.h>

#include <filesystem>

#include "io/file_kind.h"

namespace fluidsound::io {
namespace {

using std::filesystem::file_type;

// Claim: every kind the input and output rules refuse has its own words, used by every message
// (docs/cli.md: "found a FIFO", "it is a folder"), and a kind without words is still named.
TEST(FileKind, EveryKindHasItsWords) {
  EXPECT_EQ(fileKindName(file_type::regular), "a regular file");
  EXPECT_EQ(fileKindName(file_type::directory), "a folder");
  EXPECT_EQ(fileKindName(file_type::fifo), "a FIFO");
  EXPECT_EQ(fileKindName(file_type::character), "a character device");
  EXPECT_EQ(fileKindName(file_type::block), "a block device");
  EXPECT_EQ(fileKindName(file_type::socket), "a socket");
  EXPECT_EQ(fileKindName(file_type::symlink), "a symbolic link");
  EXPECT_EQ(fileKindName(file_type::not_found), "no such file");
  EXPECT_EQ(fileKindName(file_type::unknown), "not a regular file");
}

}  // namespace
}  // namespace fluidsound::io
