#include "specs/study_spec.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "compare/comparison_options.h"
#include "core/beam_properties.h"
#include "formats/json_reader.h"
#include "reference/analytic_modes.h"
#include "reference/reference_cost.h"
#include "validation/psd.h"

namespace shockmap {

std::pair<std::string, std::string> ReadStudyTitle(JsonObjectReader& r, std::string_view kind) {
  std::string name = r.RequiredName("name");
  if (name.empty() || name.size() > 200) r.Fail("name", "must be 1 to 200 characters");
  std::string description = r.Text("description", "");
  if (const std::string given = r.String("kind", std::string(kind)); given != kind) {
    r.Fail("kind", "this reader takes \"" + std::string(kind) + "\" studies, got \"" + given +
                       "\" (specs/study_file.h dispatches)");
  }
  return {std::move(name), std::move(description)};
}

double ReferencePolicy::RFref(double r_k) const {
  return ReferenceTruncationRule{r_fref_min, r_fref_per_sqrt_rk}.For(r_k);
}

namespace {

using Json = nlohmann::json;

struct Range {
  double lo;
  bool lo_strict;
  double hi;
  std::string Allowed() const {
    std::string s = lo_strict ? "> " : ">= ";
    s += Shown(Json(lo));
    if (std::isfinite(hi)) s += " and <= " + Shown(Json(hi));
    return s;
  }
  bool Contains(double v) const { return (lo_strict ? v > lo : v >= lo) && v <= hi; }
};

// An axis: a number, a non-empty list of numbers, {"logspace": [a, b, n]} (n values from 10^a
// to 10^b) or {"linspace": [a, b, n]}.
std::vector<double> ParseAxis(const Json& value, const std::string& file, const std::string& path,
                              const NumberOption& option) {
  std::vector<double> values;
  if (value.is_number()) {
    values.push_back(NumberAt(value, file, path));
  } else if (value.is_array()) {
    if (value.empty()) FailAt(file, path, "empty axis: give at least one value");
    for (std::size_t i = 0; i < value.size(); ++i) {
      values.push_back(NumberAt(value[i], file, path + "[" + std::to_string(i) + "]"));
    }
  } else if (value.is_object()) {
    JsonObjectReader r(value, file, path);
    const bool log = r.Has("logspace");
    const char* key = log ? "logspace" : "linspace";
    const Json* spec = r.Get(key);
    if (spec == nullptr)
      r.Fail("", "expected {\"logspace\": [a, b, n]} or {\"linspace\": [a, b, n]}");
    r.Finish();
    const std::string at = r.PathOf(key);
    if (!spec->is_array() || spec->size() != 3) {
      FailAt(file, at, "expected [start, stop, count], got " + Shown(*spec));
    }
    const double a = NumberAt((*spec)[0], file, at + "[0]");
    const double b = NumberAt((*spec)[1], file, at + "[1]");
    if (!(*spec)[2].is_number_integer() || (*spec)[2].get<std::int64_t>() < 1 ||
        (*spec)[2].get<std::int64_t>() > static_cast<std::int64_t>(kMaxStudyPoints)) {
      FailAt(file, at + "[2]",
             "count must be an integer in [1, " + std::to_string(kMaxStudyPoints) + "], got " +
                 Shown((*spec)[2]));
    }
    const auto n = (*spec)[2].get<std::int64_t>();
    if (log && (std::abs(a) > 300 || std::abs(b) > 300)) {
      FailAt(file, at, "exponents must lie in [-300, 300], got " + Shown(*spec));
    }
    for (std::int64_t i = 0; i < n; ++i) {
      const double x =
          n == 1 ? a : a + (b - a) * static_cast<double>(i) / static_cast<double>(n - 1);
      values.push_back(log ? std::pow(10.0, x) : x);
    }
  } else {
    FailAt(file, path,
           "expected a number, a list of numbers or a {\"logspace\"|\"linspace\": "
           "[a, b, n]} range, got " +
               Shown(value));
  }
  for (double v : values) {
    if (!option.Contains(v)) FailAt(file, path, option.Refusal(v));
  }
  return values;
}

std::vector<Scheme> ParseSchemes(const Json& value, const std::string& file,
                                 const std::string& path) {
  const Json list = value.is_array() ? value : Json::array({value});
  if (list.empty()) FailAt(file, path, "empty axis: give at least one scheme");
  std::vector<Scheme> schemes;
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string at = path + (value.is_array() ? "[" + std::to_string(i) + "]" : "");
    if (!list[i].is_string() || !kSchemeOption.Contains(list[i].get<std::string>())) {
      FailAt(
          file, at,
          kSchemeOption.Refusal(list[i].is_string() ? list[i].get<std::string>() : Shown(list[i])));
    }
    schemes.push_back(*SchemeFromString(list[i].get<std::string>()));
  }
  return schemes;
}

// {"rule": "paper"|"sharp", "factor": AXIS} or {"seconds": AXIS}.
std::vector<TimeStepRequest> ParseDt(const Json& value, const std::string& file,
                                     const std::string& path) {
  JsonObjectReader r(value, file, path);
  std::vector<TimeStepRequest> requests;
  if (r.Has("seconds")) {
    for (double s : ParseAxis(*r.Get("seconds"), file, r.PathOf("seconds"), kDtOption)) {
      requests.push_back({s, 0.0, DtRule::kSharp});
    }
  } else {
    const std::string rule_name = r.String("rule", kDtRuleOption.default_value);
    if (!kDtRuleOption.Contains(rule_name)) r.Fail("rule", kDtRuleOption.Refusal(rule_name));
    const auto rule = DtRuleFromString(rule_name);
    const Json* factors = r.Get("factor");
    const std::vector<double> values =
        factors == nullptr ? std::vector<double>{*kDtFactorOption.default_value}
                           : ParseAxis(*factors, file, r.PathOf("factor"), kDtFactorOption);
    for (double f : values) requests.push_back({std::nullopt, f, *rule});
  }
  r.Finish();
  return requests;
}

struct AxisSet {
  std::vector<double> rk, rftrunc, window_s, mass_damping_per_s;
  std::vector<TimeStepRequest> dt;
  std::vector<Scheme> scheme;
  std::vector<int> n_elements;
};

// {"modes": [first, last]} (see ModeEntryTruncations), else any axis.
std::vector<double> ParseTruncationAxis(const Json& value, const std::string& file,
                                        const std::string& path) {
  if (!value.is_object() || !value.contains("modes")) {
    return ParseAxis(value, file, path, kRftruncOption);
  }
  JsonObjectReader r(value, file, path);
  const Json* modes = r.Get("modes");
  r.Finish();
  const std::string at = r.PathOf("modes");
  const auto is_count = [](const Json& v) {
    return v.is_number_integer() && v.get<std::int64_t>() >= 1 &&
           v.get<std::int64_t>() <= kMaxModeAxisCount;
  };
  if (!modes->is_array() || modes->size() != 2 || !is_count((*modes)[0]) ||
      !is_count((*modes)[1]) || (*modes)[0].get<int>() > (*modes)[1].get<int>()) {
    FailAt(file, at,
           "expected [first, last], mode counts with 1 <= first <= last <= " +
               std::to_string(kMaxModeAxisCount) + ", got " + Shown(*modes));
  }
  return ModeEntryTruncations((*modes)[0].get<int>(), (*modes)[1].get<int>());
}

// The problem's damping, an axis of studies alone.
const NumberOption kDamping{
    {"", "", "mass_damping_per_s"}, "1/s", "mass-proportional damping", 0.0, 0.0, false, 1e6};

AxisSet ParseAxes(JsonObjectReader& r, const ScoringSpec& scoring, bool single) {
  const std::string& file = r.File();
  AxisSet a;
  auto required = [&](const NumberOption& option) {
    const char* key = option.names.study_key.data();
    const Json* v = r.Get(key);
    if (v == nullptr) r.Fail(key, "required axis is missing");
    if (single && !v->is_number()) r.Fail(key, "expected one number, got " + Shown(*v));
    return ParseAxis(*v, file, r.PathOf(key), option);
  };
  auto optional = [&](const NumberOption& option, double fallback) {
    const char* key = option.names.study_key.data();
    const Json* v = r.Get(key);
    if (v == nullptr) return std::vector<double>{fallback};
    if (single && !v->is_number()) r.Fail(key, "expected one number, got " + Shown(*v));
    return ParseAxis(*v, file, r.PathOf(key), option);
  };
  a.rk = required(kRkOption);
  if (const Json* v = r.Get("rftrunc"); v != nullptr && !single && v->is_object()) {
    a.rftrunc = ParseTruncationAxis(*v, file, r.PathOf("rftrunc"));
  } else {
    a.rftrunc = required(kRftruncOption);
  }
  a.window_s = optional(kWindowOption, scoring.window_s);
  a.mass_damping_per_s = optional(kDamping, *kDamping.default_value);
  for (double e : optional(kElementsOption, *kElementsOption.default_value)) {
    a.n_elements.push_back(static_cast<int>(e));
  }
  const Json* dt = r.Get("dt");
  a.dt = dt == nullptr ? std::vector<TimeStepRequest>{TimeStepRequest{}}
                       : ParseDt(*dt, file, r.PathOf("dt"));
  if (single && a.dt.size() != 1) r.Fail("dt", "expected one time step for a listed point");
  const Json* scheme = r.Get("scheme");
  a.scheme = scheme == nullptr ? std::vector<Scheme>{*SchemeFromString(kSchemeOption.default_value)}
                               : ParseSchemes(*scheme, file, r.PathOf("scheme"));
  if (single && a.scheme.size() != 1) r.Fail("scheme", "expected one scheme for a listed point");
  r.Finish();
  return a;
}

void AppendGrid(const AxisSet& a, const std::string& file, const std::string& path,
                std::vector<StudyPoint>& points) {
  const double size = static_cast<double>(a.rk.size()) * static_cast<double>(a.rftrunc.size()) *
                      static_cast<double>(a.dt.size()) * static_cast<double>(a.scheme.size()) *
                      static_cast<double>(a.window_s.size()) *
                      static_cast<double>(a.n_elements.size()) *
                      static_cast<double>(a.mass_damping_per_s.size());
  if (size + static_cast<double>(points.size()) > static_cast<double>(kMaxStudyPoints)) {
    FailAt(file, path,
           "the grid has " + Shown(Json(size)) + " points; at most " +
               std::to_string(kMaxStudyPoints) + " are allowed in one study");
  }
  for (double rk : a.rk)
    for (double rft : a.rftrunc)
      for (const auto& dt : a.dt)
        for (Scheme s : a.scheme)
          for (double w : a.window_s)
            for (int e : a.n_elements)
              for (double d : a.mass_damping_per_s) points.push_back({rk, rft, s, dt, w, e, d});
}

void ParseProblem(const Json& value, const std::string& file, CantileverImpact& p) {
  JsonObjectReader r(value, file, "problem");
  if (const Json* beam = r.Get("beam")) {
    JsonObjectReader b(*beam, file, r.PathOf("beam"));
    p.beam.length_m = b.Number("length_m", p.beam.length_m);
    p.beam.ei_n_m2 = b.Number("ei_n_m2", p.beam.ei_n_m2);
    p.beam.rho_a_kg_per_m = b.Number("rho_a_kg_per_m", p.beam.rho_a_kg_per_m);
    b.Finish();
    std::string error;
    if (!p.beam.IsValid(&error)) b.Fail(error.substr(0, error.find(' ')), error);
  }
  p.gap_m = r.Number("gap_m", p.gap_m);
  p.initial_tip_m = r.Number("initial_tip_m", p.initial_tip_m);
  r.Finish();
  if (std::abs(p.gap_m) > 1.0)
    r.Fail("gap_m", "value " + Shown(Json(p.gap_m)) + " must lie in [-1, 1] m");
  if (!(p.initial_tip_m > 0.0) || p.initial_tip_m > 1.0) {
    r.Fail("initial_tip_m", "value " + Shown(Json(p.initial_tip_m)) + " must be > 0 and <= 1 m");
  }
}

// "window_s" in seconds, or "window_periods" in first-mode periods of `beam`: one of the two.
void ParseWindow(JsonObjectReader& r, const BeamProperties& beam, ScoringSpec& s) {
  if (!r.Has("window_periods")) {
    s.window_s = r.Number("window_s", s.window_s);
    if (!kWindowOption.Contains(s.window_s)) r.Fail("window_s", kWindowOption.Refusal(s.window_s));
    return;
  }
  if (r.Has("window_s")) {
    r.Fail("window_periods",
           "give the window once: \"window_s\" in seconds or \"window_periods\" in first-mode "
           "periods, not both");
  }
  const double periods = r.Number("window_periods", 0.0);
  const double f1 = FirstClampedFreeFrequencyHz(beam);
  if (!kWindowOption.Contains(periods / f1)) {
    r.Fail("window_periods", "value " + Shown(Json(periods)) + " is " + Shown(Json(periods / f1)) +
                                 " s with f1 = " + Shown(Json(f1)) + " Hz; the window must be " +
                                 kWindowOption.Allowed() + " s");
  }
  s.window_periods = periods;
  s.window_s = periods / f1;
}

void ParseScoring(const Json& value, const std::string& file, const BeamProperties& beam,
                  ScoringSpec& s) {
  JsonObjectReader r(value, file, "scoring");
  auto in_range = [&](JsonObjectReader& reader, const char* key, double v, const Range& range) {
    if (!range.Contains(v))
      reader.Fail(key, "value " + Shown(Json(v)) + " must be " + range.Allowed());
    return v;
  };
  ParseWindow(r, beam, s);
  if (const Json* psd = r.Get("psd")) {
    JsonObjectReader p(*psd, file, r.PathOf("psd"));
    s.psd.n_samples = p.Integer("n_samples", s.psd.n_samples);
    s.psd.zero_padding_factor = p.Integer("zero_padding_factor", s.psd.zero_padding_factor);
    const std::string window = p.String("window", ToString(s.psd.window));
    const auto w = PsdWindowFromString(window);
    if (!w) p.Fail("window", "\"" + window + "\" is not a window: use \"hann\" or \"rectangular\"");
    s.psd.window = *w;
    const std::string scaling = p.String("scaling", s.psd.one_sided ? "one_sided" : "two_sided");
    if (scaling != "one_sided" && scaling != "two_sided")
      p.Fail("scaling", "\"" + scaling + "\" is not a scaling: use \"one_sided\" or \"two_sided\"");
    s.psd.one_sided = scaling == "one_sided";
    p.Finish();
    in_range(p, "n_samples", s.psd.n_samples, {kMinPsdSamples, false, kMaxPsdSamples});
    in_range(p, "zero_padding_factor", s.psd.zero_padding_factor,
             {1.0, false, kMaxZeroPaddingFactor});
  }
  if (const Json* shocks = r.Get("shocks")) {
    JsonObjectReader sh(*shocks, file, r.PathOf("shocks"));
    s.rest_duration_t1 =
        in_range(sh, "rest_duration_t1", sh.Number("rest_duration_t1", s.rest_duration_t1),
                 {0.0, true, 10.0});
    const std::string definition = sh.String("srf_definition", ToString(s.srf_definition));
    const auto d = SrfDefinitionFromString(definition);
    if (!d)
      sh.Fail("srf_definition", "\"" + definition +
                                    "\" is not an SRf definition: use \"first_shock\", "
                                    "\"first_contact\" or \"reference_window\"");
    s.srf_definition = *d;
    sh.Finish();
  }
  if (const Json* ref = r.Get("reference")) {
    JsonObjectReader f(*ref, file, r.PathOf("reference"));
    auto& p = s.reference;
    p.r_fref_min =
        in_range(f, "r_fref_min", f.Number("r_fref_min", p.r_fref_min), {1.0, false, 1e5});
    p.r_fref_per_sqrt_rk =
        in_range(f, "r_fref_per_sqrt_rk", f.Number("r_fref_per_sqrt_rk", p.r_fref_per_sqrt_rk),
                 {0.0, false, 1e3});
    p.crossing_samples_per_period = static_cast<int>(
        in_range(f, "crossing_samples_per_period",
                 f.Integer("crossing_samples_per_period", p.crossing_samples_per_period),
                 {4.0, false, 1024.0}));
    p.tolerance = in_range(f, "tolerance", f.Number("tolerance", p.tolerance), {0.0, true, 1.0});
    const std::string check = f.String("check", ToString(p.check));
    const auto c = ReferenceCheckFromString(check);
    if (!c)
      f.Fail("check", "\"" + check +
                          "\" is not a reference check: use \"finer\" (the default: 3 R_fref, "
                          "a bound) or \"coarser\" (R_fref / 3 alone, no bound)");
    p.check = *c;
    f.Finish();
  }
  if (const Json* spread = r.Get("spread")) {
    JsonObjectReader sp(*spread, file, r.PathOf("spread"));
    s.spread_from_rk = in_range(sp, "from_rk", sp.Number("from_rk", s.spread_from_rk),
                                {0.0, true, std::numeric_limits<double>::infinity()});
    sp.Finish();
  }
  if (const Json* timing = r.Get("timing")) {
    JsonObjectReader t(*timing, file, r.PathOf("timing"));
    s.timing_repeat_until_s =
        in_range(t, "repeat_until_s", t.Number("repeat_until_s", s.timing_repeat_until_s),
                 {0.0, false, 1.0});
    t.Finish();
  }
  if (const Json* th = r.Get("thresholds")) {
    JsonObjectReader t(*th, file, r.PathOf("thresholds"));
    ReadThresholds(t, s.thresholds);
    t.Finish();
  }
  r.Finish();
}

Json DtJson(const TimeStepRequest& dt) {
  if (dt.dt_s) return {{"seconds", *dt.dt_s}};
  return {{"rule", ToString(dt.rule)}, {"factor", dt.factor}};
}

Json ProblemJson(const CantileverImpact& p) {
  return {{"length_m", p.beam.length_m},
          {"ei_n_m2", p.beam.ei_n_m2},
          {"rho_a_kg_per_m", p.beam.rho_a_kg_per_m},
          {"gap_m", p.gap_m},
          {"initial_tip_m", p.initial_tip_m}};
}

}  // namespace

