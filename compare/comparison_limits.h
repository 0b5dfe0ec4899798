#pragma once
// What one comparison may cost, checked before it runs: the eigenproblem of its mesh, its
// reference and its step count. `shockmap compare` and the Python module's compare() refuse
// alike, each naming the parameter as its user spells it.

#include <string>

#include "compare/comparison.h"

namespace shockmap {

// The names of the parameters in a refusal: "--rftrunc" on the command line, "rftrunc" in
// Python.
struct ComparisonParameterNames {
  std::string rftrunc;
  std::string rfref;
  std::string window;
  std::string elements;
  std::string dt;
  std::string dt_factor;
};

// Throws InputError, naming the parameter, its value and the budget, when the mesh (given, or
// the default for r_ftrunc) has an eigenproblem beyond the budget (core/modal_basis.h), the
// reference is estimated beyond its own (reference/reference_cost.h), or the step over the
// window takes more steps than a run may (TransientOptions::max_steps) or none (a window
// shorter than one step). Preconditions:
// problem.IsValid(), options.IsValid().
void CheckComparisonAffordable(const CantileverImpact& problem, const ComparisonOptions& options,
                               const ComparisonParameterNames& names);

}  // namespace shockmap
