// tools/number_checks.h — CLI11 checks for floating-point options that refuse NaN and ±inf.
// CLI::Range, CLI::PositiveNumber and CLI::NonNegativeNumber compare with < and >, which are false
// for NaN, so `--normalize nan` passed them and reached the code as a number (an internal error).
// Every floating-point option of every subcommand uses one of these instead (docs/cli.md).
#pragma once

namespace CLI {
class Validator;
}

namespace fluidsound::tools {

/// @brief A finite number in [min, max] (both inclusive). Refused (exit 2, CLI11 names the option):
///        "--normalize: expected a finite number from -120 to 0, found nan".
CLI::Validator finiteRange(double min, double max);

/// A finite number > 0: "--displacement: expected a finite number > 0, found inf".
CLI::Validator finitePositive();

/// A finite number >= 0: "--chirp-rise: expected a finite number >= 0, found -1".
CLI::Validator finiteNonNegative();

}  // namespace fluidsound::tools