void ReadThresholds(JsonObjectReader& r, std::map<std::string, double, std::less<>>& thresholds) {
  for (const ScoreDefinition& score : Scores()) {
    const std::string key = score.ThresholdKey();
    if (r.Get(key) == nullptr) continue;
    const double v = r.Number(key, 0.0);
    const Range range{score.threshold_low, false, score.threshold_high};
    if (!range.Contains(v)) r.Fail(key, "value " + Shown(Json(v)) + " must be " + range.Allowed());
    thresholds[std::string(score.name)] = v;
  }
}

std::vector<double> ModeEntryTruncations(int first_mode, int last_mode) {
  const std::vector<double> b = CharacteristicRoots(0.0, 0.0, last_mode);
  std::vector<double> r_ftrunc;
  for (int n = first_mode; n <= last_mode; ++n) {
    const double ratio = b[static_cast<std::size_t>(n - 1)] / b[0];
    r_ftrunc.push_back(ratio * ratio * (1.0 + kModeEntryMargin));
  }
  return r_ftrunc;
}

namespace {

// Refuses a study whose reference at some (R_k, window) exceeds the budget of
// reference/reference_cost.h, naming the first such point. Each reference is costed once: the
// points scored against it share it.
void CheckReferenceCosts(const StudySpec& spec) {
  std::set<std::string> costed;
  for (const StudyPoint& point : spec.points) {
    if (!costed.insert(ReferenceKey(spec, point)).second) continue;
    const ReferenceOptions reference = OptionsOf(spec, point).reference;
    const std::string excess =
        ReferenceBudgetExcess(ProblemOf(spec, point), reference, point.window_s);
    if (excess.empty()) continue;
    std::ostringstream at;
    at << "rk = " << Shown(Json(point.r_k)) << " and window_s = " << Shown(Json(point.window_s))
       << " give R_fref = " << Shown(Json(reference.r_fref)) << ": " << excess
       << "; lower r_fref_min, r_fref_per_sqrt_rk, the largest rk or the window";
    FailAt(spec.file, "scoring.reference", at.str());
  }
}

}  // namespace

