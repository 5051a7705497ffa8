// tools/run_report.h — the report.json every command run leaves: settings, stage times, results,
// peak memory and library versions (docs/cli.md lists the fields).
#pragma once

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "acoustics/bubble/oscillator_model.h"

namespace fluidsound::tools {

class RunReport {
 public:
  explicit RunReport(const std::string& command);
  ~RunReport();
  RunReport(const RunReport&) = delete;
  RunReport& operator=(const RunReport&) = delete;

  void setting(const std::string& key, const std::string& value);
  void setting(const std::string& key, double value);
  void setOscillatorModel(const acoustics::OscillatorModel& model);
  void stageSeconds(const std::string& stage, double seconds);
  void result(const std::string& key, double value);
  void result(const std::string& key, const std::string& value);
  /// Attaches a JSON document (text) under `key` of the results, e.g. a validation table.
  void resultJson(const std::string& key, const std::string& jsonText);

  /// `"complete": false` and where the command stopped (a signal); every report is complete
  /// otherwise.
  void markIncomplete(const std::string& interruptedAt);

  /// Adds peak memory and `versions` (an object: library name → version) and returns the document.
  nlohmann::ordered_json document();

  /// document() as the text of its file (jsonFileText).
  std::string text();

  /// text(), written by the output rule (io/output_file.h).
  /// @throws io::OutputError
  void write(const std::filesystem::path& path);

 private:
  struct Data;
  std::unique_ptr<Data> data_;
};

/// (name, version) of fluidsound and of every library it links (io/library_versions.h, CLI11).
std::vector<std::pair<std::string, std::string>> versions();

/// `fluidsound --version`: "fluidsound X.Y.Z", then "  NAME VERSION" per library, one per line.
std::string versionText();

/// @brief A JSON document as the text of a file we write, indented by 2: bytes that are not UTF-8
///        (a Linux file name is bytes) become U+FFFD, so the file still names its paths as well as
///        it can instead of failing after the work.
std::string jsonFileText(const nlohmann::ordered_json& document);

/// Peak resident memory of this process [bytes].
double peakMemoryBytes();

}  // namespace fluidsound::tools
