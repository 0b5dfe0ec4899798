#pragma once
// The options of a comparison of the paper's problem, each declared once: its names on the three
// front ends (`shockmap compare`'s flag, Python's keyword of compare(), the key of a canonical
// study's grid or point), unit, help, default and the one range of values it takes. The command
// line, the Python module and the study files take their defaults, checks and help from here.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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

  bool Contains(double value) const;
  // What is allowed: "> 0 and <= 1e+12", "a whole number from 0 to 1500".
  std::string Allowed() const;
  // "value 0 is out of range: must be > 0 and <= 1e+12": a refusal without the option's name,
  // which each front end puts first as its user spells it.
  std::string Refusal(double value) const;
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

// The stiffness ratio R_k = k_s / K_bend (required).
extern const NumberOption kRkOption;
// The modal truncation R_ftrunc = f_trunc / f1 (required).
extern const NumberOption kRftruncOption;
// The time step in seconds; without it, --dt-factor of the --dt-rule bound.
extern const NumberOption kDtOption;
extern const NumberOption kDtFactorOption;
extern const ChoiceOption kDtRuleOption;
extern const NumberOption kWindowOption;
extern const ChoiceOption kSchemeOption;
// The beam's finite elements (0: enough for every retained mode).
extern const NumberOption kElementsOption;
// The reference's starting truncation R_fref = f_ref / f1 (command line and Python; a study sets
// it by its reference policy).
extern const NumberOption kRfrefOption;

// Every number option and every choice, in the order `shockmap compare --help` lists them.
std::span<const NumberOption* const> ComparisonNumberOptions();
std::span<const ChoiceOption* const> ComparisonChoiceOptions();

// Throws InputError "NAME: value V is out of range: must be ALLOWED" when `option` does not
// contain `value`; NAME is the option as the caller's user spells it.
void RequireOption(const NumberOption& option, std::string_view name, double value);
void RequireOption(const ChoiceOption& option, std::string_view name, std::string_view value);

}  // namespace shockmap
