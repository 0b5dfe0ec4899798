#include "compare/reference_decision.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "reference/reference_cost.h"

namespace shockmap {
namespace {

// The quantities of the estimate a part is judged by.
std::vector<const QuantityConvergence*> QuantitiesOf(const ReferenceConvergence& c,
                                                     ReferencePart part) {
  if (part == ReferencePart::kFirstShock) return {&c.impulse};
  return {&c.tip, &c.induced_err};
}

}  // namespace

double PartEstimate(const ReferenceConvergence& c, ReferencePart part) {
  double estimate = 0.0;
  for (const QuantityConvergence* q : QuantitiesOf(c, part))
    estimate = std::max(estimate, q->error);
  return estimate;
}

bool DecidesPart(const ReferenceConvergence& c, ReferencePart part, double tolerance) {
  return PartEstimate(c, part) <= tolerance;
}

std::optional<double> ExpectedOrder(const QuantityConvergence& q) {
  return q.order ? q.order : q.progress_order;
}

std::optional<double> PredictedTruncation(const ReferenceConvergence& c, ReferencePart part,
                                          double tolerance) {
  double predicted = c.r_fref;
  for (const QuantityConvergence* q : QuantitiesOf(c, part)) {
    if (q->error <= tolerance) continue;
    const std::optional<double> order = ExpectedOrder(*q);
    if (!order) return std::nullopt;
    predicted = std::max(predicted, c.r_fref * std::pow(q->error / tolerance, 1.0 / *order));
  }
  return predicted;
}

bool ReferenceProblem::Affords(double r_fref) const {
  ReferenceOptions o = options;
  o.r_fref = r_fref;
  return ReferenceBudgetExcess(problem, o, window_s).empty();
}

bool RaiseCanDecide(const ReferenceProblem& reference, const ReferenceConvergence& c,
                    double tolerance) {
  // Before its first shock converges, a reference's orders are not yet meaningful.
  if (!DecidesPart(c, ReferencePart::kFirstShock, tolerance)) return true;
  if (DecidesPart(c, ReferencePart::kWindowTip, tolerance)) return false;
  const std::optional<double> predicted =
      PredictedTruncation(c, ReferencePart::kWindowTip, tolerance);
  return predicted && reference.Affords(*predicted);
}

std::string UndecidedPartMessage(const ReferenceProblem& reference, const ReferenceConvergence& c,
                                 ReferencePart part, double tolerance) {
  const std::string quantities =
      part == ReferencePart::kFirstShock
          ? fmt::format("first-shock impulse {:.3g}", c.impulse.error)
          : fmt::format("tip {:.3g} of the amplitude, induced Err {:.3g}", c.tip.error,
                        c.induced_err.error);
  const std::string message = fmt::format(
      "the reference's estimate on {} is {:.3g} ({}; R_fref = {:g} checked against {:g}), above "
      "scoring.reference.tolerance = {:g}; ",
      ToString(part), PartEstimate(c, part), quantities, c.r_fref, c.r_fref_check, tolerance);
  if (c.r_fref_check < c.r_fref) {  // ReferenceCheck::kCoarser: no order, no raise.
    return message + fmt::format(
                         "checked against a coarser truncation alone (scoring.reference.check = "
                         "\"coarser\"), it is not raised: R_fref above {:g} is needed",
                         c.r_fref);
  }
  const std::optional<double> predicted = PredictedTruncation(c, part, tolerance);
  if (!predicted) {
    return message + fmt::format(
                         "finer truncations did not reduce its difference: R_fref above {:g} is "
                         "needed",
                         c.r_fref_check);
  }
  return message +
         fmt::format("R_fref = {:.3g} would do by the order its truncations showed{}", *predicted,
                     reference.Affords(*predicted) ? "" : ", beyond the reference budget");
}

}  // namespace shockmap
