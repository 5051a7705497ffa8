// tests/io/modal_model_file_test.cpp — a body's modal model cached on disk (docs/solids.md, Cache):
// the same bits back, a damaged or foreign file ignored, a cache path that is not a regular file
// left alone.
#include "io/modal_model_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "acoustics/modal/modal_analysis.h"
#include "support/special_files.h"
#include "support/temp_folder.h"

namespace fluidsound::io {
namespace {

const acoustics::ModalModel& barModel() {
  static const acoustics::ModalModel model = [] {
    acoustics::ModalSettings settings;
    settings.maxModes = 6;
    return acoustics::analyseModes(acoustics::voxelBox({0.2, 0.02, 0.01}, 0.01), *acoustics::findSolidMaterial("steel"),
                                   settings);
  }();
  return model;
}

TEST(ModalModelFile, RoundTripKeepsEveryBit) {
  const std::string bytes = encodeModalModel(barModel(), 42);
  const std::optional<acoustics::ModalModel> back = decodeModalModel(bytes, 42);
  ASSERT_TRUE(back);
  EXPECT_TRUE(*back == barModel());
}

TEST(ModalModelFile, ForeignOrDamagedBytesAreNotAModel) {
  const std::string bytes = encodeModalModel(barModel(), 42);
  EXPECT_FALSE(decodeModalModel(bytes, 43));                              // another key's
  EXPECT_FALSE(decodeModalModel(bytes.substr(0, bytes.size() - 1), 42));  // cut short
  EXPECT_FALSE(decodeModalModel(bytes + "x", 42));                        // something after it
  std::string header = bytes;
  header[3] = 'X';
  EXPECT_FALSE(decodeModalModel(header, 42));
  EXPECT_FALSE(decodeModalModel("", 42));
}

TEST(ModalModelFile, CacheIsWrittenReadAndNeverReplacesWhatIsNotARegularFile) {
  test::TempFolder folder;
  const auto cache = folder.path() / "modes";
  EXPECT_FALSE(readCachedModes(cache, 7));
  EXPECT_FALSE(writeCachedModes(cache, 7, barModel()));  // no problem: written (folder made)
  const auto read = readCachedModes(cache, 7);
  ASSERT_TRUE(read);
  EXPECT_TRUE(*read == barModel());
  // A damaged file is ignored (and replaced by the next write).
  std::ofstream(modalCacheFile(cache, 7), std::ios::trunc) << "fluidsound.modes/1\n";
  EXPECT_FALSE(readCachedModes(cache, 7));
  EXPECT_FALSE(writeCachedModes(cache, 7, barModel()));
  EXPECT_TRUE(readCachedModes(cache, 7));
  // A FIFO and a folder where the cache file would go: left alone, reported.
  ASSERT_TRUE(test::makeFifo(modalCacheFile(cache, 8)));
  const auto fifo = writeCachedModes(cache, 8, barModel());
  ASSERT_TRUE(fifo);
  EXPECT_NE(fifo->find("not a regular file"), std::string::npos) << *fifo;
  EXPECT_TRUE(std::filesystem::is_fifo(modalCacheFile(cache, 8)));
  EXPECT_FALSE(readCachedModes(cache, 8));
  std::filesystem::create_directory(modalCacheFile(cache, 9));
  EXPECT_TRUE(writeCachedModes(cache, 9, barModel()));
  EXPECT_TRUE(std::filesystem::is_directory(modalCacheFile(cache, 9)));
}

}  // namespace
}  // namespace fluidsound::io
