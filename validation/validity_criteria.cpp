#include "validation/validity_criteria.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/validity.h"

namespace shockmap {

bool CriteriaOptions::IsValid(std::string* error) const {
  for (const auto& [name, threshold] : thresholds) {
    const ScoreDefinition* score = FindScore(name);
    if (score == nullptr) {
      if (error != nullptr) *error = "no score named \"" + name + "\" (validation/scores.h)";
      return false;
    }
    if (!RequireInRange(score->ThresholdKey().c_str(), threshold, score->threshold_low,
                        score->threshold_high, error)) {
      return false;
    }
  }
  return RequireInRange("confidence", confidence, 0.5, 0.9999, error);
}

bool CriteriaOptions::Passes(const ScoredPoint& p) const {
  if (p.status != RunStatus::kOk || Undecided(p)) return false;
  for (const auto& [name, threshold] : thresholds) {
    const std::optional<double> value = p.scores[name];
    const ScoreDefinition* score = FindScore(name);
    if (value ? !score->Meets(*value, threshold) : score->required) return false;
  }
  return true;
}

bool ScoredPoint::ReferenceUndecides(std::string_view score) const {
  return std::ranges::find(reference_undecided, score) != reference_undecided.end();
}

namespace {

// What a point says of score `name` against `threshold`: met or failed (in every perturbed run
// when it has a spread, else in its run), or open: its spread straddles the threshold, or its
// reference does not decide it. A score without a spread at a point with spreads says nothing
// (kNone).
enum class Verdict { kNone, kMet, kFailed, kOpen };

Verdict VerdictOf(const ScoredPoint& p, std::string_view name, double threshold) {
  if (p.ReferenceUndecides(name)) return Verdict::kOpen;
  const ScoreDefinition* score = FindScore(name);
  if (p.spread_runs == 0) {
    const std::optional<double> value = p.scores[name];
    const bool meets = value ? score->Meets(*value, threshold) : !score->required;
    return meets ? Verdict::kMet : Verdict::kFailed;
  }
  const std::optional<double> low = p.spread_low[name], high = p.spread_high[name];
  if (!low || !high) return Verdict::kNone;
  const bool low_meets = score->Meets(*low, threshold), high_meets = score->Meets(*high, threshold);
  if (low_meets != high_meets) return Verdict::kOpen;
  return low_meets ? Verdict::kMet : Verdict::kFailed;
}

}  // namespace

bool CriteriaOptions::Undecided(const ScoredPoint& p) const {
  if (p.status != RunStatus::kOk) return false;
  bool open = false;
  for (const auto& [name, threshold] : thresholds) {
    const Verdict v = VerdictOf(p, name, threshold);
    if (v == Verdict::kFailed) return false;  // Fails decidedly: the point is decided.
    open = open || v == Verdict::kOpen;
  }
  return open;
}

std::string CriteriaOptions::Straddling(const ScoredPoint& p) const {
  std::vector<std::string> straddling, by_reference;
  for (const auto& [name, threshold] : thresholds) {
    if (VerdictOf(p, name, threshold) != Verdict::kOpen) continue;
    const ScoreDefinition* score = FindScore(name);
    if (p.ReferenceUndecides(name)) {
      by_reference.push_back(fmt::format("{} undecided by the reference", score->label));
      continue;
    }
    straddling.push_back(fmt::format("{} from {:.3g} to {:.3g} ({} {:g})", score->label,
                                     *p.spread_low[name], *p.spread_high[name],
                                     score->better == Better::kSmaller ? "max" : "min", threshold));
  }
  std::vector<std::string> each;
  if (!straddling.empty())
    each.push_back(fmt::format("{} over {} runs", fmt::join(straddling, ", "), p.spread_runs));
  if (!by_reference.empty())
    each.push_back(fmt::format("{} ({})", fmt::join(by_reference, ", "), p.message));
  return fmt::format("{}", fmt::join(each, "; "));
}

std::string CriteriaOptions::Judged(const ScoredPoint& p) const {
  std::ostringstream judged;
  for (const ScoreDefinition& score : Scores()) {
    const auto threshold = thresholds.find(score.name);
    if (threshold == thresholds.end()) continue;
    judged << (judged.tellp() > 0 ? ", " : "") << score.label << " = "
           << p.scores[score.name].value_or(NAN) << " ("
           << (score.better == Better::kSmaller ? "max " : "min ") << threshold->second << ")";
  }
  return judged.str();
}

std::string ThresholdsText(const CriteriaOptions& options, bool with_sources) {
  std::ostringstream text;
  for (const ScoreDefinition& score : Scores()) {
    const auto threshold = options.thresholds.find(score.name);
    if (threshold == options.thresholds.end()) continue;
    text << (text.tellp() > 0 ? ", " : "") << score.label
         << (score.better == Better::kSmaller ? " <= " : " >= ") << threshold->second;
    if (with_sources) text << " (" << score.source << ")";
  }
  return text.str();
}

std::optional<double> ValidityCriteria::RequiredRFtrunc(double r_k) const {
  if (!fit) return std::nullopt;
  if (r_k < fit->knee_r_k) return r_ftrunc_smallest_studied;
  return std::max(r_ftrunc_smallest_studied, fit->c_envelope * std::pow(r_k, fit->p));
}

namespace {

bool Scorable(const ScoredPoint& p) { return p.status != RunStatus::kReferenceUnconverged; }

}  // namespace

bool LostStability(RunStatus status) {
  return status == RunStatus::kDiverged || status == RunStatus::kUnstable;
}

namespace {

template <typename T>
void KeepMax(std::optional<T>& slot, T v) {
  if (!slot || v > *slot) slot = v;
}
template <typename T>
void KeepMin(std::optional<T>& slot, T v) {
  if (!slot || v < *slot) slot = v;
}

RkBoundary BoundaryAt(double r_k, const std::vector<const ScoredPoint*>& at,
                      const CriteriaOptions& options) {
  RkBoundary b;
  b.r_k = r_k;
  b.n_points = static_cast<int>(at.size());
  for (const auto* p : at) {
    if (options.Passes(*p)) ++b.n_passing;
    if (LostStability(p->status)) KeepMin(b.smallest_diverged_dt_ratio, p->DtRatio());
  }
  // Stable up to the largest ratio below the first loss of stability, so the two never overlap.
  for (const auto* p : at) {
    if (p->status != RunStatus::kOk) continue;
    if (!b.smallest_diverged_dt_ratio || p->DtRatio() < *b.smallest_diverged_dt_ratio) {
      KeepMax(b.largest_stable_dt_ratio, p->DtRatio());
    }
  }
  // Candidate dt ratios, smallest first: the boundary is judged at the finest time step and
  // the time step is then raised while everything above the boundary keeps passing.
  std::vector<double> ratios;
  for (const auto* p : at) ratios.push_back(p->DtRatio());
  std::ranges::sort(ratios);
  ratios.erase(std::unique(ratios.begin(), ratios.end(),
                           [](double a, double c) { return std::abs(a - c) <= 1e-9 * c; }),
               ratios.end());
  if (ratios.empty()) return b;
  auto passes_from = [&](double r_ftrunc, double ratio) {
    bool any = false;
    for (const auto* p : at) {
      if (p->r_ftrunc < r_ftrunc || p->DtRatio() > ratio * (1 + 1e-9)) continue;
      if (!options.Passes(*p)) return false;
      any = true;
    }
    return any;
  };
  std::vector<double> truncations;
  for (const auto* p : at) truncations.push_back(p->r_ftrunc);
  std::ranges::sort(truncations);
  truncations.erase(std::unique(truncations.begin(), truncations.end()), truncations.end());
  b.r_ftrunc_below = truncations.back();
  for (std::size_t i = 0; i < truncations.size(); ++i) {
    if (passes_from(truncations[i], ratios.front())) {
      b.r_ftrunc_min = truncations[i];
      b.r_ftrunc_below = i > 0 ? truncations[i - 1] : 0.0;
      break;
    }
  }
  if (!b.r_ftrunc_min) return b;
  for (std::size_t i = 0; i < ratios.size(); ++i) {
    if (!passes_from(*b.r_ftrunc_min, ratios[i])) {
      b.dt_ratio_above = ratios[i];
      break;
    }
    b.dt_ratio_max = ratios[i];
  }
  return b;
}

std::optional<PowerLawFit> FitBoundary(const std::vector<RkBoundary>& boundary,
                                       double smallest_truncation, double confidence) {
  std::vector<double> x, y;
  PowerLawFit fit;
  for (const auto& b : boundary) {
    if (!b.r_ftrunc_min || *b.r_ftrunc_min <= smallest_truncation) continue;
    if (x.empty()) fit.knee_r_k = b.r_k;
    x.push_back(std::log10(b.r_k));
    y.push_back(std::log10(*b.r_ftrunc_min));
  }
  fit.n = static_cast<int>(x.size());
  if (fit.n < 2) return std::nullopt;
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sumsq = 0;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  fit.p = c1;
  fit.c = std::pow(10.0, c0);
  fit.p_stderr = std::sqrt(cov11);
  fit.log10_c_stderr = std::sqrt(cov00);
  fit.rms_residual_log10 = std::sqrt(sumsq / fit.n);
  // Student t with n - 2 degrees of freedom; with two points the interval is unbounded.
  const double t = fit.n > 2 ? gsl_cdf_tdist_Pinv(0.5 + confidence / 2, fit.n - 2)
                             : std::numeric_limits<double>::infinity();
  fit.p_low = fit.p - t * fit.p_stderr;
  fit.p_high = fit.p + t * fit.p_stderr;
  double lift = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) lift = std::max(lift, y[i] - (c0 + c1 * x[i]));
  fit.c_envelope = std::pow(10.0, c0 + lift);
  return fit;
}

}  // namespace