StudySpec ParseStudySpec(const Json& json, const std::string& file) {
  StudySpec spec;
  spec.file = file;
  JsonObjectReader r(json, file, "");
  std::tie(spec.name, spec.description) = ReadStudyTitle(r, "canonical");
  if (const Json* p = r.Get("problem")) ParseProblem(*p, file, spec.problem);
  if (const Json* s = r.Get("scoring")) ParseScoring(*s, file, spec.problem.beam, spec.scoring);
  const Json* grids = r.Get("grids");
  const Json* points = r.Get("points");
  r.Finish();
  if (grids == nullptr && points == nullptr) {
    FailAt(file, "", "give \"grids\" (full products of axes) and/or \"points\" (a list)");
  }
  std::vector<StudyPoint> all;
  for (const auto& [key, list] : {std::pair{"grids", grids}, std::pair{"points", points}}) {
    if (list == nullptr) continue;
    if (!list->is_array() || list->empty()) {
      FailAt(file, key, "expected a non-empty list, got " + Shown(*list));
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
      const std::string path = std::string(key) + "[" + std::to_string(i) + "]";
      JsonObjectReader item((*list)[i], file, path);
      AppendGrid(ParseAxes(item, spec.scoring, std::string(key) == "points"), file, path, all);
    }
  }
  std::set<std::string> seen;
  for (const auto& p : all) {
    if (seen.insert(PointKey(p)).second) spec.points.push_back(p);
  }
  CheckReferenceCosts(spec);
  spec.spec_json = json.dump();
  return spec;
}

