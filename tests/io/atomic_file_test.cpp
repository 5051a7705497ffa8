// tests/io/atomic_file_test.cpp — an AtomicFile's target appears whole on commit() or not at all.
#include "io/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>  // access

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "support/file_bytes.h"
#include "support/special_files.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

namespace fs = std::filesystem;

using test::TempFolder;

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  ASSERT_TRUE(out.good()) << path;
}

using test::fileBytes;

TEST(AtomicFile, TargetAppearsOnlyAfterCommit) {
  TempFolder folder;
  const fs::path target = folder.path() / "out.txt";
  AtomicFile file(target);
  // The temporary is a hidden file beside the target, so the rename never crosses file systems.
  EXPECT_EQ(file.temporaryPath().parent_path(), folder.path());
  EXPECT_TRUE(file.temporaryPath().filename().string().starts_with(".out.txt.tmp-"))
      << file.temporaryPath();
  EXPECT_EQ(file.targetPath(), target);
  writeText(file.temporaryPath(), "whole");
  EXPECT_FALSE(fs::exists(target));
  file.commit();
  EXPECT_EQ(fileBytes(target), "whole");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, UncommittedTemporaryIsRemoved) {
  TempFolder folder;
  {
    AtomicFile file(folder.path() / "out.txt");
    writeText(file.temporaryPath(), "half");
    EXPECT_EQ(folder.entries().size(), 1u);
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, FailureBeforeCommitLeavesNothing) {
  TempFolder folder;
  try {
    AtomicFile file(folder.path() / "out.txt");
    writeText(file.temporaryPath(), "half");
    throw std::runtime_error("the writer failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, ExistingTargetIsUntouchedUntilCommit) {
  TempFolder folder;
  const fs::path target = folder.path() / "out.txt";
  writeText(target, "old");
  {
    AtomicFile file(target);
    writeText(file.temporaryPath(), "new, abandoned");
  }
  EXPECT_EQ(fileBytes(target), "old");
  AtomicFile file(target);
  writeText(file.temporaryPath(), "new");
  EXPECT_EQ(fileBytes(target), "old");
  file.commit();
  EXPECT_EQ(fileBytes(target), "new");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

TEST(AtomicFile, SimultaneousWritersGetDistinctTemporaries) {
  TempFolder folder;
  AtomicFile first(folder.path() / "out.txt");
  AtomicFile second(folder.path() / "out.txt");
  EXPECT_NE(first.temporaryPath(), second.temporaryPath());
}

TEST(AtomicFile, MissingFolderIsAnOutputErrorNamingThePath) {
  TempFolder folder;
  const fs::path target = folder.path() / "missing" / "out.txt";
  try {
    AtomicFile file(target);
    FAIL() << "no OutputError";
  } catch (const OutputError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.starts_with(target.string() + ": cannot write")) << message;
    EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(AtomicFile, FolderThatIsAFileIsAnOutputError) {
  TempFolder folder;
  writeText(folder.path() / "plain", "not a folder");
  const fs::path target = folder.path() / "plain" / "out.txt";
  try {
    AtomicFile file(target);
    FAIL() << "no OutputError";
  } catch (const OutputError& error) {
    EXPECT_TRUE(std::string(error.what()).starts_with(target.string() + ": ")) << error.what();
  }
}

TEST(AtomicFile, TargetThatIsAFolderIsAnOutputError) {
  TempFolder folder;
  fs::create_directory(folder.path() / "sub");
  EXPECT_THROW(AtomicFile(folder.path() / "sub"), OutputError);
}

TEST(AtomicFile, ReadOnlyFolderIsAnOutputError) {
  TempFolder folder;
  const fs::path readOnly = folder.path() / "read-only";
  fs::create_directory(readOnly);
  fs::permissions(readOnly, fs::perms::owner_read | fs::perms::owner_exec);
  if (::access(readOnly.c_str(), W_OK) == 0) {
    GTEST_SKIP() << "this process may write into read-only folders (running as root?)";
  }
  try {
    AtomicFile file(readOnly / "out.txt");
    FAIL() << "no OutputError";
  } catch (const OutputError& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.starts_with((readOnly / "out.txt").string() + ": cannot write")) << message;
    EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
  }
}

TEST(AtomicFile, NeverRenamesOntoAFifoOrThroughALinkToNothing) {
  // Replacing is only for regular files and new names (io/output_file.h): a FIFO is written
  // through by writeOutputFile, never renamed over; a link to nothing does not make its target.
  TempFolder folder;
  const fs::path fifo = folder.path() / "pipe", dangling = folder.path() / "link.txt";
  ASSERT_TRUE(test::makeFifo(fifo));
  fs::create_symlink("missing.txt", dangling);
  EXPECT_THROW(AtomicFile{fifo}, OutputError);
  EXPECT_THROW(AtomicFile{dangling}, OutputError);
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_symlink(dangling));
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"link.txt", "pipe"}));
}

TEST(AtomicFile, SymlinkTargetIsReplacedAndTheLinkStays) {
  TempFolder folder;
  const fs::path target = folder.path() / "real.txt", link = folder.path() / "link.txt";
  writeText(target, "old");
  fs::create_symlink("real.txt", link);
  AtomicFile file(link);
  EXPECT_EQ(file.targetPath(), fs::canonical(target));
  writeText(file.temporaryPath(), "new");
  file.commit();
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(fileBytes(target), "new");
}

}  // namespace
}  // namespace fluidsound::io
