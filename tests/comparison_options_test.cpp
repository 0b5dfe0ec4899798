// The options of a comparison (compare/comparison_options.h): the command line and the study
// files take each declared default and refuse each value outside its declared range, saying what
// is allowed; the request both the command line and Python make from their options.
// (python/tests/test_options.py holds Python to the same, beside both.)

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "compare/comparison_options.h"
#include "core/input_error.h"
#include "specs/study_spec.h"
#include "tests/run_command.h"

namespace shockmap {
namespace {

using testing::Outcome;
using testing::RunShockmap;
using Json = nlohmann::json;

// A point of the paper's problem that runs in milliseconds.
constexpr double kRk = 100.0;
constexpr double kRftrunc = 10.0;

// Values just outside the range: its lower bound when strict (else one below), and twice its
// upper bound (one above for a whole number) when it has one.
std::vector<double> Outside(const NumberOption& o) {
  std::vector<double> values{o.low_strict ? o.low : o.low - 1.0};
  if (std::isfinite(o.high)) values.push_back(o.whole ? o.high + 1.0 : 2.0 * o.high);
  return values;
}

// A one-point study whose point is {"rk", "rftrunc"} with `key` (dotted: "dt.factor") set.
Json StudyWith(const std::string& key, const Json& value) {
  Json point{{"rk", kRk}, {"rftrunc", kRftrunc}};
  if (const std::size_t dot = key.find('.'); dot != std::string::npos) {
    point[key.substr(0, dot)][key.substr(dot + 1)] = value;
  } else if (!key.empty()) {
    point[key] = value;
  }
  return {{"kind", "canonical"}, {"name", "options"}, {"points", Json::array({point})}};
}

// The study's refusal of `json`, or "" when it is accepted.
std::string StudyRefusal(const Json& json) {
  try {
    ParseStudySpec(json, "options.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string Shown(double value) {
  if (value == std::floor(value) && std::abs(value) < 1e15) {
    return std::to_string(static_cast<long long>(value));
  }
  return Json(value).dump();
}

TEST(ComparisonOptions, EachDeclaredDefaultLiesInItsRange) {
  for (const NumberOption* o : ComparisonNumberOptions()) {
    if (o->default_value) {
      EXPECT_TRUE(o->Contains(*o->default_value)) << o->names.flag;
    }
    for (double v : Outside(*o)) EXPECT_FALSE(o->Contains(v)) << o->names.flag << " " << v;
  }
  for (const ChoiceOption* o : ComparisonChoiceOptions()) {
    EXPECT_TRUE(o->Contains(o->default_value)) << o->names.flag;
  }
}

TEST(ComparisonOptions, AStudyPointTakesTheDeclaredDefaults) {
  const StudySpec spec = ParseStudySpec(StudyWith("", nullptr), "options.json");
  ASSERT_EQ(spec.points.size(), 1u);
  const ComparisonOptions o = OptionsOf(spec, spec.points[0]);
  EXPECT_EQ(o.dt.factor, *kDtFactorOption.default_value);
  EXPECT_EQ(ToString(o.dt.rule), kDtRuleOption.default_value);
  EXPECT_FALSE(o.dt.dt_s.has_value());
  EXPECT_EQ(o.window_s, *kWindowOption.default_value);
  EXPECT_EQ(ToString(o.scheme), kSchemeOption.default_value);
  EXPECT_EQ(o.n_elements, *kElementsOption.default_value);
}

TEST(ComparisonOptions, AStudyRefusesEachValueOutsideTheDeclaredRange) {
  for (const NumberOption* o : ComparisonNumberOptions()) {
    if (o->names.study_key.empty()) continue;
    const std::string key(o->names.study_key);
    for (double v : Outside(*o)) {
      const std::string refusal = StudyRefusal(StudyWith(key, v));
      EXPECT_NE(refusal.find("options.json: points[0]." + key), std::string::npos) << refusal;
      EXPECT_NE(refusal.find("must be " + o->Allowed()), std::string::npos) << refusal;
    }
  }
  for (const ChoiceOption* o : ComparisonChoiceOptions()) {
    const std::string refusal = StudyRefusal(StudyWith(std::string(o->names.study_key), "fast"));
    EXPECT_NE(refusal.find("points[0]." + std::string(o->names.study_key)), std::string::npos)
        << refusal;
    EXPECT_NE(refusal.find(o->Allowed()), std::string::npos) << refusal;
  }
}

// The ranges hold every shipped study of the paper's problem.
TEST(ComparisonOptions, EveryShippedCanonicalStudyLiesInTheDeclaredRanges) {
  int read = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(SHOCKMAP_SOURCE_DIR) + "/studies")) {
    if (entry.path().extension() != ".json") continue;
    const Json json = ReadJsonFile(entry.path().string());
    if (json.value("kind", json.contains("scene") ? "scene_sweep" : "canonical") != "canonical") {
      continue;
    }
    EXPECT_NO_THROW(ParseStudySpec(json, entry.path().string())) << entry.path();
    ++read;
  }
  EXPECT_GE(read, 10);  // studies/ holds 10 today.
}

TEST(ComparisonOptions, TheCommandLineRefusesEachValueOutsideTheDeclaredRange) {
  for (const NumberOption* o : ComparisonNumberOptions()) {
    for (double v : Outside(*o)) {
      const std::string flag(o->names.flag);
      std::string args = "compare";
      if (flag != "--rk") args += " --rk " + Shown(kRk);
      if (flag != "--rftrunc") args += " --rftrunc " + Shown(kRftrunc);
      const Outcome r = RunShockmap(args + " " + flag + " " + Shown(v));
      EXPECT_EQ(r.exit_code, 2) << args << " " << flag << " " << v << "\n" << r.output;
      EXPECT_NE(
          r.output.find(flag + ": value " + Shown(v) + " is out of range: must be " + o->Allowed()),
          std::string::npos)
          << r.output;
    }
  }
}

TEST(ComparisonOptions, TheCommandLineTakesTheDeclaredDefaults) {
  const Outcome r =
      RunShockmap("compare --rk " + Shown(kRk) + " --rftrunc " + Shown(kRftrunc) + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Json j = Json::parse(r.output);
  EXPECT_EQ(j.at("window_s").get<double>(), *kWindowOption.default_value);
  EXPECT_EQ(j.at("scheme").get<std::string>(), kSchemeOption.default_value);
  ASSERT_EQ(kDtRuleOption.default_value, "sharp");
  EXPECT_EQ(j.at("dt_requested_s").get<double>(),
            *kDtFactorOption.default_value * j.at("dt_sharp_s").get<double>());
  // The declared 0 asks for the default mesh of the truncation.
  ASSERT_EQ(*kElementsOption.default_value, 0.0);
  EXPECT_EQ(j.at("n_elements").get<int>(), DefaultElementCount(kRftrunc));
}

// The message of the InputError `asked` throws, or "" when it throws none.
template <typename Call>
std::string Refusal(Call asked) {
  try {
    asked();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ComparisonOptions, ARequestIsEachGivenValueSetThroughItsDeclaration) {
  GivenOptions given;
  given.numbers = {{&kRkOption, 1e6},
                   {&kRftruncOption, 30.0},
                   {&kDtFactorOption, 0.5},
                   {&kWindowOption, 0.01},
                   {&kElementsOption, 40.0}};
  given.choices = {{&kDtRuleOption, "paper"}, {&kSchemeOption, "implicit-full"}};
  ComparisonRequest r = ComparisonAsked(given, &OptionNames::keyword);
  EXPECT_EQ(r.problem.r_k, 1e6);
  EXPECT_EQ(r.options.r_ftrunc, 30.0);
  EXPECT_EQ(r.options.dt.factor, 0.5);
  EXPECT_EQ(r.options.dt.dt_s, TimeStepRequest{}.dt_s);
  EXPECT_EQ(r.options.dt.rule, DtRule::kPaper);
  EXPECT_EQ(r.options.window_s, 0.01);
  EXPECT_EQ(r.options.n_elements, 40);
  EXPECT_EQ(r.options.scheme, Scheme::kImplicitFull);
  // Not given, the reference's truncation follows the studies' rule, max(3000, 10 sqrt(R_k)),
  // on every front end.
  EXPECT_EQ(r.options.reference.r_fref, 1e4);
  given.numbers[&kRfrefOption] = 5000.0;
  given.numbers[&kDtOption] = 1e-5;
  r = ComparisonAsked(given, &OptionNames::flag);
  EXPECT_EQ(r.options.reference.r_fref, 5000.0);
  EXPECT_EQ(r.options.dt.dt_s, 1e-5);
}

TEST(ComparisonOptions, ARequestIsRefusedAsItsFrontEndSpellsTheOption) {
  GivenOptions given;
  given.numbers = {{&kRftruncOption, kRftrunc}};
  EXPECT_EQ(Refusal([&] { ComparisonAsked(given, &OptionNames::flag); }),
            "--rk: required, " + kRkOption.Allowed());
  EXPECT_EQ(Refusal([&] { ComparisonAsked(given, &OptionNames::keyword); }),
            "rk: required, " + kRkOption.Allowed());
  given.numbers[&kRkOption] = kRk;
  given.numbers[&kWindowOption] = 200.0;
  EXPECT_EQ(Refusal([&] { ComparisonAsked(given, &OptionNames::keyword); }),
            "window_s: " + kWindowOption.Refusal(200.0));
  given.numbers.erase(&kWindowOption);
  given.choices[&kSchemeOption] = "fast";
  EXPECT_EQ(Refusal([&] { ComparisonAsked(given, &OptionNames::flag); }),
            "--scheme: " + kSchemeOption.Refusal("fast"));
  // Within every range but more steps than a run may take: named by its spelling too.
  given.choices.clear();
  given.numbers[&kDtOption] = 1e-9;
  given.numbers[&kWindowOption] = 1.0;
  EXPECT_EQ(Refusal([&] { ComparisonAsked(given, &OptionNames::keyword); }).rfind("dt: 1e-09 s", 0),
            0u);
}

}  // namespace
}  // namespace shockmap