StudySpec LoadStudySpec(const std::string& path) {
  return ParseStudySpec(ReadJsonFile(path), path);
}

std::optional<std::string> WindowWarning(const StudySpec& spec) {
  const double f1 = FirstClampedFreeFrequencyHz(spec.problem.beam);
  const double paper_f1 = FirstClampedFreeFrequencyHz(BeamProperties{});
  if (std::max(f1 / paper_f1, paper_f1 / f1) <= 1.5) return std::nullopt;
  std::set<double> windows;
  for (const StudyPoint& p : spec.points) windows.insert(p.window_s);
  if (windows.empty() ||
      (spec.scoring.window_periods && windows == std::set<double>{spec.scoring.window_s})) {
    return std::nullopt;
  }
  const double w = *windows.begin();
  return fmt::format(
      "{}: window_s: {:g} s covers {:.3g} first-mode periods of this beam (f1 = {:.4g} Hz), "
      "where it covers {:.3g} of the paper's (f1 = {:.4g} Hz; its Fig. 4 window, {:g} s, "
      "covers {:.3g}): Err and SRf over it measure another part of the motion. Give "
      "\"scoring\": {{\"window_periods\": ...}} to set the window in periods",
      spec.file, w, w * f1, f1, w * paper_f1, paper_f1, kFig4WindowS, kFig4WindowS * paper_f1);
}

