#include "app/flag_checks.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <sstream>

#include "db/study_database.h"
#include "formats/scene_file.h"

namespace shockmap {

namespace {

// "" when `path` may name a database file; else why not, for a message naming its source.
std::string DatabasePathProblem(const std::string& path) {
  if (path.empty()) return "is empty; it must name a database file";
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return "names \"" + path + "\", a directory; it must name a database file";
  }
  return "";
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
        return "";
      },
      description);
}

}  // namespace shockmap
