#include "validation/advice.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/cantilever_impact.h"
#include "core/input_error.h"

namespace shockmap {
namespace {

constexpr double kSame = 1e-9;  // Relative: grid values computed two ways compare equal.

bool Same(double a, double b) { return std::abs(a - b) <= kSame * std::abs(b); }

// The truncation and time step chosen, what they rest on and why.
struct Basis {
  double r_ftrunc = 0.0;
  double dt_ratio = 0.0;
  std::vector<double> studied_r_k;
  std::string words;
  std::vector<std::string> warnings;
};

// Throws InputError when no truncation passes at every studied time step at b.r_k.
const RkBoundary& Passing(const RkBoundary& b) {
  if (!b.r_ftrunc_min || !b.dt_ratio_max) {
    throw InputError(fmt::format(
        "no studied truncation passes the thresholds at R_k = {:g}, the studied R_k the advice "
        "would rest on; study larger R_ftrunc or smaller time steps there",
        b.r_k));
  }
  return b;
}

// The largest studied dt / dt_sharp below `ratio`, or `ratio` when none is.
double FinerStudiedRatio(const std::vector<ScoredPoint>& points, double ratio) {
  double finer = 0.0;
  for (const auto& p : points) {
    if (p.DtRatio() < ratio * (1 - 1e-6)) finer = std::max(finer, p.DtRatio());
  }
  return finer > 0.0 ? finer : ratio;
}

// Between two studied R_k: the larger truncation of the two, so the advice is never less than
// either side needed (the boundary grows with R_k, eqs. 10-11), and the studied time step one
// finer than the smaller of their largest passing ones: near the sharp bound Err varies with
// R_k by more than the threshold (measured on quick: R_ftrunc 215, 0.9 dt_sharp passes at
// R_k = 3.16e4 and 1e5, Err 0.073 and 0.087, and failed between them, Err 0.28 at 5.62e4 with
// the earlier reference).
Basis Between(const RkBoundary& below, const RkBoundary& above, double r_k,
              const std::vector<ScoredPoint>& points) {
  Basis b{std::max(*below.r_ftrunc_min, *above.r_ftrunc_min),
          FinerStudiedRatio(points, std::min(*below.dt_ratio_max, *above.dt_ratio_max)),
          {below.r_k, above.r_k},
          fmt::format("the larger R_ftrunc_min of the studied R_k = {:g} and {:g} around it, and "
                      "the studied dt/dt_sharp one finer than the smaller of their largest "
                      "passing ones",
                      below.r_k, above.r_k),
          {}};
  if (!Same(*below.r_ftrunc_min, *above.r_ftrunc_min) ||
      !Same(*below.dt_ratio_max, *above.dt_ratio_max)) {
    b.warnings.push_back(fmt::format(
        "R_k = {:g} lies between sparse studied values: the boundary changes from R_ftrunc_min "
        "{:g} (dt/dt_sharp max {:g}) at R_k = {:g} to {:g} ({:g}) at R_k = {:g}; the advice "
        "takes the safer side, study R_k in between to refine it",
        r_k, *below.r_ftrunc_min, *below.dt_ratio_max, below.r_k, *above.r_ftrunc_min,
        *above.dt_ratio_max, above.r_k));
  }
  return b;
}

// Outside the studied R_k, where the criteria know least, a time step never less conservative
// than inside: the studied dt / dt_sharp one finer than the smaller of the largest passing ones
// at the edge of the studied range and its studied neighbour, as Between takes it.
double OutsideRatio(const std::vector<RkBoundary>& all, bool above,
                    const std::vector<ScoredPoint>& points) {
  const RkBoundary& edge = above ? all.back() : all.front();
  double ratio = *edge.dt_ratio_max;
  if (all.size() > 1) {
    const RkBoundary& neighbour = above ? all[all.size() - 2] : all[1];
    if (neighbour.dt_ratio_max) ratio = std::min(ratio, *neighbour.dt_ratio_max);
  }
  return FinerStudiedRatio(points, ratio);
}

std::string OutsideWarning(double r_k, const std::vector<RkBoundary>& all, const char* side) {
  return fmt::format(
      "R_k = {:g} lies outside the studied range [{:g}, {:g}], {}: the criteria know least "
      "there, so dt/dt_sharp is one studied step finer than the largest passing at the edge of "
      "the range (as between studied values); study R_k out there to refine it",
      r_k, all.front().r_k, all.back().r_k, side);
}

// Past the largest studied R_k: the fitted envelope C R_k^p, never below the largest studied
// boundary, and OutsideRatio's time step.
Basis Beyond(const ValidityCriteria& c, const RkBoundary& last, double r_k,
             const std::vector<ScoredPoint>& points) {
  if (!c.fit) {
    throw InputError(fmt::format(
        "R_k = {:g} lies above the largest studied R_k = {:g} and the study has no fitted "
        "truncation boundary to extrapolate; study larger R_k",
        r_k, last.r_k));
  }
  const double envelope = c.fit->c_envelope * std::pow(r_k, c.fit->p);
  return {std::max(*last.r_ftrunc_min, envelope),
          OutsideRatio(c.boundary, true, points),
          {last.r_k},
          fmt::format("the fitted envelope {:.3g} R_k^{:.3f}, at least the R_ftrunc_min of the "
                      "largest studied R_k = {:g}, and the studied dt/dt_sharp one finer than the "
                      "largest passing there",
                      c.fit->c_envelope, c.fit->p, last.r_k),
          {OutsideWarning(r_k, c.boundary, "above it (the truncation is extrapolated)")}};
}

// Throws InputError when the study has no scored points.
Basis Choose(const ValidityCriteria& c, const std::vector<ScoredPoint>& points, double r_k) {
  const auto& all = c.boundary;  // Ascending R_k.
  if (all.empty()) throw InputError("the study has no scored explicit-modal points to advise from");
  const auto above =
      std::ranges::find_if(all, [&](const RkBoundary& b) { return b.r_k >= r_k * (1 - kSame); });
  if (above == all.end()) return Beyond(c, Passing(all.back()), r_k, points);
  if (Same(above->r_k, r_k)) {
    const RkBoundary& b = Passing(*above);
    return {*b.r_ftrunc_min,
            *b.dt_ratio_max,
            {b.r_k},
            fmt::format("the boundary studied at R_k = {:g}", b.r_k),
            {}};
  }
  if (above == all.begin()) {
    const RkBoundary& b = Passing(*above);
    return {*b.r_ftrunc_min,
            OutsideRatio(all, false, points),
            {b.r_k},
            fmt::format("the R_ftrunc_min of the smallest studied R_k = {:g} (a softer contact "
                        "needs no more) and the studied dt/dt_sharp one finer than the largest "
                        "passing there",
                        b.r_k),
            {OutsideWarning(r_k, all, "below it")}};
  }
  return Between(Passing(*std::prev(above)), Passing(*above), r_k, points);
}

// At each studied R_k of the basis, the points at the studied truncations on either side of
// the advised one, each at the largest studied time step not above the advised one.
std::vector<ScoredPoint> NearestPoints(const std::vector<ScoredPoint>& points, const Basis& b) {
  std::vector<ScoredPoint> nearest;
  for (double r_k : b.studied_r_k) {
    std::optional<double> lower, upper;
    for (const auto& p : points) {
      if (!Same(p.r_k, r_k)) continue;
      if (p.r_ftrunc < b.r_ftrunc * (1 - kSame)) {
        if (!lower || p.r_ftrunc > *lower) lower = p.r_ftrunc;
      } else if (!upper || p.r_ftrunc < *upper) {
        upper = p.r_ftrunc;
      }
    }
    for (const auto& truncation : {lower, upper}) {
      if (!truncation) continue;
      const ScoredPoint* best = nullptr;
      for (const auto& p : points) {
        if (!Same(p.r_k, r_k) || !Same(p.r_ftrunc, *truncation)) continue;
        if (p.DtRatio() > b.dt_ratio * (1 + kSame)) continue;
        if (best == nullptr || p.DtRatio() > best->DtRatio()) best = &p;
      }
      if (best != nullptr) nearest.push_back(*best);
    }
  }
  return nearest;
}

// The criteria's undecided points at the studied R_k an advice rests on: those that may have
// raised its boundary.
std::vector<PointsSetAside> UndecidedAt(const ValidityCriteria& criteria,
                                        const std::vector<double>& studied_r_k) {
  std::vector<PointsSetAside> at;
  for (const PointsSetAside& u : criteria.undecided) {
    if (std::ranges::any_of(studied_r_k, [&u](double r_k) { return Same(u.r_k, r_k); }))
      at.push_back(u);
  }
  return at;
}

double MedianSecondsPerModeStep(const std::vector<ScoredPoint>& points) {
  std::vector<double> per_mode_step;
  for (const auto& p : points) {
    if (p.status == RunStatus::kOk && p.steps > 0 && p.n_modes > 0) {
      per_mode_step.push_back(p.cpu_s / (static_cast<double>(p.steps) * p.n_modes));
    }
  }
  if (per_mode_step.empty()) return 0.0;
  std::ranges::nth_element(per_mode_step, per_mode_step.begin() + per_mode_step.size() / 2);
  return per_mode_step[per_mode_step.size() / 2];
}

}  // namespace

Advice Advise(const CantileverImpact& problem, double window_s, const ValidityCriteria& criteria,
              const std::vector<ScoredPoint>& points, double r_k) {
  Basis basis = Choose(criteria, points, r_k);
  Advice a;
  a.r_k = r_k;
  a.r_ftrunc = basis.r_ftrunc;
  a.dt_ratio = basis.dt_ratio;
  CantileverImpact at_r_k = problem;
  at_r_k.r_k = r_k;
  const ImpactModel model = BuildImpactModel(at_r_k, Scheme::kExplicitModal, a.r_ftrunc);
  a.n_modes = model.n_modes;
  a.dt_sharp_s = model.bounds.dt_sharp_s;
  a.dt_s = a.dt_ratio * a.dt_sharp_s;
  a.window_s = window_s;
  a.steps = static_cast<std::int64_t>(std::ceil(a.window_s / a.dt_s));
  a.seconds_per_mode_step = MedianSecondsPerModeStep(points);
  a.expected_cpu_s = a.seconds_per_mode_step * static_cast<double>(a.steps) * a.n_modes;
  a.nearest = NearestPoints(points, basis);
  a.studied_r_k = std::move(basis.studied_r_k);
  a.basis = std::move(basis.words);
  a.warnings = std::move(basis.warnings);
  if (const auto unscored = UnscoredWarning(criteria)) a.warnings.push_back(*unscored);
  if (const auto undecided = UndecidedWarning(UndecidedAt(criteria, a.studied_r_k)))
    a.warnings.push_back(*undecided);
  return a;
}

}  // namespace shockmap