CantileverImpact ProblemOf(const StudySpec& spec, const StudyPoint& point) {
  CantileverImpact p = spec.problem;
  p.r_k = point.r_k;
  p.mass_damping_per_s = point.mass_damping_per_s;
  return p;
}

ComparisonOptions OptionsOf(const StudySpec& spec, const StudyPoint& point) {
  ComparisonOptions o;
  o.r_ftrunc = point.r_ftrunc;
  o.scheme = point.scheme;
  o.dt = point.dt;
  o.window_s = point.window_s;
  o.n_elements = point.n_elements;
  o.reference.r_fref = spec.scoring.reference.RFref(point.r_k);
  o.reference.crossing_samples_per_period = spec.scoring.reference.crossing_samples_per_period;
  o.psd = spec.scoring.psd;
  o.rest_duration_t1 = spec.scoring.rest_duration_t1;
  o.srf_definition = spec.scoring.srf_definition;
  o.reference_tolerance = spec.scoring.reference.tolerance;
  o.reference.target_error = o.reference_tolerance;
  o.reference.check = spec.scoring.reference.check;
  return o;
}

std::string PointKey(const StudyPoint& p) {
  return Json{{"rk", p.r_k},
              {"rftrunc", p.r_ftrunc},
              {"scheme", ToString(p.scheme)},
              {"dt", DtJson(p.dt)},
              {"window_s", p.window_s},
              {"n_elements", p.n_elements},
              {"mass_damping_per_s", p.mass_damping_per_s}}
      .dump();
}

