#pragma once
// Validity criteria derived from scored points (paper §2.4, eqs. 10-11): for every R_k the
// smallest truncation and the largest time step that meet the thresholds, a log-log fit of the
// truncation boundary R_ftrunc > C R_k^p above its knee, and the stability boundary in dt.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/run_status.h"
#include "validation/scores.h"

namespace shockmap {

// One stored point as the criteria see it.
struct ScoredPoint {
  std::int64_t point_id = 0;
  double r_k = 0.0;
  double r_ftrunc = 0.0;
  RunStatus status = RunStatus::kFailed;
  ScoreValues scores;  // By score name (validation/scores.h).
  double dt_s = 0.0;   // As asked: the used step is shortened to land on the window's end.
  double dt_sharp_s = 0.0;
  double dt_paper_s = 0.0;
  double wall_s = 0.0;
  // CPU time of the single-threaded numerical run: unlike wall time, not inflated when the
  // machine is shared (docs/physics.md §4.4).
  double cpu_s = 0.0;
  int n_modes = 0;
  std::int64_t steps = 0;
  // What the run stored beside its status: why it failed, or why it was not scored (for
  // reference_unconverged, the reference's estimate against its tolerance).
  std::string message;
  // Each score's smallest and largest value over the point's perturbed runs
  // (compare/score_spread.h), when its study took them (spread_runs > 0).
  int spread_runs = 0;
  ScoreValues spread_low, spread_high;
  // The scores its reference does not decide, by name (their values absent; `message` says
  // why: the reference's estimate on the part of it they read).
  std::vector<std::string> reference_undecided;

  bool ReferenceUndecides(std::string_view score) const;

  double DtRatio() const { return dt_s / dt_sharp_s; }
};

struct CriteriaOptions {
  // The threshold of each score that judges, by score name (validation/scores.h): by default
  // Err <= 0.10 and SRf >= 0.80.
  std::map<std::string, double, std::less<>> thresholds = DefaultThresholds();
  double confidence = 0.95;

  // Each threshold within its score's range, and the confidence in [0.5, 0.9999].
  bool IsValid(std::string* error) const;
  // Ended ok, its verdict decided, and meets every threshold: a score without a value fails
  // when it is required, passes otherwise (validation/scores.h).
  bool Passes(const ScoredPoint& p) const;
  // Ended ok, a thresholded score's verdict is open and no decided score fails: its spread
  // over the point's perturbed runs holds values on both sides of its threshold (whether the
  // setting passes is not a property of it), or its reference does not decide it
  // (ScoredPoint::reference_undecided). A score fails decidedly when it fails in every
  // perturbed run, or, without spreads, in the point's run.
  bool Undecided(const ScoredPoint& p) const;
  // Why an undecided point's verdicts are open: "Err from 0.071 to 0.13 (max 0.1) over 5
  // runs" for the spreads that straddle a threshold, "Err undecided by the reference (<its
  // message>)" for the thresholded scores the reference does not decide.
  std::string Straddling(const ScoredPoint& p) const;
  // "Err = 0.12 (max 0.1), SRf = 0.9 (min 0.8)": the point's value of each thresholded score.
  std::string Judged(const ScoredPoint& p) const;
};

// The boundary at one R_k. A truncation passes when it and every larger studied truncation
// pass (stable and within both thresholds) at every studied time step up to dt_ratio_max.
struct RkBoundary {
  double r_k = 0.0;
  int n_points = 0;
  int n_passing = 0;
  std::optional<double> r_ftrunc_min;
  // The studied truncation below r_ftrunc_min, the largest (0 when r_ftrunc_min is the
  // smallest studied), or the largest studied when none passes: the grid puts the boundary
  // above it. Unknown (nullopt) in a baseline written before it was recorded.
  std::optional<double> r_ftrunc_below;
  // Largest dt / dt_sharp such that every point at or below it, at or above r_ftrunc_min, passes.
  std::optional<double> dt_ratio_max;
  // The smallest studied dt / dt_sharp above dt_ratio_max (nullopt: it is the largest studied).
  std::optional<double> dt_ratio_above;
  // The smallest dt / dt_sharp at which a point diverged or ended unstable, and the largest
  // below it at which a point ended ok: every point at or below it stayed stable.
  std::optional<double> largest_stable_dt_ratio;
  std::optional<double> smallest_diverged_dt_ratio;
};

// log10 R_ftrunc_min = log10 C + p log10 R_k, least squares (GSL) over the R_k above the knee.
struct PowerLawFit {
  int n = 0;
  double knee_r_k = 0.0;  // Smallest R_k where the boundary rises above the smallest truncation.
  double p = 0.0, p_stderr = 0.0, p_low = 0.0, p_high = 0.0;  // p and its confidence interval.
  double c = 0.0, log10_c_stderr = 0.0;
  // C raised so that C R_k^p covers every observed boundary point: the criterion checked.
  double c_envelope = 0.0;
  double rms_residual_log10 = 0.0;
};

// The points of one R_k that decide nothing: unscored (their reference did not converge: the
// boundary does not see them) or undecided (CriteriaOptions::Undecided: they cannot make a
// setting pass); the criteria say so.
struct PointsSetAside {
  double r_k = 0.0;
  int n_points = 0;
  std::string reason;  // The first such point's: its stored message, or its straddling spread.
};

struct ValidityCriteria {
  CriteriaOptions options;
  std::vector<RkBoundary> boundary;       // Ascending R_k.
  std::vector<PointsSetAside> unscored;   // Ascending R_k.
  std::vector<PointsSetAside> undecided;  // Ascending R_k.
  double r_ftrunc_smallest_studied = 0.0;
  std::optional<PowerLawFit> fit;
  // Largest dt / dt_sharp that passes at every R_k with a boundary.
  std::optional<double> dt_ratio_max;
  // The smallest largest_stable_dt_ratio and the smallest smallest_diverged_dt_ratio over the
  // R_k: stable at every R_k up to the first, stability lost at some R_k from the second.
  std::optional<double> largest_stable_dt_ratio;
  std::optional<double> smallest_diverged_dt_ratio;

