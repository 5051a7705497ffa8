// tools/run_report.h — the report.json every command run leaves: settings, stage times, results,
// peak memory and library versions (docs/cli.md lists the fields).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "acoustics/oscillator_model.h"

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
  /// Attaches a JSON document (text) under `key` of the results, e.g. a validation table.
  void resultJson(const std::string& key, const std::string& jsonText);

  /// `"complete": false` and where the command stopped (a signal); every report is complete
  /// otherwise.
  void markIncomplete(const std::string& interruptedAt);

  /// Adds peak memory and versions and returns the document.
  std::string text();

  /// text(), written by the output rule (io/output_file.h).
  /// @throws io::OutputError
  void write(const std::filesystem::path& path);

 private:
  struct Data;
  std::unique_ptr<Data> data_;
};

/// "fluidsound X.Y.Z" and the versions of the libraries it was built with, one per line.
std::string versionText();

/// Peak resident memory of this process [bytes].
double peakMemoryBytes();

}  // namespace fluidsound::tools