std::string ReferenceKey(const StudySpec& spec, const StudyPoint& p) {
  const ComparisonOptions o = OptionsOf(spec, p);
  Json key{{"problem", ProblemJson(spec.problem)},
           {"rk", p.r_k},
           {"mass_damping_per_s", p.mass_damping_per_s},
           {"r_fref", o.reference.r_fref},
           {"crossing_samples_per_period", o.reference.crossing_samples_per_period},
           {"window_s", p.window_s},
           {"rest_duration_t1", o.rest_duration_t1}};
  // Only when not the default, so that the references stored before the key keep theirs.
  if (o.reference.check != ReferenceCheck::kFiner) key["check"] = ToString(o.reference.check);
  return key.dump();
}

std::optional<RepeatedTiming> ShortRunTiming(const ScoringSpec& scoring) {
  if (scoring.timing_repeat_until_s == 0.0) return std::nullopt;
  return RepeatedTiming{scoring.timing_repeat_until_s, 2, 101};
}

std::string SettingsKey(const StudySpec& spec) {
  const ScoringSpec& s = spec.scoring;
  return Json{{"problem", ProblemJson(spec.problem)},
              {"scoring",
               {{"window_s", s.window_s},
                {"psd",
                 {{"n_samples", s.psd.n_samples},
                  {"window", ToString(s.psd.window)},
                  {"zero_padding_factor", s.psd.zero_padding_factor},
                  {"scaling", s.psd.one_sided ? "one_sided" : "two_sided"}}},
                {"shocks",
                 {{"rest_duration_t1", s.rest_duration_t1},
                  {"srf_definition", ToString(s.srf_definition)}}},
                {"reference",
                 {{"r_fref_min", s.reference.r_fref_min},
                  {"r_fref_per_sqrt_rk", s.reference.r_fref_per_sqrt_rk},
                  {"crossing_samples_per_period", s.reference.crossing_samples_per_period},
                  {"tolerance", s.reference.tolerance},
                  {"check", ToString(s.reference.check)}}}}}}
      .dump();
}

}  // namespace shockmap
