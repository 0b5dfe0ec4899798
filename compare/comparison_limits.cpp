#include "compare/comparison_limits.h"

#include <fmt/format.h>

#include "core/modal_basis.h"
#include "reference/reference_cost.h"

namespace shockmap {
namespace {

void CheckMeshCost(const ComparisonOptions& o, OptionSpelling s) {
  const int elements = o.n_elements > 0 ? o.n_elements : DefaultElementCount(o.r_ftrunc);
  const std::string excess = EigenBudgetExcess({BeamUnknowns(elements)}, 1);
  if (excess.empty()) return;
  if (o.n_elements > 0) {
    throw InputError(fmt::format("{}: {}: {}", kElementsOption.names.*s, elements, excess));
  }
  throw InputError(fmt::format("{}: {:g} needs {} elements by default: {}", kRftruncOption.names.*s,
                               o.r_ftrunc, elements, excess));
}

void CheckReferenceCost(const CantileverImpact& problem, const ComparisonOptions& o,
                        OptionSpelling s) {
  const std::string excess = ReferenceBudgetExcess(problem, o.reference, o.window_s);
  if (excess.empty()) return;
  throw InputError(fmt::format("{}: {:g} over the {:g} s {}: {}", kRfrefOption.names.*s,
                               o.reference.r_fref, o.window_s, kWindowOption.names.*s, excess));
}

// The step, given or resolved on the model's bounds as the run will resolve it, against the
// window: at least one step (a shorter window holds nothing to compare) and at most max_steps;
// after the mesh check, since resolving a factor builds the model.
void CheckStepCount(const CantileverImpact& problem, const ComparisonOptions& o, OptionSpelling s) {
  const bool given = o.dt.dt_s.has_value();
  const double dt_s =
      given ? *o.dt.dt_s
            : o.dt.Resolve(BuildImpactModel(problem, o.scheme, o.r_ftrunc, o.n_elements).bounds);
  const auto max_steps = TransientOptions{}.max_steps;
  if (o.window_s >= dt_s && o.window_s / dt_s <= max_steps) return;
  const std::string step =
      given ? fmt::format("{}: {:g} s", kDtOption.names.*s, dt_s)
            : fmt::format("{}: {:g} of the {} bound, {:.4g} s,", kDtFactorOption.names.*s,
                          o.dt.factor, ToString(o.dt.rule), dt_s);
  if (o.window_s < dt_s) {
    const std::string origin =
        given ? std::string(kDtOption.names.*s)
              : fmt::format("{} {:g} of the {} bound", kDtFactorOption.names.*s, o.dt.factor,
                            ToString(o.dt.rule));
    throw InputError(
        fmt::format("{}: the {:g} s window is shorter than one time step, {} s ({}): nothing to "
                    "compare; give a window of at least {} s",
                    kWindowOption.names.*s, o.window_s, dt_s, origin, dt_s));
  }
  throw InputError(fmt::format("{} over the {:g} s window is {:.3g} steps; at most {} are allowed",
                               step, o.window_s, o.window_s / dt_s, max_steps));
}

}  // namespace

void CheckComparisonAffordable(const CantileverImpact& problem, const ComparisonOptions& options,
                               OptionSpelling spelling) {
  CheckMeshCost(options, spelling);
  CheckReferenceCost(problem, options, spelling);
  CheckStepCount(problem, options, spelling);
}

}  // namespace shockmap
