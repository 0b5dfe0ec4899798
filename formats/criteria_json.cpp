#include "formats/criteria_json.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "compare/comparison_options.h"
#include "formats/json_or_null.h"
#include "formats/json_reader.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// What a criteria file may hold: a range per number, each end open or closed.
struct Allowed {
  double lo, hi;
  bool lo_open = true;
  const char* why = "";  // What lies outside, for the message.
};

// dt / dt_sharp where points pass: criteria are of the explicit scheme (as written below),
// which is unstable past its sharp bound, a ratio of 1.
constexpr Allowed kPassingDtRatio{0.0, 1.0, true,
                                  "above 1 the explicit scheme is past its stability bound"};
constexpr Allowed kDtRatio{0.0, 1e3};
// As a study's axes allow (specs/study_spec.cpp).
constexpr Allowed kRk{0.0, kMaxRk};
constexpr Allowed kRftrunc{1.0, 1e5, false};
// 0: nothing studied below the boundary.
constexpr Allowed kRftruncBelow{0.0, 1e5, false};
constexpr Allowed kExponent{-10.0, 10.0, false};
constexpr Allowed kCoefficient{0.0, 1e12};
constexpr Allowed kSpread{0.0, 1e3, false};  // A standard error or residual.
constexpr Allowed kFactor{1.0, 1e3, false};  // A ratio either way.

double Checked(JsonObjectReader& r, const std::string& key, double v, const Allowed& a) {
  if (!((a.lo_open ? v > a.lo : v >= a.lo) && v <= a.hi)) {
    r.Fail(key, fmt::format("value {} must lie in {}{:g}, {:g}]{}{}", Shown(Json(v)),
                            a.lo_open ? "(" : "[", a.lo, a.hi, *a.why ? ": " : "", a.why));
  }
  return v;
}

// Refuses, naming the file and the key, options outside CriteriaOptions::IsValid's ranges, which
// every use of them (DeriveCriteria, Passes, the views) assumes. `options` were read from
// "thresholds" (each score's key: err_max, srf_min, ...) and "fit" (confidence).
void CheckOptions(const CriteriaOptions& options, const std::string& file) {
  std::string error;  // "<name> = <value>: must be in [<lo>, <hi>]"
  if (options.IsValid(&error)) return;
  const std::string name = error.substr(0, error.find(' '));
  FailAt(file, (name == "confidence" ? "fit." : "thresholds.") + name, error);
}

double RequiredIn(JsonObjectReader& r, const std::string& key, const Allowed& a) {
  return Checked(r, key, r.RequiredNumber(key), a);
}

double ReadNumber(JsonObjectReader& r, const std::string& key, double fallback, const Allowed& a) {
  return Checked(r, key, r.Number(key, fallback), a);
}

// A fit through two R_k has no spread: its standard errors, interval and residual are NaN,
// which a baseline file holds as null.
double SpreadIn(JsonObjectReader& r, const std::string& key, double fallback, const Allowed& a) {
  const Json* v = r.Get(key);
  if (v != nullptr && (v->is_null() || (v->is_number_float() && std::isnan(v->get<double>())))) {
    return std::numeric_limits<double>::quiet_NaN();
  }
  return ReadNumber(r, key, fallback, a);
}

std::optional<double> OptionalNumber(JsonObjectReader& r, const std::string& key,
                                     const Allowed& a) {
  const Json* v = r.Get(key);
  if (v == nullptr || v->is_null()) return std::nullopt;
  return Checked(r, key, NumberAt(*v, r.File(), r.PathOf(key)), a);
}

// "unscored" or "undecided": optional (baselines written before them have none), each item an
// R_k, a count of at least 1 and a reason.
std::vector<PointsSetAside> SetAsideFromJson(JsonObjectReader& r, const std::string& key) {
  std::vector<PointsSetAside> unscored;
  const Json* list = r.Get(key);
  if (list == nullptr) return unscored;
  if (!list->is_array()) r.Fail(key, "expected a list, got " + Shown(*list));
  for (std::size_t i = 0; i < list->size(); ++i) {
    JsonObjectReader u((*list)[i], r.File(), r.PathOf(key) + "[" + std::to_string(i) + "]");
    PointsSetAside item{RequiredIn(u, "r_k", kRk), u.Integer("n_points", 0), u.Text("reason", "")};
    if (item.n_points < 1) u.Fail("n_points", "must be at least 1");
    u.Finish();
    unscored.push_back(std::move(item));
  }
  return unscored;
}

