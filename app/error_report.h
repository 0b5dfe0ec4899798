#pragma once
// How every command reports the error that ends it: one line on stderr and its exit code
// (app/exit_codes.h).

#include <exception>

namespace CLI {
class App;
class ParseError;
}  // namespace CLI

namespace shockmap {

// Prints `failure` (an exception in flight) as the command's last word and returns the exit
// code it ends with: 2 for input the user can fix (InputError, DbError), 1 for a plot error or
// an internal one. A CLI::RuntimeError carries a verdict already printed: only its code is
// returned.
int ReportFailure(const std::exception_ptr& failure);

// Prints the error `e` met while parsing the command line of `app` and returns its exit code:
// 0 after printing the help or version asked for, else 2. An argument no command knows is named
// first, with the option or command it most likely misspells ("unknown option --rftruc (did you
// mean --rftrunc?)"); an unknown or missing command is answered with the commands allowed.
int ReportParseError(const CLI::App& app, const CLI::ParseError& e);

}  // namespace shockmap
