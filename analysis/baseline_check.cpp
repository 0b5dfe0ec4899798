#include "analysis/baseline_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "validation/boundary_comparison.h"

namespace shockmap {
namespace {

std::string Num(std::optional<double> v) { return v ? fmt::format("{:.4g}", *v) : "-"; }

// Whether a and b are positive and within `factor` of each other, either way.
bool WithinFactor(double a, double b, double factor) {
  return a > 0 && b > 0 && std::max(a / b, b / a) <= factor * (1 + 1e-12);
}

// The studied truncation at `r_k` below `r_ftrunc_min`, the largest (0 when none), or the
// largest studied when r_ftrunc_min is none.
double StudiedBelow(const std::vector<ScoredPoint>& points, double r_k,
                    const std::optional<double>& r_ftrunc_min) {
  double below = 0.0;
  for (const ScoredPoint& p : points) {
    if (std::abs(p.r_k - r_k) > 1e-9 * r_k) continue;
    if (!r_ftrunc_min || p.r_ftrunc < *r_ftrunc_min * (1 - 1e-9))
      below = std::max(below, p.r_ftrunc);
  }
  return below;
}

// "(100, 215.4]", "above 1000": where a grid put a truncation boundary.
std::string Span(const ResolvedBoundary& b) {
  if (!b.value) return fmt::format("above {:.4g}", b.low);
  return fmt::format("({:.4g}, {:.4g}]", b.low, *b.value);
}

// Why the fits and the time-step bounds of two criteria cannot be set side by side: derived over
// different R_k, or with a different smallest truncation (the knee is the first R_k whose
// boundary rises above it); nullopt when they can.
std::optional<std::string> FitGridDifference(const ValidityCriteria& baseline,
                                             const ValidityCriteria& current) {
  auto r_ks = [](const ValidityCriteria& c) {
    std::vector<double> r_k;
    for (const RkBoundary& b : c.boundary) r_k.push_back(b.r_k);
    return r_k;
  };
  const std::vector<double> was = r_ks(baseline), is = r_ks(current);
  const bool same_r_k = std::ranges::equal(
      was, is, [](double x, double y) { return std::abs(x - y) <= 1e-9 * std::max(x, y); });
  if (!same_r_k) {
    auto range = [](const std::vector<double>& r) {
      return r.empty() ? std::string("none")
                       : fmt::format("{:.4g} to {:.4g} ({} values)", r.front(), r.back(), r.size());
    };
    return fmt::format(
        "not comparable: grids differ at R_k (the baseline studied {}, the study {})", range(was),
        range(is));
  }
  const double a = baseline.r_ftrunc_smallest_studied, b = current.r_ftrunc_smallest_studied;
  if (std::abs(a - b) > 1e-9 * std::max(a, b)) {
    return fmt::format(
        "not comparable: grids differ at R_ftrunc (the smallest studied is {:g} in the baseline, "
        "{:g} in the study)",
        a, b);
  }
  return std::nullopt;
}

}  // namespace

BaselineCheck CheckAgainstBaseline(const ValidityCriteria& baseline, const CriteriaTolerances& t,
                                   const ValidityCriteria& current,
                                   const std::vector<ScoredPoint>& points) {
  BaselineCheck check;
  std::vector<std::string>& problems = check.contradictions;
  const std::optional<std::string> other_grid = FitGridDifference(baseline, current);
  if (other_grid) {
    check.not_comparable.push_back("criteria fit and dt/dt_sharp max: " + *other_grid);
  } else if (baseline.fit.has_value() != current.fit.has_value()) {
    problems.push_back(fmt::format("criterion fit: baseline {}, now {}",
                                   baseline.fit ? "fitted" : "none",
                                   current.fit ? "fitted" : "none"));
  } else if (baseline.fit) {
    const PowerLawFit& a = *baseline.fit;
    const PowerLawFit& b = *current.fit;
    if (std::abs(a.p - b.p) > t.p) {
      problems.push_back(
          fmt::format("criterion p: baseline {:.4f}, now {:.4f} (tolerance {:g})", a.p, b.p, t.p));
    }
    if (!WithinFactor(a.c_envelope, b.c_envelope, t.c_envelope_factor)) {
      problems.push_back(fmt::format("criterion C: baseline {:.4g}, now {:.4g} (tolerance x{:g})",
                                     a.c_envelope, b.c_envelope, t.c_envelope_factor));
    }
    if (a.knee_r_k != b.knee_r_k) {
      problems.push_back(
          fmt::format("criterion knee R_k: baseline {:.4g}, now {:.4g}", a.knee_r_k, b.knee_r_k));
    }
  }
  if (!other_grid && baseline.dt_ratio_max && current.dt_ratio_max &&
      !WithinFactor(*baseline.dt_ratio_max, *current.dt_ratio_max, t.dt_ratio_factor)) {
    problems.push_back(fmt::format("criterion dt/dt_sharp max: baseline {:.4g}, now {:.4g}",
                                   *baseline.dt_ratio_max, *current.dt_ratio_max));
  }
  for (const auto& old : baseline.boundary) {
    for (const auto& now : current.boundary) {
      if (std::abs(now.r_k - old.r_k) > 1e-9 * old.r_k) continue;
      // A baseline that did not record where its grid put the boundary is taken to share the
      // study's grid.
      const ResolvedBoundary was =
          TruncationBoundary(old, StudiedBelow(points, old.r_k, old.r_ftrunc_min));
      const ResolvedBoundary is = TruncationBoundary(now, 0.0);
      const BoundaryComparison comparison = Compare(was, is);
      if (comparison == BoundaryComparison::kAlike) continue;
      const std::string line =
          fmt::format("criterion R_ftrunc_min at R_k = {:.4g}: baseline {}, now {}", old.r_k,
                      Num(old.r_ftrunc_min), Num(now.r_ftrunc_min));
      if (comparison == BoundaryComparison::kDiffers) {
        problems.push_back(line);
      } else {
        check.not_comparable.push_back(
            fmt::format("{}: not comparable: grids differ at R_ftrunc (the baseline puts the "
                        "boundary in {}, the study in {})",
                        line, Span(was), Span(is)));
      }
    }
  }
  for (const auto& c : FindContradictions(baseline, points)) {
    problems.push_back(fmt::format("point {} (R_k = {:.4g}, R_ftrunc = {:g}): {}", c.point.point_id,
                                   c.point.r_k, c.point.r_ftrunc, c.reason));
  }
  return check;
}

}  // namespace shockmap
