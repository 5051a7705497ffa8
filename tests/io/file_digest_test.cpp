// Tests of io/file_digest.h: FNV-1a 64 against the published test vectors, and the digest of a
// file (size and hash) as run's resume check uses it.
#include "io/file_digest.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <string>

#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Reference: the FNV-1a 64-bit test vectors of Fowler, Noll & Vo (isthe.com/chongo/tech/comp/fnv,
// "FNV test suite"): "" → cbf29ce484222325 (the offset basis), "a" → af63dc4c8601ec8c,
// "foobar" → 85944171f73967e8. Exact: integer arithmetic.
TEST(FileDigest, Fnv1aMatchesThePublishedTestVectors) {
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ull);
  EXPECT_EQ(fnv1a64("bar", fnv1a64("foo")), fnv1a64("foobar"))
      << "continuing a hash = hashing the whole";
}

// A file's digest is its size and the hash of all its bytes, across the 64 KiB read pieces; one
// byte changed or one byte cut off changes it.
TEST(FileDigest, DigestOfAFileIsItsSizeAndTheHashOfItsBytes) {
  const test::TempFolder folder;
  std::string bytes(200000, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 7919) % 251);
  writeBytes(folder.path() / "frame.vdb", bytes);
  const std::optional<FileDigest> digest = digestOfFile(folder.path() / "frame.vdb");
  ASSERT_TRUE(digest);
  EXPECT_EQ(digest->bytes, bytes.size());
  EXPECT_EQ(digest->fnv1a, fnv1a64(bytes));

  std::string edited = bytes;
  edited[123456] ^= 1;
  writeBytes(folder.path() / "edited.vdb", edited);
  EXPECT_NE(digestOfFile(folder.path() / "edited.vdb"), digest);
  writeBytes(folder.path() / "cut.vdb", bytes.substr(0, bytes.size() - 1));
  EXPECT_NE(digestOfFile(folder.path() / "cut.vdb"), digest);
}

// Only a regular file has a digest: a missing name, a folder and a FIFO have none (a FIFO is not
// opened, so the call cannot block).
TEST(FileDigest, OnlyARegularFileHasADigest) {
  const test::TempFolder folder;
  EXPECT_FALSE(digestOfFile(folder.path() / "missing.wav"));
  EXPECT_FALSE(digestOfFile(folder.path()));
  const fs::path fifo = folder.path() / "fifo.wav";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_FALSE(digestOfFile(fifo));
}

TEST(FileDigest, HexDigitsRoundTrip) {
  EXPECT_EQ(hexDigits(0x0123456789abcdefull), "0123456789abcdef");
  EXPECT_EQ(parseHexDigits("0123456789ABCDEF"), 0x0123456789abcdefull);
  EXPECT_FALSE(parseHexDigits("0123456789abcde"));   // 15 digits
  EXPECT_FALSE(parseHexDigits("0123456789abcdeg"));  // not hex
}

}  // namespace
}  // namespace fluidsound::io
