#pragma once
// The options of a comparison of the paper's problem, each declared once: its names on the three
// front ends (`shockmap compare`'s flag, Python's keyword of compare(), the key of a canonical
// study's grid or point), unit, help, default and the one range of values it takes. The command
// line, the Python module and the study files take their defaults, checks and help from here.

#include <cmath>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compare/comparison.h"
#include "core/modal_basis.h"

namespace shockmap {

// The largest stiffness ratio R_k a comparison takes.
inline constexpr double kMaxRk = 1e12;

// Where an option is spelled on each front end.
struct OptionNames {
  std::string_view flag;       // "--dt-factor"
  std::string_view keyword;    // Python's compare(): "dt_factor"
  std::string_view study_key;  // a study's grid or point: "dt.factor"
};

// How one front end spells the options: &OptionNames::flag, &OptionNames::keyword.
using OptionSpelling = std::string_view OptionNames::*;

// What a comparison is asked: the problem and the run's options, as the front ends fill them
// through the declared options.
struct ComparisonRequest {
  CantileverImpact problem;
  ComparisonOptions options;
};

// A number: finite, in (low, high] or [low, high], a whole number when `whole`.
struct NumberOption {
  OptionNames names;
  std::string_view unit = "";  // "" for a ratio or a count
  std::string_view help;
  // The value taken when the option is not given; none when it is required or, as the help
  // says, set by a rule.
  std::optional<double> default_value = std::nullopt;
  double low = 0.0;
  bool low_strict = false;
  double high = 0.0;
  bool whole = false;
  // Why a value above `high` cannot be afforded (the cost it would take), or nullptr.
  std::string (*beyond_high)(double value) = nullptr;
  // Given on every front end: no default and no rule.
  bool required = false;
  // Puts a value given into the request; nullptr for an option no comparison takes.
  void (*set)(ComparisonRequest& request, double value) = nullptr;
  // Sets the value of an option not given from the rest of the request (the rule its help
  // states), or nullptr: the default stands.
  void (*rule)(ComparisonRequest& request) = nullptr;

  bool Contains(double value) const;
  // What is allowed: "> 0 and <= 1e+12", "a whole number from 0 to 1500".
  std::string Allowed() const;
  // "value 0 is out of range: must be > 0 and <= 1e+12" (then why, for a value above `high`
  // whose cost is stated): a refusal without the option's name, which each front end puts first
  // as its user spells it. `shown`: the value as its user wrote it.
  std::string Refusal(double value) const;
  std::string Refusal(std::string_view shown, double value) const;
};

// One of a few words.
struct ChoiceOption {
  OptionNames names;
  std::string_view help;
  std::string default_value;
  std::vector<std::string_view> choices;
  // Puts a value given (one of `choices`) into the request.
  void (*set)(ComparisonRequest& request, std::string_view value) = nullptr;

