#pragma once
// The options of a comparison of the paper's problem, each declared once: its names on the three
// front ends (`shockmap compare`'s flag, Python's keyword of compare(), the key of a canonical
// study's grid or point), unit, help, default and the one range of values it takes. The command
// line, the Python module and the study files take their defaults, checks and help from here.

#include <cmath>
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

// A number: finite, in (low, high] or [low, high], a whole number when `whole`.
struct NumberOption {
  OptionNames names;
  std::string_view unit;  // "" for a ratio or a count
  std::string_view help;
  // The value taken when the option is not given; none when it is required or, as the help
  // says, set by a rule.
  std::optional<double> default_value;
  double low = 0.0;
  bool low_strict = false;
  double high = 0.0;
  bool whole = false;
  // Why a value above `high` cannot be afforded (the cost it would take), or nullptr.
  std::string (*beyond_high)(double value) = nullptr;

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
inline const NumberOption kRkOption{{"--rk", "rk", "rk"},
                                    "",
                                    "stiffness ratio R_k = k_s / K_bend",
                                    std::nullopt,
                                    0.0,
                                    true,
                                    kMaxRk};
// A study's mode axis reaches 6.3e4 f1 (mode 150); at 1e5 f1 the default mesh, 988 elements, is
// within the eigenproblem budget, which it leaves near 2.3e5 f1 (a refusal there states the cost).
inline const NumberOption kRftruncOption{{"--rftrunc", "rftrunc", "rftrunc"},
                                         "",
                                         "modal truncation ratio f_trunc / f1",
                                         std::nullopt,
                                         1.0,
                                         false,
                                         1e5,
                                         false,
                                         &DefaultMeshCost};
// The paper's beam has f1 = 19 Hz: a step of a second resolves nothing of its motion.
inline const NumberOption kDtOption{{"--dt", "dt", "dt.seconds"},
                                    "s",
                                    "time step (without it: --dt-factor of the --dt-rule bound)",
                                    std::nullopt,
                                    0.0,
                                    true,
                                    1.0};
// Above 1 the explicit scheme is beyond its stability bound; the implicit one is not bound.
inline const NumberOption kDtFactorOption{{"--dt-factor", "dt_factor", "dt.factor"},
                                          "",
                                          "time step as a factor of the bound chosen by --dt-rule",
                                          TimeStepRequest{}.factor,
                                          0.0,
                                          true,
                                          100.0};
inline const ChoiceOption kDtRuleOption{
    {"--dt-rule", "dt_rule", "dt.rule"},
    "bound --dt-factor applies to: paper = 1/(4 f_trunc), sharp = 2/omega_max",
    ToString(TimeStepRequest{}.rule),
    {"paper", "sharp"}};
// 100 s is about 1900 first-mode periods of the paper's beam; the reference's budget
// (reference/reference_cost.h) refuses long windows earlier at large R_k.
inline const NumberOption kWindowOption{{"--window", "window_s", "window_s"},
                                        "s",
                                        "observation window",
                                        ComparisonOptions{}.window_s,
                                        0.0,
                                        true,
                                        100.0};
inline const ChoiceOption kSchemeOption{{"--scheme", "scheme", "scheme"},
                                        "numerical scheme",
                                        ToString(ComparisonOptions{}.scheme),
                                        {"explicit-modal", "implicit-full"}};
// A mesh of more elements has an eigenproblem beyond the budget of core/modal_basis.h.
inline const NumberOption kElementsOption{
    {"--elements", "elements", "n_elements"},
    "",
    "finite elements of the beam (0: enough for every retained mode)",
    static_cast<double>(ComparisonOptions{}.n_elements),
    0.0,
    false,
    static_cast<double>(kEigenBudgetElements),
    true,
    &MeshCost};
// No bound above: the reference's budget (reference/reference_cost.h) refuses what costs.
inline const NumberOption kRfrefOption{
    {"--rfref", "rfref", ""},
    "",
    "truncation ratio f_ref / f1 the reference starts from (default: max(3000, 10 sqrt(R_k)), "
    "as studies; raised until its estimated error is below 0.02)",
    std::nullopt,
    1.0,
    false,
    HUGE_VAL};

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

}  // namespace shockmap
