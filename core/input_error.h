#pragma once
// Bad input from the user (a value, a file, a path): the command line turns it into exit code 2.
// Broken invariants are assertions, and numerical failure is a status, never this.

#include <stdexcept>

namespace shockmap {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace shockmap