  bool Contains(std::string_view value) const;
  std::string Allowed() const;  // "one of paper, sharp"
  std::string Refusal(std::string_view value) const;
};

// The eigenproblem's cost of a beam of `elements` elements against the budget of
// core/modal_basis.h; "" within it, and beyond 1e9 elements, whose unknowns an int does not count.
std::string MeshCost(double elements);
// The same for the default mesh of truncation `r_ftrunc` (DefaultElementCount), naming its
// elements; "" within the budget, and beyond 1e12.
std::string DefaultMeshCost(double r_ftrunc);

// The defaults are those of ComparisonOptions and TimeStepRequest, which the library's own
// callers take too.
inline const NumberOption kRkOption{
    .names = {"--rk", "rk", "rk"},
    .help = "stiffness ratio R_k = k_s / K_bend",
    .low = 0.0,
    .low_strict = true,
    .high = kMaxRk,
    .required = true,
    .set = [](ComparisonRequest& r, double v) { r.problem.r_k = v; }};
// A study's mode axis reaches 6.3e4 f1 (mode 150); at 1e5 f1 the default mesh, 988 elements, is
// within the eigenproblem budget, which it leaves near 2.3e5 f1 (a refusal there states the cost).
inline const NumberOption kRftruncOption{
    .names = {"--rftrunc", "rftrunc", "rftrunc"},
    .help = "modal truncation ratio f_trunc / f1",
    .low = 1.0,
    .high = 1e5,
    .beyond_high = &DefaultMeshCost,
    .required = true,
    .set = [](ComparisonRequest& r, double v) { r.options.r_ftrunc = v; }};
// The paper's beam has f1 = 19 Hz: a step of a second resolves nothing of its motion.
inline const NumberOption kDtOption{
    .names = {"--dt", "dt", "dt.seconds"},
    .unit = "s",
    .help = "time step (without it: --dt-factor of the --dt-rule bound)",
    .low = 0.0,
    .low_strict = true,
    .high = 1.0,
    .set = [](ComparisonRequest& r, double v) { r.options.dt.dt_s = v; }};
// Above 1 the explicit scheme is beyond its stability bound; the implicit one is not bound.
inline const NumberOption kDtFactorOption{
    .names = {"--dt-factor", "dt_factor", "dt.factor"},
    .help = "time step as a factor of the bound chosen by --dt-rule",
    .default_value = TimeStepRequest{}.factor,
    .low = 0.0,
    .low_strict = true,
    .high = 100.0,
    .set = [](ComparisonRequest& r, double v) { r.options.dt.factor = v; }};
inline const ChoiceOption kDtRuleOption{
    .names = {"--dt-rule", "dt_rule", "dt.rule"},
    .help = "bound --dt-factor applies to: paper = 1/(4 f_trunc), sharp = 2/omega_max",
    .default_value = ToString(TimeStepRequest{}.rule),
    .choices = {"paper", "sharp"},
    .set = [](ComparisonRequest& r, std::string_view v) {
      r.options.dt.rule = *DtRuleFromString(v);
    }};
// 100 s is about 1900 first-mode periods of the paper's beam; the reference's budget
// (reference/reference_cost.h) refuses long windows earlier at large R_k.
inline const NumberOption kWindowOption{
    .names = {"--window", "window_s", "window_s"},
    .unit = "s",
    .help = "observation window",
    .default_value = ComparisonOptions{}.window_s,
    .low = 0.0,
    .low_strict = true,
    .high = 100.0,
    .set = [](ComparisonRequest& r, double v) { r.options.window_s = v; }};
inline const ChoiceOption kSchemeOption{.names = {"--scheme", "scheme", "scheme"},
                                        .help = "numerical scheme",
                                        .default_value = ToString(ComparisonOptions{}.scheme),
                                        .choices = {"explicit-modal", "implicit-full"},
                                        .set = [](ComparisonRequest& r, std::string_view v) {
                                          r.options.scheme = *SchemeFromString(v);
                                        }};
// A mesh of more elements has an eigenproblem beyond the budget of core/modal_basis.h.
inline const NumberOption kElementsOption{
    .names = {"--elements", "elements", "n_elements"},
    .help = "finite elements of the beam (0: enough for every retained mode)",
    .default_value = static_cast<double>(ComparisonOptions{}.n_elements),
    .low = 0.0,
    .high = static_cast<double>(kEigenBudgetElements),
    .whole = true,
    .beyond_high = &MeshCost,
    .set = [](ComparisonRequest& r, double v) { r.options.n_elements = static_cast<int>(v); }};
// No bound above: the reference's budget (reference/reference_cost.h) refuses what costs.
inline const NumberOption kRfrefOption{
    .names = {"--rfref", "rfref", ""},
    .help =
        "truncation ratio f_ref / f1 the reference starts from (default: max(3000, 10 "
        "sqrt(R_k)), as studies; raised until its estimated error is below 0.02)",
    .low = 1.0,
    .high = HUGE_VAL,
    .set = [](ComparisonRequest& r, double v) { r.options.reference.r_fref = v; },
    .rule =
        [](ComparisonRequest& r) {
          r.options.reference.r_fref = ReferenceTruncationRule{}.For(r.problem.r_k);
        }};

// Every number option and every choice, in the order `shockmap compare --help` lists them.
inline std::span<const NumberOption* const> ComparisonNumberOptions() {
  static const NumberOption* const kAll[] = {&kRkOption,       &kRftruncOption, &kDtOption,
                                             &kDtFactorOption, &kWindowOption,  &kRfrefOption,
                                             &kElementsOption};
  return kAll;
}

inline std::span<const ChoiceOption* const> ComparisonChoiceOptions() {
  static const ChoiceOption* const kAll[] = {&kDtRuleOption, &kSchemeOption};
  return kAll;
}

// Throws InputError "NAME: value V is out of range: must be ALLOWED" when `option` does not
// contain `value`; NAME is the option as the caller's user spells it.
void RequireOption(const NumberOption& option, std::string_view name, double value);
void RequireOption(const ChoiceOption& option, std::string_view name, std::string_view value);

// The option spelled `name` on a front end, or nullptr.
const NumberOption* ComparisonNumberOption(std::string_view name, OptionSpelling spelling);
const ChoiceOption* ComparisonChoiceOption(std::string_view name, OptionSpelling spelling);

// The values a front end was given, by declared option; an option not given is absent.
struct GivenOptions {
  std::map<const NumberOption*, double> numbers;
  std::map<const ChoiceOption*, std::string> choices;
};

// The comparison `given` asks for, as every front end runs it: each value checked by its
// option and set through it, the others at their defaults or by their rules (the reference's
// truncation: ReferenceTruncationRule for the problem's R_k); then the problem and the options
// checked whole and their cost (CheckComparisonAffordable). Throws InputError naming the option
// as `spelling` spells it: a required option missing, a value out of its range, a run beyond
// its budget.
ComparisonRequest ComparisonAsked(const GivenOptions& given, OptionSpelling spelling);

}  // namespace shockmap
