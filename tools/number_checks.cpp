// tools/number_checks.cpp — see number_checks.h.
#include "tools/number_checks.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>

namespace fluidsound::tools {
namespace {

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", value);
  return text;
}

/// A check that parses the option's text as a double and accepts it when it is finite and
/// `accepts` it; otherwise the message "expected a finite number EXPECTED, found TEXT".
CLI::Validator finiteCheck(std::string expected, std::function<bool(double)> accepts) {
  const std::string description = "finite number " + expected;
  return CLI::Validator(
      [expected = std::move(expected),
       accepts = std::move(accepts)](std::string& text) -> std::string {
        double value = 0.0;
        const bool parsed = CLI::detail::lexical_cast(text, value);
        if (parsed && std::isfinite(value) && accepts(value)) return {};
        return "expected a finite number " + expected + ", found " +
               (text.empty() ? "nothing" : text);
      },
      description);
}

}  // namespace

CLI::Validator finiteRange(double min, double max) {
  return finiteCheck("from " + shortNumber(min) + " to " + shortNumber(max),
                     [min, max](double v) { return v >= min && v <= max; });
}

CLI::Validator finitePositive() {
  return finiteCheck("> 0", [](double v) { return v > 0.0; });
}

CLI::Validator finiteNonNegative() {
  return finiteCheck(">= 0", [](double v) { return v >= 0.0; });
}

}  // namespace fluidsound::tools
