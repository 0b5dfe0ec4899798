#pragma once
// How every command reports the error that ends it: one line on stderr and its exit code
// (app/exit_codes.h).

#include <exception>

namespace shockmap {

// Prints `failure` (an exception in flight) as the command's last word and returns the exit
// code it ends with: 2 for input the user can fix (InputError, DbError), 1 for a plot error or
// an internal one. A CLI::RuntimeError carries a verdict already printed: only its code is
// returned.
int ReportFailure(const std::exception_ptr& failure);

}  // namespace shockmap
