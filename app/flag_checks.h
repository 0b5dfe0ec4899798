#pragma once
// CLI11 validators whose messages name the value and what is allowed; CLI11 prefixes the flag.

#include <CLI/CLI.hpp>

#include "compare/comparison_options.h"

namespace shockmap {

struct SceneFileAccess;

// The environment variable naming the database used when --db is not given.
inline constexpr const char* kDatabaseEnvironmentVariable = "SHOCKMAP_DB";

// --db FILE: the study database; without it, $SHOCKMAP_DB when set, else shockmap.db in the
// current directory. An empty value or a directory is refused, naming both sources.
void AddDatabaseFlag(CLI::App* command, std::string& database_path);

// --allow-path DIR (repeatable): a folder outside the scene's own from which its data files may
// be read.
void AddAllowPathFlag(CLI::App* command, SceneFileAccess& access);

// A finite number > lo (strict) or >= lo, and at most hi.
CLI::Validator FiniteIn(double lo, bool strict, double hi);
// A finite number > lo (strict) or >= lo.
CLI::Validator FiniteAbove(double lo, bool strict);
inline CLI::Validator Positive() { return FiniteAbove(0.0, true); }
// A finite number strictly between lo and hi, described as "in (lo, hi)".
CLI::Validator StrictlyBetween(double lo, double hi);
// A whole number written in decimal digits (an optional leading '-'), from lo to hi: checked
// on the text, so that a value out of the option's type is named instead of clamped or
// refused as unconvertible, and "0x10" is refused and "010" read as 10, not as hexadecimal or
// octal.
CLI::Validator WholeNumberIn(long long lo, long long hi);

// A value `option` contains (a whole number written in decimal digits when it takes one); the
// refusal names the value as given and option.Allowed().
CLI::Validator Within(const NumberOption& option);

// The option's flag with its help and unit, its check and, when declared, its default, which
// `target` is set to (shown by --help). Required when it has neither a default nor a rule.
template <typename T>
CLI::Option* AddDeclaredOption(CLI::App* command, const NumberOption& option, T& target) {
  if (option.default_value) target = static_cast<T>(*option.default_value);
  std::string help(option.help);
  if (!option.unit.empty()) help += " (" + std::string(option.unit) + ")";
  CLI::Option* added =
      command->add_option(std::string(option.names.flag), target, help)->check(Within(option));
  if (option.default_value) added->capture_default_str();
  if (option.whole) added->type_name("INT");
  return added;
}
CLI::Option* AddDeclaredOption(CLI::App* command, const ChoiceOption& option, std::string& target);

}  // namespace shockmap
