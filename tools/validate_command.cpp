// tools/validate_command.cpp — `fluidsound validate` (see validate_command.h).
#include "tools/validate_command.h"

#include <cmath>
#include <cstdio>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "acoustics/analysis/validation.h"
#include "io/text_file.h"
#include "tools/progress_display.h"
#include "tools/number_checks.h"
#include "tools/run_report.h"

namespace fluidsound::tools {

CLI::App* addValidateCommand(CLI::App& app, ValidateOptions& o) {
  CLI::App* c = app.add_subcommand("validate", "analytic bubble-acoustics report; exit 1 on any failure");
  c->add_option("--rate", o.sampleRate, "sample rate in Hz (default 48000)")->check(finiteRange(44100.0, 192000.0));
  c->add_option("--report", o.report, "also write the table as a report JSON");
  addOscillatorModelOptions(*c, o.model);
  addCommonOptions(*c, o.common);
  return c;
}

int runValidateCommand(const ValidateOptions& o) {
  if (!o.report.empty()) io::requireWritableFolder(o.report);
  acoustics::SynthesisSettings settings;
  settings.sampleRate = o.sampleRate;
  settings.model = o.model;
  std::vector<acoustics::ValidationRow> rows;
  {
    ProgressDisplay progress("validate", 1.0, "checks", o.common.quiet);
    rows = acoustics::validateBubbleAcoustics(settings, [&](double f) { progress.update(f); });
  }
  std::printf("%-44s %-26s %14s %14s %12s %-13s %s\n", "check", "reference", "measured", "expected",
              "error", "unit", "result");
  int failures = 0;
  nlohmann::ordered_json table = nlohmann::ordered_json::array();
  for (const acoustics::ValidationRow& r : rows) {
    const double error = r.absolute ? std::fabs(r.measured - r.expected)
                                    : std::fabs(r.measured - r.expected) / std::fabs(r.expected);
    char errorText[40], tolText[40];
    if (r.absolute) {
      std::snprintf(errorText, sizeof errorText, "%.3g", error);
      std::snprintf(tolText, sizeof tolText, "<= %.3g", r.tolerance);
    } else {
      std::snprintf(errorText, sizeof errorText, "%.4f%%", 100.0 * error);
      std::snprintf(tolText, sizeof tolText, "<= %g%%", 100.0 * r.tolerance);
    }
    std::printf("%-44s %-26s %14.7g %14.7g %12s %-13s %s (%s)%s%s\n", r.check.c_str(), r.reference.c_str(),
                r.measured, r.expected, errorText, r.unit.c_str(), r.pass ? "pass" : "FAIL", tolText,
                r.note.empty() ? "" : " ", r.note.c_str());
    failures += r.pass ? 0 : 1;
    table.push_back({{"check", r.check}, {"reference", r.reference}, {"measured", r.measured},
                     {"expected", r.expected}, {"tolerance", r.tolerance}, {"absolute", r.absolute},
                     {"unit", r.unit}, {"pass", r.pass}});
    if (!r.note.empty()) table.back()["note"] = r.note;
  }
  if (failures == 0) std::printf("validation: all %zu checks within tolerance\n", rows.size());
  else std::printf("validation: %d of %zu checks outside tolerance\n", failures, rows.size());
  if (!o.report.empty()) {
    RunReport report("validate");
    report.setting("sample_rate", o.sampleRate);
    report.setOscillatorModel(o.model);
    report.resultJson("rows", table.dump());
    report.result("failures", failures);
    report.write(o.report);
  }
  return failures == 0 ? kExitSuccess : kExitValidationFailed;
}

}  // namespace fluidsound::tools
