// tests/io/output_file_test.cpp — the output rule: regular files and new names are replaced
// atomically, symlinks replace their regular target and stay, devices and FIFOs are written
// through, and folders, sockets, block devices and links to nothing are refused untouched.
#include "io/output_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "support/special_files.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

using test::fileBytes;
using test::TempFolder;

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

/// The error of writing `bytes` to `path`, or "" if it was written.
std::string writeError(const fs::path& path, const std::string& bytes) {
  try {
    writeOutputFile(path, bytes);
    return {};
  } catch (const OutputError& error) {
    return error.what();
  }
}

TEST(OutputFile, NewNameAndRegularFileAreReplacedWhole) {
  TempFolder folder;
  const fs::path path = folder.path() / "out.txt";
  EXPECT_EQ(resolveOutput(path).kind, OutputKind::Replace);
  writeOutputFile(path, "first");
  writeOutputFile(path, "second");
  EXPECT_EQ(fileBytes(path), "second");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});  // no temporary left
}

TEST(OutputFile, SymlinkToARegularFileReplacesTheTargetAndTheLinkStays) {
  TempFolder folder;
  fs::create_directory(folder.path() / "real");
  const fs::path target = folder.path() / "real" / "render.txt", link = folder.path() / "link.txt";
  writeText(target, "old");
  fs::create_symlink("real/render.txt", link);
  const OutputTarget resolved = resolveOutput(link);
  EXPECT_EQ(resolved.kind, OutputKind::Replace);
  EXPECT_EQ(resolved.file, fs::canonical(target));
  writeOutputFile(link, "new");
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(fs::read_symlink(link), "real/render.txt");
  EXPECT_EQ(fileBytes(target), "new");
  std::vector<std::string> inReal;
  for (const auto& entry : fs::directory_iterator(folder.path() / "real"))
    inReal.push_back(entry.path().filename().string());
  EXPECT_EQ(inReal, std::vector<std::string>{"render.txt"});  // the temporary went beside it, and away
}

TEST(OutputFile, RefusedKindsAreLeftAsTheyWere) {
  TempFolder folder;
  const fs::path dir = folder.path() / "dir", dangling = folder.path() / "dangling.txt";
  const fs::path socket = folder.path() / "sock", block = folder.path() / "block";
  fs::create_directory(dir);
  fs::create_symlink("missing.txt", dangling);
  struct Case {
    fs::path path;
    const char* reason;
  };
  std::vector<Case> cases{{dir, "it is a folder"}, {dangling, "symbolic link to nothing"}};
  if (test::makeSocketFile(socket)) cases.push_back({socket, "it is a socket"});
  if (test::makeBlockDevice(block)) cases.push_back({block, "it is a block device"});
  for (const Case& c : cases) {
    const std::string message = writeError(c.path, "bytes");
    EXPECT_TRUE(message.starts_with(c.path.string() + ": cannot write: ")) << message;
    EXPECT_NE(message.find(c.reason), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
  EXPECT_TRUE(fs::is_directory(dir) && fs::is_empty(dir));
  EXPECT_TRUE(fs::is_symlink(dangling));
  EXPECT_FALSE(fs::exists(folder.path() / "missing.txt"));  // a link to nothing makes nothing
  if (fs::exists(fs::symlink_status(socket))) {
    EXPECT_TRUE(fs::is_socket(socket));
  }
  if (fs::exists(fs::symlink_status(block))) {
    EXPECT_TRUE(fs::is_block_file(block));
  }
}

TEST(OutputFile, NullDeviceIsWrittenThroughAndStaysADevice) {
  TempFolder folder;
  const fs::path null = folder.path() / "null";
  if (!test::makeCharacterDevice(null, test::kMemoryMajor, test::kNullMinor))
    GTEST_SKIP() << "mknod needs CAP_MKNOD";
  EXPECT_EQ(resolveOutput(null).kind, OutputKind::WriteThrough);
  EXPECT_EQ(writeError(null, std::string(100000, 'x')), "");
  EXPECT_TRUE(fs::is_character_file(null));
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"null"});
}

TEST(OutputFile, FullDeviceIsOneLineWriteErrorAndLeavesNothing) {
  TempFolder folder;
  const fs::path full = folder.path() / "full";
  if (!test::makeCharacterDevice(full, test::kMemoryMajor, test::kFullMinor))
    GTEST_SKIP() << "mknod needs CAP_MKNOD";
  EXPECT_EQ(writeError(full, "bytes"), full.string() + ": cannot write: No space left on device");
  EXPECT_TRUE(fs::is_character_file(full));
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"full"});
}

TEST(OutputFile, FifoGetsTheBytesWithoutATemporary) {
  TempFolder folder;
  const fs::path fifo = folder.path() / "pipe";
  ASSERT_TRUE(test::makeFifo(fifo));
  EXPECT_EQ(resolveOutput(fifo).kind, OutputKind::WriteThrough);
  test::FifoReader reader(fifo);
  const std::string bytes(200000, 'b');  // more than a pipe buffer (64 KiB): written in parts
  writeOutputFile(fifo, bytes);
  EXPECT_EQ(reader.bytes(), bytes);
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"pipe"});
}

TEST(OutputFile, DashIsStandardOutput) {
  EXPECT_TRUE(isStandardOutput("-"));
  EXPECT_FALSE(isStandardOutput("./-"));  // a file named "-" is still reachable this way
  EXPECT_EQ(resolveOutput("-").kind, OutputKind::StandardOutput);
  EXPECT_EQ(resolveOutput("./-").kind, OutputKind::Replace);
}

TEST(OutputFile, BatchWritesNothingWhenOneOutputIsRefused) {
  TempFolder folder;
  fs::create_directory(folder.path() / "dir");
  writeText(folder.path() / "kept.txt", "old");
  {
    OutputBatch batch;
    batch.add(folder.path() / "kept.txt", "new");
    batch.add(folder.path() / "fresh.txt", "new");
    EXPECT_THROW(batch.add(folder.path() / "dir", "new"), OutputError);
  }  // destroyed without commit()
  EXPECT_EQ(fileBytes(folder.path() / "kept.txt"), "old");
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"dir", "kept.txt"}));
}

TEST(OutputFile, BatchWithAFullDeviceRenamesNothing) {
  TempFolder folder;
  const fs::path full = folder.path() / "full";
  if (!test::makeCharacterDevice(full, test::kMemoryMajor, test::kFullMinor))
    GTEST_SKIP() << "mknod needs CAP_MKNOD";
  {
    OutputBatch batch;
    batch.add(folder.path() / "report.json", "{}");
    batch.add(full, "audio");
    EXPECT_THROW(batch.commit(), OutputError);
  }
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"full"});  // no report of what failed
}

}  // namespace
}  // namespace fluidsound::io
