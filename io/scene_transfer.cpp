// io/scene_transfer.cpp — the scene's `transfer` block (see scene_transfer.h).
#include "io/scene_transfer.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>

#include "acoustics/transfer/geometric_transfer.h"

namespace fluidsound::io {
namespace {

/// Largest loss factor η: beyond 0.1 the "small physical loss" would damp the water body itself
/// (docs/transfer.md), not only keep its resonances finite.
constexpr double kMaxLossFactor = 0.1;
constexpr std::uint64_t kMinBands = 2;

/// `first` or `second` by its JSON string; else a failure naming both, the nearer as a hint.
template <typename T>
T eitherOf(const JsonValidator& check, const nlohmann::json& value, const std::string& path,
           std::pair<std::string_view, T> first, std::pair<std::string_view, T> second) {
  std::string expected = quotedText(first.first) + " or " + quotedText(second.first);
  if (value.is_string()) {
    const std::string& text = value.get_ref<const std::string&>();
    if (text == first.first) return first.second;
    if (text == second.first) return second.second;
    const std::string suggestion = closestKey(text, {first.first, second.first}, true);
    if (!suggestion.empty()) expected += " (did you mean " + quotedText(suggestion) + "?)";
  }
  check.fail(path, expected, describe(value));
}

}  // namespace

sim::TransferSettings readTransferSettings(const JsonValidator& check,
                                           const nlohmann::json& object) {
  const std::string path = "transfer";
  check.rejectUnknownKeys(object, path, {"model", "max_bands", "loss_factor", "max_frequency",
                                         "air", "air_interval", "air_cell"});
  sim::TransferSettings s;
  if (const nlohmann::json* model = findMember(object, "model"))
    s.model = eitherOf(check, *model, memberPath(path, "model"),
                       std::pair{std::string_view("geometric"), sim::TransferModel::Geometric},
                       std::pair{std::string_view("image"), sim::TransferModel::Image});
  if (const nlohmann::json* bands = findMember(object, "max_bands")) {
    const auto limit = static_cast<std::uint64_t>(acoustics::kMaxTransferBands);
    s.maxBands = static_cast<int>(check.wholeNumber(
        *bands, memberPath(path, "max_bands"),
        "an integer from 2 to " + std::to_string(limit) + " (bands per frame)", kMinBands, limit));
  }
  if (const nlohmann::json* loss = findMember(object, "loss_factor"))
    s.lossFactor = check.number(*loss, memberPath(path, "loss_factor"),
                                "a number > 0 and <= 0.1 (the water's loss factor)",
                                [](double v) { return v > 0 && v <= kMaxLossFactor; });
  if (const nlohmann::json* limit = findMember(object, "max_frequency"))
    s.maxFrequency = check.number(*limit, memberPath(path, "max_frequency"),
                                  "a frequency > 0 and <= 100000 Hz (the geometric model's limit)",
                                  [](double v) { return v > 0 && v <= acoustics::kMaxTransferFrequency; });
  if (const nlohmann::json* air = findMember(object, "air"))
    s.air = eitherOf(check, *air, memberPath(path, "air"),
                     std::pair{std::string_view("rigid_surface"), sim::AirModel::RigidSurface},
                     std::pair{std::string_view("wave"), sim::AirModel::Wave});
  if (const nlohmann::json* interval = findMember(object, "air_interval"))
    s.airInterval = check.number(*interval, memberPath(path, "air_interval"),
                                 "a time > 0 and <= 10 s (between air solves)",
                                 [](double v) { return v > 0 && v <= 10.0; });
  if (const nlohmann::json* cell = findMember(object, "air_cell"))
    s.airCell = check.number(*cell, memberPath(path, "air_cell"),
                             "a length > 0 and <= 0.1 m (the air grid's cell)",
                             [](double v) { return v > 0 && v <= 0.1; });
  return s;
}

}  // namespace fluidsound::io
