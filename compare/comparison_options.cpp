#include "compare/comparison_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "compare/comparison_limits.h"
#include "core/input_error.h"

namespace shockmap {

bool NumberOption::Contains(double value) const {
  if (!std::isfinite(value) || value > high) return false;
  if (low_strict ? value <= low : value < low) return false;
  return !whole || value == std::floor(value);
}

std::string NumberOption::Allowed() const {
  if (whole) return fmt::format("a whole number from {:g} to {:g}", low, high);
  std::string allowed = fmt::format("{} {:g}", low_strict ? ">" : ">=", low);
  if (std::isfinite(high)) allowed += fmt::format(" and <= {:g}", high);
  return allowed;
}

std::string NumberOption::Refusal(double value) const {
  return Refusal(fmt::format("{}", value), value);
}

std::string NumberOption::Refusal(std::string_view shown, double value) const {
  std::string refusal = fmt::format("value {} is out of range: must be {}", shown, Allowed());
  if (beyond_high != nullptr && value > high) {
    if (const std::string why = beyond_high(value); !why.empty()) refusal += ": " + why;
  }
  return refusal;
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

// The option of `options` spelled `name`, or nullptr.
template <typename Option>
const Option* Spelled(std::span<const Option* const> options, std::string_view name,
                      OptionSpelling spelling) {
  for (const Option* o : options) {
    if (o->names.*spelling == name) return o;
  }
  return nullptr;
}

}  // namespace

const NumberOption* ComparisonNumberOption(std::string_view name, OptionSpelling spelling) {
  return Spelled(ComparisonNumberOptions(), name, spelling);
}

const ChoiceOption* ComparisonChoiceOption(std::string_view name, OptionSpelling spelling) {
  return Spelled(ComparisonChoiceOptions(), name, spelling);
}

ComparisonRequest ComparisonAsked(const GivenOptions& given, OptionSpelling spelling) {
  ComparisonRequest request;
  for (const NumberOption* o : ComparisonNumberOptions()) {
    const auto value = given.numbers.find(o);
    if (value == given.numbers.end()) {
      if (o->required)
        throw InputError(fmt::format("{}: required, {}", o->names.*spelling, o->Allowed()));
      continue;
    }
    RequireOption(*o, o->names.*spelling, value->second);
    o->set(request, value->second);
  }
  for (const auto& [option, value] : given.choices) {
    RequireOption(*option, option->names.*spelling, value);
    option->set(request, value);
  }
  // The rules read the values given, so they come after them.
  for (const NumberOption* o : ComparisonNumberOptions()) {
    if (o->rule != nullptr && !given.numbers.contains(o)) o->rule(request);
  }
  std::string error;
  if (!request.problem.IsValid(&error) || !request.options.IsValid(&error)) throw InputError(error);
  CheckComparisonAffordable(request.problem, request.options, spelling);
  return request;
}

std::string MeshCost(double elements) {
  if (elements > 1e9) return "";
  return EigenBudgetExcess({BeamUnknowns(static_cast<int>(elements))}, 1);
}

std::string DefaultMeshCost(double r_ftrunc) {
  if (r_ftrunc > 1e12) return "";
  const int elements = DefaultElementCount(r_ftrunc);
  const std::string excess = MeshCost(elements);
  return excess.empty() ? "" : fmt::format("its default mesh, {} elements: {}", elements, excess);
}

}  // namespace shockmap
