#pragma once
// One point of a study: the numerical solver against the reference on the canonical problem,
// scored with every registered score (validation/scores.h: Err, paper eq. 8, SRf, eq. 9, ...).

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "compare/reference_decision.h"
#include "compare/reference_run.h"
#include "core/cantilever_impact.h"
#include "core/input_error.h"
#include "core/run_status.h"
#include "core/scheme.h"
#include "core/stability_bounds.h"
#include "core/transient_run.h"
#include "validation/impulse_ratio.h"
#include "validation/psd.h"
#include "validation/scores.h"

namespace shockmap {

struct ComparisonOptions {
  double r_ftrunc = 300.0;  // f_trunc / f1.
  Scheme scheme = Scheme::kExplicitModal;
  TimeStepRequest dt;
  // Covers the first two shocks at R_k = 3000 (first contact at T1/4 = 13 ms, the second
  // shock near 44 ms), where references at 1000 f1 and 3000 f1 still agree (docs/physics.md §2).
  double window_s = 0.06;
  int n_elements = 0;  // 0: DefaultElementCount(r_ftrunc).
  ReferenceOptions reference;
  PsdOptions psd;
  // Contacts closer than this fraction of the first period 1 / f1 form one shock: the rebounds
  // of a shock at R_k = 3000 are < 2 ms (0.04 T1) apart, successive shocks ~ 30 ms (0.6 T1).
  double rest_duration_t1 = 0.1;
  // Which impulses SRf compares (paper eq. 9 admits several readings).
  SrfDefinition srf_definition = SrfDefinition::kFirstShock;
  // A score is decided when the reference's estimate on the part it reads is at most this
  // (compare/reference_decision.h); RunComparison raises the reference's truncation until its
  // whole estimate (ReferenceConvergence::difference) is, while a raise can decide a part.
  double reference_tolerance = 0.02;

  bool IsValid(std::string* error) const;
  ShockSegmentationOptions Shocks(double f1_hz) const;
};

// The histories a point's numerical run records: kScored those Err and SRf read (the tip
// displacement and the contact force), as a study scores and times its points; kAll adds the
// tip velocity and the energies, as the point's CSV (formats/history_csv.h) writes them.
enum class RecordedHistories { kScored, kAll };

struct ComparisonResult {
  // The numerical run's status, or kReferenceUnconverged when it ran but the reference decides
  // no score.
  RunStatus status = RunStatus::kOk;
  // Why it failed or was not scored; for a run scored with scores left undecided, why the
  // reference does not decide them.
  std::string message;
  // Every registered score (validation/scores.h) the reference decides, set only when status is
  // kOk or kUnstable: Err whenever decided, SRf when either side has a shock.
  ScoreValues scores;
  // The registered scores the reference does not decide (no value in `scores`), by name in
  // registry order; empty when it decides every one or the run was not scored.
  std::vector<std::string> undecided;
  SrfDefinition srf_definition = SrfDefinition::kFirstShock;  // The one srf was computed with.
  int n_modes = 0;
  int n_elements = 0;
  int n_dofs = 0;
  StabilityBounds bounds;
  // dt asked / used, steps, wall and CPU time (lower medians of repeated runs when
  // ScoreAgainstReference was given a RepeatedTiming).
  RunSummary numerical;
  std::vector<Shock> shocks_numerical;
  std::shared_ptr<const ReferenceRun> reference;  // Shared by every point of the same problem.
  // Tip displacement and contact force; tip velocity and energies too when recorded kAll.
  TransientResult histories;
};

// Why the scores of `undecided` (names, in registry order) are not decided by reference c at
// `tolerance`: "Err undecided: the reference's estimate on the window's tip is ..." for each
// part of the reference they read (UndecidedPartMessage), joined by "; ".
std::string UndecidedMessage(const ReferenceProblem& reference, const ReferenceConvergence& c,
                             const std::vector<std::string>& undecided, double tolerance);

// Why a point is not scored against reference c at `tolerance`: "the reference decides no
// score: " and UndecidedMessage of every score (each part's estimate, the tolerance's key and
// the truncation its truncations' order predicts, beyond the reference budget or not).
std::string UnconvergedMessage(const ReferenceProblem& reference, const ReferenceConvergence& c,
                               double tolerance);

// Preconditions: problem.IsValid(), options.IsValid(). Throws InputError when the
// reference cannot represent the problem.
ComparisonResult RunComparison(const CantileverImpact& problem, const ComparisonOptions& options);

// Transient options of a point's numerical run: its window, its step resolved on the model's
// bounds, the tip row observed and the histories recorded.
TransientOptions NumericalRun(const ComparisonOptions& options, const ImpactModel& model,
                              RecordedHistories recorded);

// The wall and CPU time of a point's numerical run as the lower median of `repeats` runs of the
// same model, so that the cost of runs of a few microseconds is not one sample of timer noise.
struct RunTiming {
  double wall_s = 0.0;
  double cpu_s = 0.0;
  int repeats = 1;
};

// How a short run is timed again: a run of less CPU time than min_total_s is run again on the
// same model until at least min_repeats runs (the first included) total min_total_s of wall
// time, or max_repeats runs were made.
struct RepeatedTiming {
  double min_total_s = 0.0;
  int min_repeats = 1;
  int max_repeats = 1;
};

// Scores a numerical run against a reference computed for the same problem and window. With
// `timing`, a run that reached its end and took less CPU time than timing->min_total_s is timed
// again on its own model (TimeRepeatedly) and `numerical` holds the lower medians of its wall
// and CPU times.
ComparisonResult ScoreAgainstReference(const CantileverImpact& problem,
                                       const ComparisonOptions& options,
                                       std::shared_ptr<const ReferenceRun> reference,
                                       RecordedHistories recorded = RecordedHistories::kAll,
                                       std::optional<RepeatedTiming> timing = std::nullopt);

// Runs `run` on `model` again until timing's totals are reached (the first run, given as
// `first`, included); the lower median of all, so that a run the scheduler preempted once does
// not set the cost.
RunTiming TimeRepeatedly(const ImpactModel& model, Scheme scheme, const TransientOptions& run,
                         const RunSummary& first, const RepeatedTiming& timing);

}  // namespace shockmap
