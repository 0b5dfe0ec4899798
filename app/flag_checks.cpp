#include "app/flag_checks.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>

#include "db/study_database.h"
#include "formats/scene_file.h"

namespace shockmap {

namespace {

// "" when `path` may name a database file; else why not, for a message naming its source.
std::string DatabasePathProblem(const std::string& path) {
  if (path.empty()) return "is empty; it must name a database file";
  if (path == kInMemoryDatabaseName) {
    return "\":memory:\" names SQLite's database in memory, which keeps nothing once the "
           "command ends; it must name a database file (./:memory: for a file of that name)";
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return "names \"" + path + "\", a directory; it must name a database file";
  }
  return "";
}

// `text` as a double when it is one in full (a finite or infinite value, never NaN).
std::optional<double> ParsedDouble(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || std::isnan(value)) return std::nullopt;
  return value;
}

// `value` in the shortest digits that read back as it.
std::string Shortest(double value) {
  std::array<char, 32> digits{};
  const auto end = std::to_chars(digits.data(), digits.data() + digits.size(), value).ptr;
  return std::string(digits.data(), end);
}

// Whether `text` is a number whose magnitude a double does not hold, above or below.
bool BeyondDouble(const std::string& text) {
  errno = 0;
  std::strtod(text.c_str(), nullptr);
  return errno == ERANGE;
}

// `text` as a whole number when it is written in decimal digits (an optional leading '-'); one
// beyond a long long as an infinity of its sign.
std::optional<double> ParsedWholeNumber(const std::string& text) {
  const std::size_t digits = text.starts_with('-') ? 1 : 0;
  if (text.size() == digits || text.find_first_not_of("0123456789", digits) != std::string::npos) {
    return std::nullopt;
  }
  long long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc()) return digits == 1 ? -HUGE_VAL : HUGE_VAL;
  return static_cast<double>(value);
}

}  // namespace

void AddDatabaseFlag(CLI::App* command, std::string& database_path) {
  database_path = kDefaultDatabasePath;
  CLI::Option* db =
      command
          ->add_option("--db", database_path,
                       std::string("study database (SQLite), created by `study run` when "
                                   "missing; default: $") +
                           kDatabaseEnvironmentVariable + " when set, else " + kDefaultDatabasePath)
          ->type_name("FILE")
          ->check(CLI::Validator(
              [](std::string& path) {
                const std::string problem = DatabasePathProblem(path);
                return problem.empty() ? problem : "the value " + problem;
              },
              ""));
  command->parse_complete_callback([db, &database_path] {
    const char* variable = std::getenv(kDatabaseEnvironmentVariable);
    if (db->count() > 0 || variable == nullptr) return;
    const std::string problem = DatabasePathProblem(variable);
    if (!problem.empty()) {
      throw CLI::ValidationError(std::string("environment variable ") +
                                 kDatabaseEnvironmentVariable + " " + problem +
                                 " (or unset it for " + kDefaultDatabasePath + ")");
    }
    database_path = variable;
  });
}

void AddAllowPathFlag(CLI::App* command, SceneFileAccess& access) {
  command
      ->add_option("--allow-path", access.allowed_folders,
                   "folder a scene's data files (base-motion CSV) may also be read from; by "
                   "default only the scene's own folder and below (repeatable)")
      ->check(CLI::Validator(
          [](std::string& path) -> std::string {
            std::error_code ec;
            if (std::filesystem::is_directory(path, ec)) return "";
            return path +
                   (std::filesystem::exists(path, ec) ? ": not a folder" : ": no such folder");
          },
          "DIR"));
}

CLI::Validator FiniteAbove(double lo, bool strict) {
  return FiniteIn(lo, strict, std::numeric_limits<double>::max());
}

CLI::Validator FiniteIn(double lo, bool strict, double hi) {
  std::ostringstream allowed;
  allowed << "finite and " << (strict ? "> " : ">= ") << lo;
  if (hi < std::numeric_limits<double>::max()) allowed << " and <= " << hi;
  const std::string description = allowed.str();
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        char* end = nullptr;
        errno = 0;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size())
          return "value '" + text + "' is not a number";
        if (errno == ERANGE) {
          return "value " + text +
                 " is out of range: a double holds magnitudes from 2.2e-308 to 1.8e+308";
        }
        if (!std::isfinite(value) || value < lo || (strict && value == lo) || value > hi) {
          return "value " + text + " must be " + description;
        }
        text = std::to_string(value);  // CLI11 would read a leading 0 as octal.
        return "";
      },
      description);
}

CLI::Validator StrictlyBetween(double lo, double hi) {
  const std::string description = "in (" + Shortest(lo) + ", " + Shortest(hi) + ")";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const std::optional<double> value = ParsedDouble(text);
        if (!value) return "value '" + text + "' is not a number";
        if (!(*value > lo && *value < hi)) {
          return "value " + text + " must be greater than " + Shortest(lo) + " and less than " +
                 Shortest(hi);
        }
        return "";
      },
      description);
}

CLI::Validator WholeNumberIn(long long lo, long long hi) {
  const std::string description =
      "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        const std::size_t digits = text.starts_with('-') ? 1 : 0;
        if (text.size() == digits ||
            text.find_first_not_of("0123456789", digits) != std::string::npos) {
          return "value '" + text + "' must be " + description;
        }
        long long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || value < lo || value > hi) {
          return "value " + text + " must be " + description;
        }
        text = std::to_string(value);  // CLI11 would read a leading 0 as octal.
        return "";
      },
      description);
}

CLI::Validator Within(const NumberOption& option) {
  return CLI::Validator(
      [&option](std::string& text) -> std::string {
        if (!option.whole && BeyondDouble(text)) {
          return "value " + text +
                 " is out of range: a double holds magnitudes from 2.2e-308 to 1.8e+308";
        }
        const std::optional<double> value =
            option.whole ? ParsedWholeNumber(text) : ParsedDouble(text);
        if (!value) {
          return "value '" + text + "' is not " + (option.whole ? "a whole number" : "a number");
        }
        if (!option.Contains(*value)) return option.Refusal(text, *value);
        // CLI11 would read a leading 0 as octal.
        text = option.whole ? std::to_string(static_cast<long long>(*value)) : Shortest(*value);
        return "";
      },
      option.Allowed());
}

CLI::Option* AddDeclaredOption(CLI::App* command, const ChoiceOption& option, std::string& target) {
  target = option.default_value;
  // CLI::IsMember, whose description the bash completion reads (app/completion_command.cpp).
  std::vector<std::string> choices(option.choices.begin(), option.choices.end());
  return command->add_option(std::string(option.names.flag), target, std::string(option.help))
      ->capture_default_str()
      ->check(CLI::IsMember(choices));
}

}  // namespace shockmap