ValidityCriteria DeriveCriteria(const std::vector<ScoredPoint>& points,
                                const CriteriaOptions& options) {
  ValidityCriteria c;
  c.options = options;
  std::map<double, std::vector<const ScoredPoint*>> by_rk;
  std::map<double, PointsSetAside> unscored, undecided;
  auto set_aside = [](std::map<double, PointsSetAside>& by, const ScoredPoint& p,
                      std::string reason) {
    ++by.try_emplace(p.r_k, PointsSetAside{p.r_k, 0, std::move(reason)}).first->second.n_points;
  };
  for (const auto& p : points) {
    if (!Scorable(p)) {
      set_aside(unscored, p, p.message);
      continue;
    }
    if (options.Undecided(p)) {
      set_aside(undecided, p,
                fmt::format("point {} (R_ftrunc {:g}, dt {:.3g} dt_sharp): {}", p.point_id,
                            p.r_ftrunc, p.DtRatio(), options.Straddling(p)));
    }
    by_rk[p.r_k].push_back(&p);
    c.r_ftrunc_smallest_studied = c.r_ftrunc_smallest_studied == 0.0
                                      ? p.r_ftrunc
                                      : std::min(c.r_ftrunc_smallest_studied, p.r_ftrunc);
  }
  for (const auto& [r_k, at] : by_rk) {
    c.boundary.push_back(BoundaryAt(r_k, at, options));
    const RkBoundary& b = c.boundary.back();
    if (b.dt_ratio_max) KeepMin(c.dt_ratio_max, *b.dt_ratio_max);
    if (b.largest_stable_dt_ratio) KeepMin(c.largest_stable_dt_ratio, *b.largest_stable_dt_ratio);
    if (b.smallest_diverged_dt_ratio) {
      KeepMin(c.smallest_diverged_dt_ratio, *b.smallest_diverged_dt_ratio);
    }
  }
  for (auto& [r_k, u] : unscored) c.unscored.push_back(std::move(u));
  for (auto& [r_k, u] : undecided) c.undecided.push_back(std::move(u));
  c.fit = FitBoundary(c.boundary, c.r_ftrunc_smallest_studied, options.confidence);
  return c;
}

