#include "app/error_report.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "app/exit_codes.h"
#include "core/input_error.h"
#include "db/sqlite_handle.h"
#include "formats/calculix_job.h"
#include "formats/json_reader.h"
#include "formats/nearest_name.h"
#include "views/gnuplot.h"

namespace shockmap {

namespace {

// The commands given on the command line, the top one first ("shockmap", "study", "run").
std::vector<const CLI::App*> CommandsGiven(const CLI::App& app) {
  std::vector<const CLI::App*> given = {&app};
  while (!given.back()->get_subcommands().empty())
    given.push_back(given.back()->get_subcommands().back());
  return given;
}

// The commands given up to `last`, without the program's name ("study run").
std::string CommandPath(const std::vector<const CLI::App*>& given, const CLI::App* last) {
  std::string path;
  for (const CLI::App* command : given) {
    if (command->get_parent() != nullptr) path += (path.empty() ? "" : " ") + command->get_name();
    if (command == last) break;
  }
  return path;
}

std::vector<std::string> SubcommandNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* sub : command.get_subcommands({})) {
    if (!sub->get_group().empty()) names.push_back(sub->get_name());  // Not hidden.
  }
  return names;
}

std::vector<std::string> OptionNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
  }
  return names;
}

std::string Joined(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

// " (did you mean X?)" when one of `allowed` is near `given`, X in `quote`s.
std::string Suggestion(const std::string& given, const std::vector<std::string>& allowed,
                       const std::string& quote = "") {
  const auto meant = NearestName(given, allowed);
  return meant ? " (did you mean " + quote + *meant + quote + "?)" : "";
}

bool IsOption(const std::string& argument) { return argument.size() > 1 && argument[0] == '-'; }

// "study run: " before a message about the command at `path` ("" for the program itself).
std::string Where(const std::string& path) { return path.empty() ? "" : path + ": "; }

// "`shockmap study run --help`".
std::string HelpOf(const std::string& path) {
  return "`shockmap " + (path.empty() ? "" : path + " ") + "--help`";
}

// The message for the arguments the command at `path` was given and knows nothing of (quoted
// as Excerpt() shows them). A command with subcommands names the word it was given in place of
// one; otherwise an unknown option is named first (a value after it taken for its own), else
// the first argument too many.
std::string UnknownArgument(const CLI::App& command, const std::string& path,
                            const std::vector<std::string>& unknown) {
  const std::vector<std::string> commands = SubcommandNames(command);
  const auto option = std::find_if(unknown.begin(), unknown.end(), IsOption);
  if (!commands.empty() && !IsOption(unknown.front())) {
    return Where(path) + "unknown command \"" + Excerpt(unknown.front()) + "\"" +
           Suggestion(unknown.front(), commands, "\"") + "; use one of " + Joined(commands) + " (" +
           HelpOf(path) + " says what each does)";
  }
  if (option != unknown.end()) {
    const std::string name = option->substr(0, option->find('='));
    return Where(path) + "unknown option " + Excerpt(name) +
           Suggestion(name, OptionNames(command)) + "; " + HelpOf(path) + " lists the options";
  }
  return Where(path) + "unexpected argument \"" + Excerpt(unknown.front()) + "\"; " + HelpOf(path) +
         " says what it takes";
}

// What went wrong: the first argument unknown to the command given it, a command missing, or
// else CLI11's own message.
std::string ParseErrorMessage(const CLI::App& app, const CLI::ParseError& e) {
  const std::vector<const CLI::App*> given = CommandsGiven(app);
  for (const CLI::App* command : given) {
    const std::vector<std::string> unknown = command->remaining();
    if (!unknown.empty()) return UnknownArgument(*command, CommandPath(given, command), unknown);
  }
  const CLI::App& last = *given.back();
  if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr &&
      last.get_require_subcommand_min() > 0) {
    const std::string path = CommandPath(given, &last);
    return Where(path) + "a command is required, one of " + Joined(SubcommandNames(last)) + "; " +
           HelpOf(path) + " says what each does";
  }
  return e.what();
}

}  // namespace

int ReportFailure(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // A verdict already printed (criteria check, a signal).
  } catch (const InputError& e) {
    std::cerr << "shockmap: error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const DbError& e) {
    // The database named by the user is missing, foreign, corrupt, newer, locked, or the SQL
    // given is invalid or would write: all input the user can fix.
    std::cerr << "shockmap: database error: " << e.what() << '\n';
    return kExitBadInput;
  } catch (const PlotError& e) {
    std::cerr << "shockmap: plot error: " << e.what() << '\n';
    return kExitFailure;
  } catch (const CalculixError& e) {
    std::cerr << "shockmap: calculix error: " << e.what() << '\n';
    return kExitFailure;
  } catch (const std::exception& e) {
    std::cerr << "shockmap: internal error: " << e.what() << '\n';
    return kExitFailure;
  }
}

int ReportParseError(const CLI::App& app, const CLI::ParseError& e) {
  if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version.
  std::cerr << "shockmap: error: " << ParseErrorMessage(app, e) << '\n';
  return kExitBadInput;
}

}  // namespace shockmap