Json SetAsideToJson(const std::vector<PointsSetAside>& set_aside) {
  Json list = Json::array();
  for (const PointsSetAside& u : set_aside) {
    list.push_back({{"r_k", u.r_k}, {"n_points", u.n_points}, {"reason", u.reason}});
  }
  return list;
}

// {"err_max": 0.1, "srf_min": 0.8}: each threshold by its key.
Json ThresholdsJson(const CriteriaOptions& options) {
  Json thresholds = Json::object();
  for (const auto& [name, threshold] : options.thresholds) {
    thresholds[FindScore(name)->ThresholdKey()] = threshold;
  }
  return thresholds;
}

}  // namespace

Json CriteriaToJson(const std::string& study, const ValidityCriteria& c,
                    const CriteriaTolerances& t) {
  Json boundary = Json::array();
  for (const auto& b : c.boundary) {
    boundary.push_back({{"r_k", b.r_k},
                        {"n_points", b.n_points},
                        {"n_passing", b.n_passing},
                        {"r_ftrunc_min", OrNull(b.r_ftrunc_min)},
                        {"r_ftrunc_below", OrNull(b.r_ftrunc_below)},
                        {"dt_ratio_max", OrNull(b.dt_ratio_max)},
                        {"dt_ratio_above", OrNull(b.dt_ratio_above)},
                        {"largest_stable_dt_ratio", OrNull(b.largest_stable_dt_ratio)},
                        {"smallest_diverged_dt_ratio", OrNull(b.smallest_diverged_dt_ratio)}});
  }
  Json fit = nullptr;
  if (c.fit) {
    const PowerLawFit& f = *c.fit;
    fit = {{"n", f.n},
           {"knee_r_k", f.knee_r_k},
           {"p", f.p},
           {"p_stderr", f.p_stderr},
           {"p_low", f.p_low},
           {"p_high", f.p_high},
           {"confidence", c.options.confidence},
           {"c", f.c},
           {"log10_c_stderr", f.log10_c_stderr},
           {"c_envelope", f.c_envelope},
           {"rms_residual_log10", f.rms_residual_log10},
           {"sqrt_rk_inside_interval", f.p_low <= 0.5 && 0.5 <= f.p_high}};
  }
  return {{"study", study},
          {"scheme", "explicit-modal"},
          {"thresholds", ThresholdsJson(c.options)},
          {"r_ftrunc_smallest_studied", c.r_ftrunc_smallest_studied},
          {"boundary", boundary},
          {"unscored", SetAsideToJson(c.unscored)},
          {"undecided", SetAsideToJson(c.undecided)},
          {"fit", fit},
          {"dt_ratio_max", OrNull(c.dt_ratio_max)},
          {"largest_stable_dt_ratio", OrNull(c.largest_stable_dt_ratio)},
          {"smallest_diverged_dt_ratio", OrNull(c.smallest_diverged_dt_ratio)},
          {"tolerances",
           {{"p", t.p},
            {"c_envelope_factor", t.c_envelope_factor},
            {"dt_ratio_factor", t.dt_ratio_factor}}}};
}