namespace {

// "4 points", "3.16e+05 (1), 1e+06 (3)" and "at R_k = 3.16e+05: " the first one's reason.
struct SetAsideText {
  std::string count, at, first;
};
SetAsideText Describe(const std::vector<PointsSetAside>& set_aside) {
  long long total = 0;  // A baseline's counts are read from a file: summed without overflow.
  std::vector<std::string> each;
  for (const PointsSetAside& u : set_aside) {
    total += u.n_points;
    each.push_back(fmt::format("{:.3g} ({})", u.r_k, u.n_points));
  }
  const PointsSetAside& first = set_aside.front();
  return {total == 1 ? std::string("1 point") : fmt::format("{} points", total),
          fmt::format("{}", fmt::join(each, ", ")),
          fmt::format("at R_k = {:.3g}: {}", first.r_k,
                      first.reason.empty() ? "no reason stored" : first.reason)};
}

}  // namespace

std::optional<std::string> UnscoredWarning(const ValidityCriteria& criteria) {
  if (criteria.unscored.empty()) return std::nullopt;
  const SetAsideText t = Describe(criteria.unscored);
  return fmt::format(
      "the criteria's study left {} unscored, at R_k = {}: their reference did not converge, so "
      "the boundary there is not measured ({})",
      t.count, t.at, t.first);
}

std::optional<std::string> UndecidedWarning(const std::vector<PointsSetAside>& undecided) {
  if (undecided.empty()) return std::nullopt;
  const SetAsideText t = Describe(undecided);
  return fmt::format(
      "the criteria's study left {} undecided, at R_k = {}: a score's spread under "
      "perturbations that leave the setting as it is straddles its threshold, or their reference "
      "does not decide a thresholded score, so they make no setting pass ({})",
      t.count, t.at, t.first);
}

std::vector<Contradiction> FindContradictions(const ValidityCriteria& criteria,
                                              const std::vector<ScoredPoint>& points) {
  std::vector<Contradiction> found;
  if (!criteria.fit || !criteria.dt_ratio_max || criteria.boundary.empty()) return found;
  const double r_k_low = criteria.boundary.front().r_k, r_k_high = criteria.boundary.back().r_k;
  for (const auto& p : points) {
    if (!Scorable(p)) continue;
    if (p.r_k < r_k_low * (1 - 1e-9) || p.r_k > r_k_high * (1 + 1e-9)) continue;
    const double required = *criteria.RequiredRFtrunc(p.r_k);
    if (p.r_ftrunc < required * (1 - 1e-9) || p.DtRatio() > *criteria.dt_ratio_max * (1 + 1e-9)) {
      continue;
    }
    if (criteria.options.Passes(p)) continue;
    std::ostringstream why;
    why << "meets the criteria (R_ftrunc " << p.r_ftrunc << " >= " << required << ", dt/dt_sharp "
        << p.DtRatio() << " <= " << *criteria.dt_ratio_max << ") but ";
    if (p.status != RunStatus::kOk) {
      why << "ended " << ToString(p.status);
    } else if (criteria.options.Undecided(p)) {
      why << "its verdict is not decided: " << criteria.options.Straddling(p);
    } else {
      why << criteria.options.Judged(p);
    }
    found.push_back({p, why.str()});
  }
  return found;
}

}  // namespace shockmap
