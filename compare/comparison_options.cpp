#include "compare/comparison_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "compare/comparison.h"
#include "core/input_error.h"
#include "core/modal_basis.h"

namespace shockmap {

bool NumberOption::Contains(double value) const {
  if (!std::isfinite(value) || value > high) return false;
  if (low_strict ? value <= low : value < low) return false;
  return !whole || value == std::floor(value);
}

std::string NumberOption::Allowed() const {
  if (whole) return fmt::format("a whole number from {} to {}", low, high);
  std::string allowed = fmt::format("{} {}", low_strict ? ">" : ">=", low);
  if (std::isfinite(high)) allowed += fmt::format(" and <= {}", high);
  return allowed;
}

std::string NumberOption::Refusal(double value) const {
  return fmt::format("value {} is out of range: must be {}", value, Allowed());
}

bool ChoiceOption::Contains(std::string_view value) const {
  return std::ranges::find(choices, value) != choices.end();
}

std::string ChoiceOption::Allowed() const {
  return fmt::format("one of {}", fmt::join(choices, ", "));
}

std::string ChoiceOption::Refusal(std::string_view value) const {
  return fmt::format("\"{}\" is not allowed: must be {}", value, Allowed());
}

void RequireOption(const NumberOption& option, std::string_view name, double value) {
  if (!option.Contains(value)) throw InputError(fmt::format("{}: {}", name, option.Refusal(value)));
}

void RequireOption(const ChoiceOption& option, std::string_view name, std::string_view value) {
  if (!option.Contains(value)) throw InputError(fmt::format("{}: {}", name, option.Refusal(value)));
}

namespace {

constexpr double kUnbounded = HUGE_VAL;

}  // namespace

// The defaults are those of ComparisonOptions and TimeStepRequest, which the library's own
// callers take too.
const NumberOption kRkOption{{"--rk", "rk", "rk"},
                             "",
                             "stiffness ratio R_k = k_s / K_bend",
                             std::nullopt,
                             0.0,
                             true,
                             kMaxRk};
// A study's mode axis reaches 6.3e4 f1 (mode 150); at 1e5 f1 the default mesh, 988 elements, is
// within the eigenproblem budget.
const NumberOption kRftruncOption{{"--rftrunc", "rftrunc", "rftrunc"},
                                  "",
                                  "modal truncation ratio f_trunc / f1",
                                  std::nullopt,
                                  1.0,
                                  false,
                                  1e5};
// The paper's beam has f1 = 19 Hz: a step of a second resolves nothing of its motion.
const NumberOption kDtOption{{"--dt", "dt", "dt.seconds"},
                             "s",
                             "time step (without it: --dt-factor of the --dt-rule bound)",
                             std::nullopt,
                             0.0,
                             true,
                             1.0};
// Above 1 the explicit scheme is beyond its stability bound; the implicit one is not bound.
const NumberOption kDtFactorOption{{"--dt-factor", "dt_factor", "dt.factor"},
                                   "",
                                   "time step as a factor of the bound chosen by --dt-rule",
                                   TimeStepRequest{}.factor,
                                   0.0,
                                   true,
                                   100.0};
const ChoiceOption kDtRuleOption{
    {"--dt-rule", "dt_rule", "dt.rule"},
    "bound --dt-factor applies to: paper = 1/(4 f_trunc), sharp = 2/omega_max",
    ToString(TimeStepRequest{}.rule),
    {"paper", "sharp"}};
// The reference's budget refuses long windows first, at R_k's where they cost.
const NumberOption kWindowOption{{"--window", "window_s", "window_s"},
                                 "s",
                                 "observation window",
                                 ComparisonOptions{}.window_s,
                                 0.0,
                                 true,
                                 100.0};
const ChoiceOption kSchemeOption{{"--scheme", "scheme", "scheme"},
                                 "numerical scheme",
                                 ToString(ComparisonOptions{}.scheme),
                                 {"explicit-modal", "implicit-full"}};
// A mesh of more elements has an eigenproblem beyond the budget of core/modal_basis.h.
const NumberOption kElementsOption{
    {"--elements", "elements", "n_elements"},
    "",
    "finite elements of the beam (0: enough for every retained mode)",
    static_cast<double>(ComparisonOptions{}.n_elements),
    0.0,
    false,
    static_cast<double>(kEigenBudgetElements),
    true};
// No bound above: the reference's budget (reference/reference_cost.h) refuses what costs.
const NumberOption kRfrefOption{
    {"--rfref", "rfref", ""},
    "",
    "truncation ratio f_ref / f1 the reference starts from (default: max(3000, 10 sqrt(R_k)), "
    "as studies; raised until its estimated error is below 0.02)",
    std::nullopt,
    1.0,
    false,
    kUnbounded};

std::span<const NumberOption* const> ComparisonNumberOptions() {
  static const NumberOption* const kAll[] = {&kRkOption,       &kRftruncOption, &kDtOption,
                                             &kDtFactorOption, &kWindowOption,  &kRfrefOption,
                                             &kElementsOption};
  return kAll;
}

std::span<const ChoiceOption* const> ComparisonChoiceOptions() {
  static const ChoiceOption* const kAll[] = {&kDtRuleOption, &kSchemeOption};
  return kAll;
}

}  // namespace shockmap