ValidityCriteria CriteriaFromJson(const Json& json, const std::string& file,
                                  CriteriaTolerances* tolerances) {
  ValidityCriteria c;
  JsonObjectReader r(json, file, "");
  r.String("study", "");
  r.String("scheme", "");
  {
    const Json* th = r.Get("thresholds");
    if (th == nullptr) r.Fail("thresholds", "required object is missing");
    JsonObjectReader t(*th, file, r.PathOf("thresholds"));
    c.options.thresholds.clear();
    for (const ScoreDefinition& score : Scores()) {
      const std::string key = score.ThresholdKey();
      // A score judging by default was judged by every criteria file; another only when given.
      if (score.default_threshold || t.Get(key) != nullptr) {
        c.options.thresholds[std::string(score.name)] = t.RequiredNumber(key);
      }
    }
    t.Finish();
  }
  c.r_ftrunc_smallest_studied = RequiredIn(r, "r_ftrunc_smallest_studied", kRftrunc);
  if (const Json* boundary = r.Get("boundary"); boundary != nullptr && boundary->is_array()) {
    for (std::size_t i = 0; i < boundary->size(); ++i) {
      JsonObjectReader b((*boundary)[i], file,
                         r.PathOf("boundary") + "[" + std::to_string(i) + "]");
      RkBoundary rb;
      rb.r_k = RequiredIn(b, "r_k", kRk);
      rb.n_points = b.Integer("n_points", 0);
      rb.n_passing = b.Integer("n_passing", 0);
      rb.r_ftrunc_min = OptionalNumber(b, "r_ftrunc_min", kRftrunc);
      rb.r_ftrunc_below = OptionalNumber(b, "r_ftrunc_below", kRftruncBelow);
      rb.dt_ratio_max = OptionalNumber(b, "dt_ratio_max", kPassingDtRatio);
      rb.dt_ratio_above = OptionalNumber(b, "dt_ratio_above", kDtRatio);
      rb.largest_stable_dt_ratio = OptionalNumber(b, "largest_stable_dt_ratio", kDtRatio);
      rb.smallest_diverged_dt_ratio = OptionalNumber(b, "smallest_diverged_dt_ratio", kDtRatio);
      b.Finish();
      c.boundary.push_back(rb);
    }
  } else {
    r.Fail("boundary", "required list is missing");
  }
  c.unscored = SetAsideFromJson(r, "unscored");
  c.undecided = SetAsideFromJson(r, "undecided");
  if (const Json* fit = r.Get("fit"); fit != nullptr && !fit->is_null()) {
    JsonObjectReader f(*fit, file, r.PathOf("fit"));
    PowerLawFit p;
    p.n = f.Integer("n", 0);
    p.knee_r_k = RequiredIn(f, "knee_r_k", kRk);
    p.p = RequiredIn(f, "p", kExponent);
    p.p_stderr = SpreadIn(f, "p_stderr", 0.0, kSpread);
    p.p_low = SpreadIn(f, "p_low", p.p, kExponent);
    p.p_high = SpreadIn(f, "p_high", p.p, kExponent);
    c.options.confidence = f.Number("confidence", c.options.confidence);
    p.c = RequiredIn(f, "c", kCoefficient);
    p.log10_c_stderr = SpreadIn(f, "log10_c_stderr", 0.0, kSpread);
    p.c_envelope = RequiredIn(f, "c_envelope", kCoefficient);
    p.rms_residual_log10 = SpreadIn(f, "rms_residual_log10", 0.0, kSpread);
    f.Get("sqrt_rk_inside_interval");
    f.Finish();
    c.fit = p;
  }
  c.dt_ratio_max = OptionalNumber(r, "dt_ratio_max", kPassingDtRatio);
  c.largest_stable_dt_ratio = OptionalNumber(r, "largest_stable_dt_ratio", kDtRatio);
  c.smallest_diverged_dt_ratio = OptionalNumber(r, "smallest_diverged_dt_ratio", kDtRatio);
  if (const Json* t = r.Get("tolerances"); t != nullptr && tolerances != nullptr) {
    JsonObjectReader tr(*t, file, r.PathOf("tolerances"));
    tolerances->p = ReadNumber(tr, "p", tolerances->p, kSpread);
    tolerances->c_envelope_factor =
        ReadNumber(tr, "c_envelope_factor", tolerances->c_envelope_factor, kFactor);
    tolerances->dt_ratio_factor =
        ReadNumber(tr, "dt_ratio_factor", tolerances->dt_ratio_factor, kFactor);
    tr.Finish();
  }
  r.Finish();
  CheckOptions(c.options, file);
  return c;
}

}  // namespace shockmap
