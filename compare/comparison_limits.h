#pragma once
// What one comparison may cost, checked before it runs: the eigenproblem of its mesh, its
// reference and its step count. `shockmap compare` and the Python module's compare() refuse
// alike, each naming the parameter as its user spells it.

#include "compare/comparison.h"
#include "compare/comparison_options.h"

namespace shockmap {

// Throws InputError, naming the parameter, its value and the budget, when the mesh (given, or
// the default for r_ftrunc) has an eigenproblem beyond the budget (core/modal_basis.h), the
// reference is estimated beyond its own (reference/reference_cost.h), or the step over the
// window takes more steps than a run may (TransientOptions::max_steps) or none (a window
// shorter than one step). Each refusal names the option as `spelling` spells its declaration
// (compare/comparison_options.h): "--rftrunc" on the command line, "rftrunc" in Python.
// Preconditions: problem.IsValid(), options.IsValid().
void CheckComparisonAffordable(const CantileverImpact& problem, const ComparisonOptions& options,
                               OptionSpelling spelling);

}  // namespace shockmap
