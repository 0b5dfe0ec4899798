#include "compare/comparison.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "core/validity.h"

namespace shockmap {

bool ComparisonOptions::IsValid(std::string* error) const {
  return RequireAtLeast("r_ftrunc", r_ftrunc, 1.0, error) && dt.IsValid(error) &&
         RequirePositive("window_s", window_s, error) &&
         RequireAtLeast("n_elements", n_elements, 0, error) && psd.IsValid(error) &&
         RequirePositive("rest_duration_t1", rest_duration_t1, error) &&
         RequirePositive("reference_tolerance", reference_tolerance, error) &&
         RequireAtLeast("reference.r_fref", reference.r_fref, 1.0, error) &&
         RequireAtLeast("reference.crossing_samples_per_period",
                        reference.crossing_samples_per_period, 4, error);
}

ShockSegmentationOptions ComparisonOptions::Shocks(double f1_hz) const {
  ShockSegmentationOptions s;
  s.rest_duration_s = rest_duration_t1 / f1_hz;
  return s;
}

ComparisonResult RunComparison(const CantileverImpact& problem, const ComparisonOptions& options) {
  ReferenceOptions reference = options.reference;
  if (reference.target_error == 0.0) reference.target_error = options.reference_tolerance;
  return ScoreAgainstReference(
      problem, options,
      std::make_shared<const ReferenceRun>(ComputeReferenceRun(problem, reference, options.window_s,
                                                               options.Shocks(problem.F1Hz()))));
}

TransientOptions NumericalRun(const ComparisonOptions& options, const ImpactModel& model,
                              RecordedHistories recorded) {
  TransientOptions run;
  run.end_time_s = options.window_s;
  run.dt_s = options.dt.Resolve(model.bounds);
  run.observed_rows = {model.tip_row};
  run.record_velocity = recorded == RecordedHistories::kAll;
  run.record_energy = recorded == RecordedHistories::kAll;
  return run;
}

namespace {

// The lower median: of two runs, the faster.
double LowerMedian(std::vector<double> v) {
  const auto middle = v.begin() + (v.size() - 1) / 2;
  std::ranges::nth_element(v, middle);
  return *middle;
}

}  // namespace

std::string UndecidedMessage(const ReferenceProblem& reference, const ReferenceConvergence& c,
                             const std::vector<std::string>& undecided, double tolerance) {
  std::vector<std::string> each;
  for (ReferencePart part : {ReferencePart::kWindowTip, ReferencePart::kFirstShock}) {
    std::vector<std::string_view> labels;
    for (const std::string& name : undecided) {
      const ScoreDefinition* score = FindScore(name);
      if (score->reads == part) labels.push_back(score->label);
    }
    if (labels.empty()) continue;
    each.push_back(fmt::format("{} undecided: {}", fmt::join(labels, ", "),
                               UndecidedPartMessage(reference, c, part, tolerance)));
  }
  return fmt::format("{}", fmt::join(each, "; "));
}

std::string UnconvergedMessage(const ReferenceProblem& reference, const ReferenceConvergence& c,
                               double tolerance) {
  std::vector<std::string> every;
  for (const ScoreDefinition& score : Scores()) every.emplace_back(score.name);
  return "the reference decides no score: " + UndecidedMessage(reference, c, every, tolerance);
}

namespace {

// Removes from `result` the scores its reference does not decide at `tolerance`, naming them
// in result.undecided and why after the run's own message.
void LeaveUndecided(ComparisonResult& result, const ReferenceProblem& reference, double tolerance) {
  const ReferenceConvergence& c = result.reference->convergence;
  for (const ScoreDefinition& score : Scores()) {
    if (DecidesPart(c, score.reads, tolerance)) continue;
    result.scores.Set(score.name, std::nullopt);
    result.undecided.emplace_back(score.name);
  }
  if (result.undecided.empty()) return;
  if (!result.message.empty()) result.message += "; ";
  result.message += UndecidedMessage(reference, c, result.undecided, tolerance);
}

}  // namespace

RunTiming TimeRepeatedly(const ImpactModel& model, Scheme scheme, const TransientOptions& run,
                         const RunSummary& first, const RepeatedTiming& timing) {
  std::vector<double> wall{first.wall_s}, cpu{first.cpu_s};
  double total = first.wall_s;
  auto runs = [&] { return static_cast<int>(wall.size()); };
  while ((total < timing.min_total_s || runs() < timing.min_repeats) &&
         runs() < timing.max_repeats) {
    const RunSummary s =
        RunTransient(*model.system, NewmarkParametersOf(scheme), model.x0, model.v0, run).summary;
    wall.push_back(s.wall_s);
    cpu.push_back(s.cpu_s);
    total += s.wall_s;
  }
  return {LowerMedian(wall), LowerMedian(cpu), static_cast<int>(wall.size())};
}

ComparisonResult ScoreAgainstReference(const CantileverImpact& problem,
                                       const ComparisonOptions& options,
                                       std::shared_ptr<const ReferenceRun> reference,
                                       RecordedHistories recorded,
                                       std::optional<RepeatedTiming> timing) {
  ComparisonResult result;
  result.srf_definition = options.srf_definition;
  const ImpactModel model =
      BuildImpactModel(problem, options.scheme, options.r_ftrunc, options.n_elements);
  result.n_modes = model.n_modes;
  result.n_elements = model.n_elements;
  result.n_dofs = model.n_dofs;
  result.bounds = model.bounds;

  const TransientOptions run = NumericalRun(options, model, recorded);
  std::string error;
  result.reference = std::move(reference);
  if (!run.IsValid(&error)) {
    result.status = RunStatus::kFailed;
    result.message = error;
    return result;
  }
  // A window inside one step holds no history to compare: Err would be 0 and the point pass.
  if (options.window_s < run.dt_s) {
    result.status = RunStatus::kFailed;
    result.message =
        fmt::format("the window {:g} s is shorter than one time step ({:g} s): nothing to score",
                    options.window_s, run.dt_s);
    return result;
  }
  result.histories =
      RunTransient(*model.system, NewmarkParametersOf(options.scheme), model.x0, model.v0, run);
  result.numerical = result.histories.summary;
  if (timing && result.numerical.steps_taken == result.numerical.steps_requested &&
      result.numerical.cpu_s < timing->min_total_s) {
    const RunTiming t = TimeRepeatedly(model, options.scheme, run, result.numerical, *timing);
    result.numerical.wall_s = t.wall_s;
    result.numerical.cpu_s = t.cpu_s;
  }
  result.status = result.numerical.status;
  result.message = result.numerical.message;
  // An unstable run reached its end: it is scored, and fails the criteria by its status.
  if (result.numerical.status != RunStatus::kOk &&
      result.numerical.status != RunStatus::kUnstable) {
    return result;
  }

  const ShockSegmentationOptions shocks = options.Shocks(problem.F1Hz());
  result.shocks_numerical =
      SegmentShocks(result.histories.contact_force_n[0], shocks, options.window_s);
  const ReferenceConvergence& convergence = result.reference->convergence;
  if (!DecidesPart(convergence, ReferencePart::kWindowTip, options.reference_tolerance) &&
      !DecidesPart(convergence, ReferencePart::kFirstShock, options.reference_tolerance)) {
    result.status = RunStatus::kReferenceUnconverged;
    result.message = UnconvergedMessage({problem, options.reference, options.window_s}, convergence,
                                        options.reference_tolerance);
    return result;
  }
  const ReferenceRun& ref = *result.reference;
  const std::optional<ReferenceSpectrum>& spectrum = ref.tip_spectrum;
  const bool spectrum_fits =
      spectrum && spectrum->options == options.psd && spectrum->window_s == options.window_s;
  result.scores = ComputeScores({.displacement = result.histories.displacement_m[0],
                                 .reference_displacement = ref.tip_m,
                                 .reference_spectrum = spectrum_fits ? &spectrum->psd : nullptr,
                                 .psd = options.psd,
                                 .end_s = options.window_s,
                                 .force = result.histories.contact_force_n[0],
                                 .shocks = result.shocks_numerical,
                                 .reference_force = ref.force_n,
                                 .reference_shocks = ref.shocks,
                                 .srf_definition = options.srf_definition,
                                 .segmentation = shocks});
  LeaveUndecided(result, {problem, options.reference, options.window_s},
                 options.reference_tolerance);
  return result;
}

}  // namespace shockmap
