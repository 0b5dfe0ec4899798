#pragma once
// Two stored studies of the paper's problem side by side (`shockmap diff A B`): the settings
// they differ in, their validity criteria R_k by R_k (derived as `criteria derive` derives
// them), the points whose outcome changed, and those studied in one only. Its text, JSON and
// tables are views/study_diff_text.h, its overlaid boundary map views/study_diff_map.h.

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "validation/boundary_comparison.h"
#include "validation/validity_criteria.h"

namespace shockmap {

// One stored point as the diff identifies it: the parameters it was asked with and its scores.
struct DiffPoint {
  ScoredPoint scored;
  std::string scheme;     // "explicit-modal", "implicit-full".
  std::string dt_rule;    // "sharp" or "paper"; empty when the step was asked in seconds.
  double dt_asked = 0.0;  // The rule's factor, or the seconds asked.
  double window_s = 0.0;
  double mass_damping_per_s = 0.0;
};

// A stored study as the diff reads it.
struct DiffedStudy {
  std::string name;
  std::string database_path;
  // The problem and scoring settings by dotted path ("psd.window", "window_s", "problem.gap_m",
  // "thresholds.err"), from the stored study file and the thresholds judged with.
  std::map<std::string, nlohmann::json> settings;
  std::vector<DiffPoint> points;  // Every scheme, by point_id.
  ValidityCriteria criteria;      // Of the explicit modal points, as `criteria derive`.
};

// Reads `study` and derives its criteria with its own thresholds, each of `given` (by score
// name) over them. Throws InputError when the database has no such study, when it is not a
// study of the paper's problem (a scene sweep, an ensemble) or has no scored explicit modal
// point; `role` ("A", "B") names the argument in the message.
DiffedStudy LoadDiffedStudy(const std::string& database_path, const std::string& study,
                            const std::map<std::string, double, std::less<>>& given,
                            const std::string& role);

// The settings whose values change what Err and SRf measure, so that the scores of studies that
// differ in one cannot be compared: the window scored (window_s), the SRf definition and the
// rest that separates shocks. Any other setting (the PSD estimate, the reference's resolution,
// the thresholds, the beam) is what a diff compares.
bool ScoresComparableAcross(const std::string& setting);

struct SettingDifference {
  std::string setting;
  nlohmann::json a, b;  // null when the study does not have the setting.
};

// The boundary of both studies at one R_k: nothing where a study has no point at it. Two
// boundaries found on different grids differ only where the points that decide them tell them
// apart (validation/boundary_comparison.h); elsewhere they are not comparable.
struct CriteriaRow {
  double r_k = 0.0;
  std::optional<RkBoundary> a, b;
  // Where the boundaries are not comparable: the values studied in one study only that decide
  // them, "R_ftrunc 215.4 in A only, 316.2 in B only"; empty when they compare.
  std::string grids_differ;

  // Alike where a study has no point at the R_k.
  BoundaryComparison Truncation() const;
  // The largest passing dt where both have one; the truncation's comparison where one alone
  // has a passing truncation.
  BoundaryComparison Dt() const;
  bool TruncationDiffers() const { return Truncation() == BoundaryComparison::kDiffers; }
  bool DtDiffers() const { return Dt() == BoundaryComparison::kDiffers; }
  bool Comparable() const { return grids_differ.empty(); }
};

struct PointPair {
  DiffPoint a, b;
};

struct StudyDiff {
  std::vector<SettingDifference> settings;
  std::vector<CriteriaRow> criteria;  // Ascending R_k.
  std::vector<PointPair> matched;     // In A's order.
  std::vector<PointPair> changed;     // The matched pairs whose outcome category differs.
  std::vector<DiffPoint> only_a, only_b;
};

// Matches the points of A and B by scheme, dt rule and their numbers (R_k, R_ftrunc, the dt
// asked, window, damping), each number equal within `relative_tolerance`; judges each point
// with its own study's thresholds (analysis/outcome_category.h). Throws
// InputError naming the setting and both values when the studies differ in a setting that
// makes their scores incomparable (ScoresComparableAcross).
StudyDiff DiffStudies(const DiffedStudy& a, const DiffedStudy& b, double relative_tolerance);

// The outcome of a point as maps and reports name it: "passes", "fails thresholds",
// "diverged", ...
std::string OutcomeOf(const DiffPoint& p, const CriteriaOptions& options);

}  // namespace shockmap