  // The truncation the criterion requires at r_k: C_envelope r_k^p above the knee, the smallest
  // studied truncation below it; nullopt without a fit or a boundary.
  std::optional<double> RequiredRFtrunc(double r_k) const;
};

// "Err <= 0.1, SRf >= 0.8", each threshold in registry order; with its source when asked:
// "Err <= 0.1 (paper eq. 8), ...".
std::string ThresholdsText(const CriteriaOptions& options, bool with_sources);

// Diverged or unstable: the run lost stability (its time step is past the bound).
bool LostStability(RunStatus status);

// Points with status reference_unconverged carry no score: the boundary ignores them and
// `unscored` lists them by R_k. Undecided points fail (a setting passes only where every
// verdict is decided) and `undecided` lists them by R_k.
ValidityCriteria DeriveCriteria(const std::vector<ScoredPoint>& points,
                                const CriteriaOptions& options);

// "the criteria's study left 10 points unscored, at R_k = 3.16e+05 (4) and 1e+06 (6): ..."
// naming each R_k, its count and the first one's reason; empty when every point was scored.
std::optional<std::string> UnscoredWarning(const ValidityCriteria& criteria);
// "the criteria's study left 12 points undecided, at R_k = ...", as UnscoredWarning, for the
// R_k of `undecided` (the criteria's, or those an advice rests on); empty when it is.
// Undecided by a straddling spread or by a reference that does not decide a thresholded score.
std::optional<std::string> UndecidedWarning(const std::vector<PointsSetAside>& undecided);

struct Contradiction {
  ScoredPoint point;
  std::string reason;
};

// Stored points that meet the criteria (truncation at least the required one, dt / dt_sharp at
// most dt_ratio_max) but fail a threshold or did not run to the end, at the R_k the criteria
// were derived over (from their smallest studied R_k to their largest): the criteria say
// nothing beyond them.
std::vector<Contradiction> FindContradictions(const ValidityCriteria& criteria,
                                              const std::vector<ScoredPoint>& points);

}  // namespace shockmap
