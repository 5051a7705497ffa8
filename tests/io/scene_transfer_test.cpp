// tests/io/scene_transfer_test.cpp — the scene's optional `transfer` block (io/scene_transfer.h;
// docs/scene.md, "transfer"): each field reaches sim::TransferSettings, an absent field leaves the
// model's default, and each bad value is one line naming tank.json, the field and what was
// expected.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "acoustics/transfer/geometric_transfer.h"
#include "io/scene_documents.h"

namespace fluidsound::io {
namespace {

using namespace scene_test;

/// minimalScene() with `transfer` set to the JSON text `block`.
json withTransfer(const char* block) { return withChange(minimalScene(), "/transfer", block); }

// Claim: every field lands in Scene::transfer as written.
TEST(SceneTransfer, EveryFieldReachesItsRecord) {
  const sim::Scene scene =
      parseScene(withTransfer(R"({"model": "image", "max_bands": 64, "loss_factor": 0.01, "max_frequency": 8000,
                                  "air": "wave", "air_interval": 0.5, "air_cell": 0.02})").dump(),
                 "tank.json");
  EXPECT_EQ(scene.transfer.model, sim::TransferModel::Image);
  EXPECT_EQ(scene.transfer.maxBands, 64);
  EXPECT_EQ(scene.transfer.lossFactor, 0.01);
  EXPECT_EQ(scene.transfer.maxFrequency, 8000.0);
  EXPECT_EQ(scene.transfer.air, sim::AirModel::Wave);
  EXPECT_EQ(scene.transfer.airInterval, 0.5);
  EXPECT_EQ(scene.transfer.airCell, 0.02);
}

// Claim: without the block, or with an empty one, the model is the image-source one (the default
// until the geometric model is ready, docs/transfer.md) and the numbers are left to the model's own
// defaults (empty in the record).
TEST(SceneTransfer, AbsentFieldsLeaveTheDefaults) {
  for (const json& document : {minimalScene(), withTransfer("{}")}) {
    const sim::Scene scene = parseScene(document.dump(), "tank.json");
    EXPECT_EQ(scene.transfer, sim::TransferSettings{});
    EXPECT_EQ(scene.transfer.model, sim::TransferModel::Image);
    EXPECT_FALSE(scene.transfer.maxBands.has_value());
    EXPECT_FALSE(scene.transfer.lossFactor.has_value());
  }
}

// Claim: the ends of each range are accepted: 2 and kMaxTransferBands bands, a loss factor of 0.1
// and a tiny positive one; a whole number written with a fraction is an integer.
TEST(SceneTransfer, TheLimitsThemselvesAreAccepted) {
  const std::string most = std::to_string(acoustics::kMaxTransferBands);
  for (const std::string& block : {std::string(R"({"max_bands": 2, "loss_factor": 0.1})"),
                                   R"({"max_bands": )" + most + R"(, "loss_factor": 1e-12})",
                                   std::string(R"({"max_bands": 8.0})")}) {
    const sim::Scene scene = parseScene(withTransfer(block.c_str()).dump(), "tank.json");
    ASSERT_TRUE(scene.transfer.maxBands.has_value()) << block;
  }
  EXPECT_EQ(parseScene(withTransfer(R"({"max_bands": 8.0})").dump(), "tank.json").transfer.maxBands,
            8);
}

/// One bad value of the block: must be rejected with exactly
/// `tank.json: FIELD: expected EXPECTED, found FOUND`.
struct TransferCase {
  const char* name;
  const char* block;  ///< JSON text of the whole `transfer` value
  std::string field, expected, found;
};

void PrintTo(const TransferCase& c, std::ostream* out) { *out << c.name; }

const std::string kBands =
    "an integer from 2 to " + std::to_string(acoustics::kMaxTransferBands) + " (bands per frame)";
const std::string kLoss = "a number > 0 and <= 0.1 (the water's loss factor)";
const std::string kLimit = "a frequency > 0 and <= 100000 Hz (the geometric model's limit)";
const std::string kModels = R"("geometric" or "image")";
const std::string kAir = R"("rigid_surface" or "wave")";

const std::vector<TransferCase> kTransferCases = {
    {"not_an_object", "[]", "transfer", "an object of transfer-model settings (docs/transfer.md)",
     "an empty array"},
    {"unknown_model", R"({"model": "nonsense"})", "transfer.model", kModels, R"("nonsense")"},
    {"misspelt_model", R"({"model": "imag"})", "transfer.model",
     kModels + R"( (did you mean "image"?))", R"("imag")"},
    {"model_number", R"({"model": 1})", "transfer.model", kModels, "1"},
    {"one_band", R"({"max_bands": 1})", "transfer.max_bands", kBands, "1"},
    {"too_many_bands", R"({"max_bands": 5000})", "transfer.max_bands", kBands, "5000"},
    {"fractional_bands", R"({"max_bands": 2.5})", "transfer.max_bands", kBands, "2.5"},
    {"bands_string", R"({"max_bands": "64"})", "transfer.max_bands", kBands, R"("64")"},
    {"zero_loss", R"({"loss_factor": 0})", "transfer.loss_factor", kLoss, "0"},
    {"loss_too_large", R"({"loss_factor": 0.2})", "transfer.loss_factor", kLoss, "0.2"},
    {"negative_loss", R"({"loss_factor": -0.001})", "transfer.loss_factor", kLoss, "-0.001"},
    {"zero_limit", R"({"max_frequency": 0})", "transfer.max_frequency", kLimit, "0"},
    {"limit_too_high", R"({"max_frequency": 200001})", "transfer.max_frequency", kLimit, "200001"},
    {"unknown_air", R"({"air": "fdtd"})", "transfer.air", kAir, R"("fdtd")"},
    {"misspelt_air", R"({"air": "wav"})", "transfer.air", kAir + R"( (did you mean "wave"?))",
     R"("wav")"},
    {"zero_air_interval", R"({"air_interval": 0})", "transfer.air_interval",
     "a time > 0 and <= 10 s (between air solves)", "0"},
    {"air_cell_too_large", R"({"air_cell": 0.5})", "transfer.air_cell",
     "a length > 0 and <= 0.1 m (the air grid's cell)", "0.5"},
    {"unknown_key", R"({"maxBands": 64})", "transfer.maxBands",
     "one of model, max_bands, loss_factor, max_frequency, air, air_interval, air_cell (did you "
     "mean 'max_bands'?)",
     "an unknown key"},
};

class SceneTransferField : public ::testing::TestWithParam<TransferCase> {};

TEST_P(SceneTransferField, IsRejectedNamingFileFieldAndExpectation) {
  const TransferCase& row = GetParam();
  const InputError error = parseError(withTransfer(row.block).dump());
  EXPECT_EQ(std::string(error.what()),
            "tank.json: " + row.field + ": expected " + row.expected + ", found " + row.found);
  EXPECT_EQ(error.field(), row.field);
}

INSTANTIATE_TEST_SUITE_P(SceneTransfer, SceneTransferField, ::testing::ValuesIn(kTransferCases),
                         [](const ::testing::TestParamInfo<TransferCase>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace fluidsound::io
