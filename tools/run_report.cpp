// tools/run_report.cpp — report.json (see run_report.h).
#include "tools/run_report.h"

#include <sys/resource.h>

#include <CLI/Version.hpp>
#include <nlohmann/json.hpp>

#include "io/library_versions.h"
#include "io/text_file.h"

namespace fluidsound::tools {

struct RunReport::Data {
  nlohmann::ordered_json json;
};

RunReport::RunReport(const std::string& command) : data_(std::make_unique<Data>()) {
  data_->json["format"] = "fluidsound.report/1";
  data_->json["command"] = command;
  data_->json["complete"] = true;
  data_->json["settings"] = nlohmann::ordered_json::object();
  data_->json["stages"] = nlohmann::ordered_json::object();
  data_->json["results"] = nlohmann::ordered_json::object();
}

RunReport::~RunReport() = default;

void RunReport::setting(const std::string& key, const std::string& value) {
  data_->json["settings"][key] = value;
}
void RunReport::setting(const std::string& key, double value) { data_->json["settings"][key] = value; }

void RunReport::setOscillatorModel(const acoustics::OscillatorModel& m) {
  using namespace acoustics;
  auto& j = data_->json["settings"]["oscillator_model"];
  j["polytropic"] = m.polytropic == PolytropicModel::Thermal ? "thermal" : "adiabatic";
  j["surface_tension"] = m.surfaceTension;
  j["vapour"] = m.vapour;
  j["hydrostatic"] = m.hydrostatic;
  j["damping"] = m.damping == DampingModel::Devin ? "devin" : "vandendoel";
  j["excitation"] = m.excitation == ExcitationModel::NeckCollapseJet ? "jet" : "displacement";
  if (m.excitation == ExcitationModel::InitialDisplacement) j["displacement"] = m.initialDisplacement;
  j["chirp"] = m.chirp;
  if (m.chirp) j["chirp_rise_factor"] = m.chirpRiseFactor;
}

void RunReport::stageSeconds(const std::string& stage, double seconds) {
  data_->json["stages"][stage] = {{"seconds", seconds}};
}

void RunReport::result(const std::string& key, double value) { data_->json["results"][key] = value; }
void RunReport::result(const std::string& key, const std::string& value) {
  data_->json["results"][key] = value;
}

void RunReport::resultJson(const std::string& key, const std::string& jsonText) {
  data_->json["results"][key] = nlohmann::ordered_json::parse(jsonText);
}

double peakMemoryBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;  // Linux reports kilobytes
}

std::vector<std::pair<std::string, std::string>> versions() {
  std::vector<std::pair<std::string, std::string>> list = {{"fluidsound", FLUIDSOUND_VERSION}};
  for (auto& library : io::libraryVersions()) list.push_back(std::move(library));
  list.emplace_back("cli11", CLI11_VERSION);
  return list;
}

std::string versionText() {
  const auto list = versions();
  std::string text = list.front().first + " " + list.front().second + "\n";
  for (std::size_t i = 1; i < list.size(); ++i)
    text += "  " + list[i].first + " " + list[i].second + "\n";
  return text;
}

void RunReport::markIncomplete(const std::string& interruptedAt) {
  data_->json["complete"] = false;
  data_->json["interrupted_at"] = interruptedAt;
}

nlohmann::ordered_json RunReport::document() {
  data_->json["peak_memory_bytes"] = peakMemoryBytes();
  nlohmann::ordered_json libraries = nlohmann::ordered_json::object();
  for (const auto& [name, version] : versions()) libraries[name] = version;
  data_->json["versions"] = libraries;
  return data_->json;
}

std::string RunReport::text() { return jsonFileText(document()); }

std::string jsonFileText(const nlohmann::ordered_json& document) {
  return document.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

void RunReport::write(const std::filesystem::path& path) { io::writeTextFile(path, text()); }

}  // namespace fluidsound::tools
