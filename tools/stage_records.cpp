// tools/stage_records.cpp — OUTDIR/stages.json (see stage_records.h; docs/cli.md, `run`).
#include "tools/stage_records.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <utility>

#include "io/text_file.h"
#include "tools/run_report.h"

namespace fluidsound::tools {
namespace {

using Json = nlohmann::ordered_json;
constexpr const char* kFormatTag = "fluidsound.stages/2";
constexpr const char* kFileName = "stages.json";

Json digestsJson(const FileDigests& digests) {
  Json out = Json::object();
  for (const auto& [file, d] : digests)
    out[file] = {{"bytes", d.bytes}, {"fnv1a64", io::hexDigits(d.fnv1a)}};
  return out;
}

/// The digests of a record's `reads` or `artefacts`; none if any entry is malformed.
std::optional<FileDigests> parseDigests(const Json& object) {
  if (!object.is_object()) return std::nullopt;
  FileDigests out;
  for (const auto& [file, entry] : object.items()) {
    if (!entry.is_object() || !entry.contains("bytes") || !entry["bytes"].is_number_unsigned() ||
        !entry.contains("fnv1a64") || !entry["fnv1a64"].is_string())
      return std::nullopt;
    const auto hash = io::parseHexDigits(entry["fnv1a64"].get<std::string>());
    if (!hash) return std::nullopt;
    out[file] = {entry["bytes"].get<std::uintmax_t>(), *hash};
  }
  return out;
}

std::optional<StageRecord> parseRecord(const Json& object) {
  if (!object.is_object() || !object.contains("input_hash") || !object["input_hash"].is_string())
    return std::nullopt;
  const auto reads = parseDigests(object.value("reads", Json::object()));
  const auto artefacts = parseDigests(object.value("artefacts", Json::object()));
  if (!reads || !artefacts) return std::nullopt;
  return StageRecord{object["input_hash"].get<std::string>(), *reads, *artefacts};
}

std::string describeChange(const std::string& file, const io::FileDigest& now,
                           const io::FileDigest& recorded) {
  if (now.bytes != recorded.bytes)
    return file + " changed: " + std::to_string(now.bytes) + " bytes, recorded " +
           std::to_string(recorded.bytes);
  return file + " changed: same size, other contents";
}

}  // namespace

StageRecords::StageRecords(std::filesystem::path outdir, std::vector<std::string> order,
                           bool ignore)
    : outdir_(std::move(outdir)), order_(std::move(order)) {
  const std::filesystem::path path = outdir_ / kFileName;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return;
  if (ignore) {  // the records on disk are dropped at the first forget()
    ignoredOnDisk_ = true;
    return;
  }
  std::ifstream in(path, std::ios::binary);
  const Json root =
      Json::parse(std::string(std::istreambuf_iterator<char>(in), {}), nullptr, false);
  if (!root.is_object() || !root.contains("format") || root["format"] != kFormatTag ||
      !root.contains("stages") || !root["stages"].is_object())
    return;
  for (const std::string& stage : order_)
    if (root["stages"].contains(stage))
      if (auto record = parseRecord(root["stages"][stage])) records_[stage] = std::move(*record);
}

std::optional<io::FileDigest> StageRecords::currentDigest(const std::string& file) {
  const auto found = current_.find(file);
  if (found != current_.end()) return found->second;
  return current_[file] = io::digestOfFile(outdir_ / file);
}

std::optional<io::FileDigest> StageRecords::inputDigest(const std::string& stage,
                                                        const std::string& file) {
  const std::optional<io::FileDigest> now = currentDigest(file);
  if (!now) return std::nullopt;
  const auto self = std::find(order_.begin(), order_.end(), stage);
  for (auto earlier = self; earlier != order_.begin();) {
    const std::optional<io::FileDigest> made = recordedArtefact(*--earlier, file);
    if (!made) continue;
    const std::vector<io::FileDigest> accepted = acceptedVersions(*earlier, file);
    return std::find(accepted.begin(), accepted.end(), *now) != accepted.end() ? made : now;
  }
  return now;
}

std::optional<io::FileDigest> StageRecords::recordedArtefact(const std::string& stage,
                                                             const std::string& file) const {
  const auto record = records_.find(stage);
  if (record == records_.end()) return std::nullopt;
  const auto artefact = record->second.artefacts.find(file);
  if (artefact == record->second.artefacts.end()) return std::nullopt;
  return artefact->second;
}

std::vector<io::FileDigest> StageRecords::acceptedVersions(const std::string& stage,
                                                           const std::string& file) const {
  std::vector<io::FileDigest> accepted{*recordedArtefact(stage, file)};
  auto later = std::find(order_.begin(), order_.end(), stage);
  for (++later; later != order_.end(); ++later) {
    const auto record = records_.find(*later);
    if (record == records_.end()) continue;
    const auto read = record->second.reads.find(file);
    const auto wrote = record->second.artefacts.find(file);
    if (read != record->second.reads.end() && wrote != record->second.artefacts.end() &&
        std::find(accepted.begin(), accepted.end(), read->second) != accepted.end())
      accepted.push_back(wrote->second);
  }
  return accepted;
}

std::string StageRecords::reasonToRun(const std::string& stage, const std::string& inputHash,
                                      const std::vector<std::string>& reads,
                                      const std::vector<std::string>& artefacts) {
  const auto found = records_.find(stage);
  if (found == records_.end()) return "no record of it completing";
  const StageRecord& record = found->second;
  if (record.inputHash != inputHash)
    return "its inputs changed (scene, meshes, cell size, models or program version)";
  const auto self = std::find(order_.begin(), order_.end(), stage);
  for (const std::string& file : reads) {
    const auto read = record.reads.find(file);
    if (read == record.reads.end()) return "its record does not list its input " + file;
    // The file as the last earlier stage that wrote it recorded it; else as it is now.
    std::optional<io::FileDigest> expected;
    for (auto earlier = self; earlier != order_.begin() && !expected;)
      expected = recordedArtefact(*--earlier, file);
    if (!expected) expected = currentDigest(file);
    if (!expected) return "its input " + file + " is missing";
    if (*expected != read->second) return "its input " + file + " changed";
  }
  for (const std::string& file : artefacts) {
    if (!record.artefacts.contains(file)) return "its record does not list " + file;
    const std::optional<io::FileDigest> now = currentDigest(file);
    if (!now) return file + " is missing";
    const std::vector<io::FileDigest> accepted = acceptedVersions(stage, file);
    if (std::find(accepted.begin(), accepted.end(), *now) == accepted.end())
      return describeChange(file, *now, accepted.back());
  }
  return {};
}

void StageRecords::forget(const std::string& stage) {
  if (records_.erase(stage) > 0 || ignoredOnDisk_) write();
}

bool StageRecords::complete(const std::string& stage, const std::string& inputHash,
                            FileDigests reads, const std::vector<std::string>& artefacts) {
  StageRecord record{inputHash, std::move(reads), {}};
  current_.clear();  // the stage may have changed any file
  for (const std::string& file : artefacts) {
    const std::optional<io::FileDigest> digest = currentDigest(file);
    if (!digest) return false;
    record.artefacts[file] = *digest;
  }
  records_[stage] = std::move(record);
  write();
  return true;
}

void StageRecords::write() {
  Json stages = Json::object();
  for (const std::string& stage : order_) {
    const auto record = records_.find(stage);
    if (record == records_.end()) continue;
    stages[stage] = {{"input_hash", record->second.inputHash},
                     {"reads", digestsJson(record->second.reads)},
                     {"artefacts", digestsJson(record->second.artefacts)}};
  }
  const Json root = {{"format", kFormatTag}, {"stages", stages}};
  io::writeTextFile(outdir_ / kFileName, jsonFileText(root));
  ignoredOnDisk_ = false;
}

}  // namespace fluidsound::tools
