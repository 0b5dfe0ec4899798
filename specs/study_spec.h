#pragma once
// A study file (JSON, in studies/): the problem, the scoring settings and the grid of
// (R_k, R_ftrunc, dt) points to compare, parsed strictly into plain structs.

#include <cstddef>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "compare/comparison.h"
#include "core/cantilever_impact.h"
#include "formats/json_reader.h"
#include "validation/scores.h"

namespace shockmap {

// Refused above this many points: a grid that large is a typing mistake, not a study.
inline constexpr std::size_t kMaxStudyPoints = 1'000'000;

// Truncation of the reference for each R_k: ReferenceTruncationRule (compare/reference_run.h)
// with these values, raised until the reference's estimated error meets the tolerance.
struct ReferencePolicy {
  double r_fref_min = ReferenceTruncationRule{}.r_fref_min;
  double r_fref_per_sqrt_rk = ReferenceTruncationRule{}.r_fref_per_sqrt_rk;
  int crossing_samples_per_period = 16;
  // Score nothing against a reference whose estimated error exceeds this; the truncation is
  // raised threefold until it does not, within the reference budget.
  double tolerance = 0.02;
  // What the reference is checked against ("check"): finer truncations (the default, a bound) or
  // R_fref / 3 alone, as a script does (ReferenceCheck, reference/reference_convergence.h).
  ReferenceCheck check = ReferenceCheck::kFiner;

  double RFref(double r_k) const;
};

// The truncation axis at mode resolution, {"modes": [first, last]}: one R_ftrunc per count n of
// retained clamped-free modes, placed just above mode n's analytic frequency,
// R_ftrunc = (b_n / b_1)^2 (1 + kModeEntryMargin), b_n the roots of 1 + cosh b cos b = 0. The
// finite-element frequencies lie above the analytic ones by less than 1e-4 with the default
// mesh (docs/physics.md §3), so the model keeps exactly n modes, and the smallest passing
// truncation found on this axis is the frequency at which the last needed mode enters.
inline constexpr double kModeEntryMargin = 1e-3;
inline constexpr int kMaxModeAxisCount = 150;  // Mode 150 is at ~6.3e4 f1, below the axis' 1e5.
std::vector<double> ModeEntryTruncations(int first_mode, int last_mode);

// The paper's Fig. 4 window: 0.03 s, 0.577 first-mode periods of its beam (f1 = 19.23 Hz).
inline constexpr double kFig4WindowS = 0.03;

struct ScoringSpec {
  double window_s = ComparisonOptions{}.window_s;
  // The window as given in first-mode periods of the problem's beam ("window_periods"), when it
  // was; window_s is then window_periods / f1.
  std::optional<double> window_periods;
  PsdOptions psd;
  double rest_duration_t1 = ComparisonOptions{}.rest_duration_t1;
  SrfDefinition srf_definition = SrfDefinition::kFirstShock;
  ReferencePolicy reference;
  // Points at R_k >= spread_from_rk that are scored are run again under the perturbations of
  // compare/score_spread.h (the release at rounding level, two finer meshes) and store their
  // scores' spread ("spread": {"from_rk": ...}); below it they move Err by less than 4e-6
  // (docs/fidelity.md).
  double spread_from_rk = 1e4;
  // The cost figures of a point's numerical run ("timing": {"repeat_until_s": ...}): a run of
  // less CPU time than this is run again on the same model until 2 runs total this much wall
  // time (at most 101), and the lower median is stored (docs/physics.md §4.4); 0 times each run
  // once. Scores do not depend on it.
  double timing_repeat_until_s = 5e-4;
  // Validity thresholds by score name (validation/scores.h), read from "thresholds" as each
  // score's key (err_max, srf_min, ...).
  std::map<std::string, double, std::less<>> thresholds = DefaultThresholds();
};

// One point of the grid: everything that varies between points.
struct StudyPoint {
  double r_k = 0.0;
  double r_ftrunc = 0.0;
  Scheme scheme = Scheme::kExplicitModal;
  TimeStepRequest dt;
  double window_s = 0.0;
  int n_elements = 0;
  double mass_damping_per_s = 0.0;
};

struct StudySpec {
  std::string file;
  std::string name;
  std::string description;
  CantileverImpact problem;  // r_k and mass_damping_per_s come from each point.
  ScoringSpec scoring;
  std::vector<StudyPoint> points;  // Union of the grids and the listed points, without repeats.
  std::string spec_json;           // The file's JSON, compact, as stored with the study.
};

// Reads each score's threshold that `r` holds under the score's key (err_max, srf_min, ...)
// into `thresholds`, by score name. Throws InputError for a value outside the score's range.
void ReadThresholds(JsonObjectReader& r, std::map<std::string, double, std::less<>>& thresholds);

// The name and description every study file begins with (a name of 1 to 200 characters
// without control characters), and its "kind", which when given must be `kind`.
std::pair<std::string, std::string> ReadStudyTitle(JsonObjectReader& r, std::string_view kind);

// Parses and validates a study file. Throws InputError naming the file, the key path, the value
// and what is allowed: unknown keys, wrong types, empty axes, out-of-range values.
StudySpec LoadStudySpec(const std::string& path);
StudySpec ParseStudySpec(const nlohmann::json& json, const std::string& file);

// A window given in seconds (a grid's or the scoring's "window_s") on a beam whose f1 is more
// than 1.5 times away from the paper's covers another number of first-mode periods than the
// same seconds do on the paper's beam, so Err and SRf change meaning: the warning says how many
// it covers and how to give it in periods. Empty otherwise.
std::optional<std::string> WindowWarning(const StudySpec& spec);

// How a point's numerical run is timed under `scoring`: none for repeat_until_s = 0 (the run's
// own timing), else RepeatedTiming{repeat_until_s, 2, 101}.
std::optional<RepeatedTiming> ShortRunTiming(const ScoringSpec& scoring);

CantileverImpact ProblemOf(const StudySpec& spec, const StudyPoint& point);
ComparisonOptions OptionsOf(const StudySpec& spec, const StudyPoint& point);

// Identifies a point within its study.
std::string PointKey(const StudyPoint& point);
// Identifies the reference a point is scored against; equal keys share one reference, across
// studies of the same database.
std::string ReferenceKey(const StudySpec& spec, const StudyPoint& point);
// The lifelong settings, by their keys in the study file: the problem and every scoring
// setting ("scoring.window_s", "scoring.psd.*", "scoring.shocks.*", "scoring.reference.*") but
// the thresholds. A study keeps them for life, since its stored scores depend on them (a
// changed window would add points whose scores criteria then pool with the old ones); grid
// axes and thresholds may change.
std::string SettingsKey(const StudySpec& spec);

}  // namespace shockmap
