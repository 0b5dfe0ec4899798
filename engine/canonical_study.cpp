#include "engine/canonical_study.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "compare/output_columns.h"
#include "compare/score_columns.h"
#include "compare/score_spread.h"
#include "engine/record_codec.h"
#include "engine/reference_store.h"
#include "formats/comparison_json.h"

namespace shockmap {
namespace {

// The point's score row: the columns `compare --json` also writes (the model's size, the step,
// its bounds, the step count, the energy ratio) from kComparisonColumns, the scores from the
// registry, and the rest from the run.
ScoreRow ToScoreRow(const ComparisonOutput& c, std::int64_t reference_id) {
  const ComparisonResult& r = c.result;
  ScoreRow s;
  s.reference_id = reference_id;
  SetScoreColumns(s, kScoreColumns, r.scores);
  SetColumnsFromOutputs(s, kScoreColumns, c, kComparisonColumns);
  s.dt_used_s = r.numerical.dt_used_s;
  s.wall_s = r.numerical.wall_s;
  s.cpu_s = r.numerical.cpu_s;
  s.n_shocks = static_cast<int>(r.shocks_numerical.size());
  nlohmann::json shocks = nlohmann::json::array();
  for (const auto& shock : r.shocks_numerical) shocks.push_back(ShockToJson(shock));
  s.shocks_json = shocks.dump();
  s.srf_definition = ToString(r.srf_definition);
  if (!r.undecided.empty()) s.reference_undecided = fmt::format("{}", fmt::join(r.undecided, ","));
  if (!r.shocks_numerical.empty()) {
    const Shock& f = r.shocks_numerical.front();
    s.first_shock_start_s = f.start_s;
    s.first_shock_impulse_n_s = f.impulse_n_s;
    s.first_shock_peak_n = f.peak_force_n;
    s.first_shock_duration_s = f.Duration();
    s.first_shock_rebounds = f.Rebounds();
  }
  return s;
}

// The spread of a scored point's scores over its perturbed runs, into its row.
void SetSpread(ScoreRow& row, const ScoreSpread& spread) {
  row.spread_runs = spread.runs;
  SetScoreColumns(row, kScoreColumns, spread.low, kSpreadLowSuffix);
  SetScoreColumns(row, kScoreColumns, spread.high, kSpreadHighSuffix);
}

PointParameters ParametersOf(const StudyPoint& p) {
  PointParameters r;
  r.r_k = p.r_k;
  r.r_ftrunc = p.r_ftrunc;
  r.scheme = ToString(p.scheme);
  if (p.dt.dt_s) {
    r.dt_asked_s = p.dt.dt_s;
  } else {
    r.dt_rule = ToString(p.dt.rule);
    r.dt_factor = p.dt.factor;
  }
  r.window_s = p.window_s;
  r.n_elements_asked = p.n_elements;
  r.mass_damping_per_s = p.mass_damping_per_s;
  return r;
}

}  // namespace

CanonicalStudy::CanonicalStudy(StudySpec spec)
    : spec_(std::move(spec)), header_{spec_.file, spec_.name, spec_.spec_json} {}

std::optional<SettingChange> CanonicalStudy::ChangedSetting(
    const nlohmann::json& stored, const std::string& database_path) const {
  return FirstChangedSetting(
      nlohmann::json::parse(SettingsKey(ParseStudySpec(stored, database_path))),
      nlohmann::json::parse(SettingsKey(spec_)));
}

NewPoint CanonicalStudy::Describe(const Point& point) const {
  return {PointKey(point), ReferenceKey(spec_, point),
          CellsOf(ParametersOf(point), kPointParameterColumns)};
}

double CanonicalStudy::ReferenceCost(const Point& point) const {
  return spec_.scoring.reference.RFref(point.r_k);  // Cost grows with the truncation.
}

CanonicalStudy::Reference CanonicalStudy::ComputeReference(const Point& point) const {
  const ComparisonOptions o = OptionsOf(spec_, point);
  return {ReferenceKey(spec_, point), point.r_k, point.window_s,
          std::make_shared<const ReferenceRun>(
              WithTipSpectrum(ComputeReferenceRun(ProblemOf(spec_, point), o.reference, o.window_s,
                                                  o.Shocks(spec_.problem.F1Hz())),
                              o.psd, o.window_s))};
}

std::optional<StoredReference<CanonicalStudy::Reference>> CanonicalStudy::FindReference(
    StudyDatabase& db, const std::string& key) const {
  const auto row = shockmap::FindReference(db, key);
  if (!row) return std::nullopt;
  return StoredReference<Reference>{
      row->reference_id,
      {key, row->r_k, row->window_s,
       std::make_shared<const ReferenceRun>(WithTipSpectrum(FromReferenceRow(*row, db.Raw().Path()),
                                                            spec_.scoring.psd, row->window_s))}};
}

std::int64_t CanonicalStudy::StoreReference(StudyDatabase& db, const Reference& reference,
                                            std::int64_t run_id) const {
  return shockmap::StoreReference(
      db, ToReferenceRow(*reference.run, reference.key, reference.r_k, reference.window_s), run_id);
}

bool CanonicalStudy::ReferenceConverged(const Reference& reference) const {
  return reference.run->convergence.difference <= spec_.scoring.reference.tolerance;
}

CanonicalStudy::Outcome CanonicalStudy::Score(const Point& point, const Reference& reference,
                                              std::int64_t reference_id) const {
  Outcome out;
  try {
    const CantileverImpact problem = ProblemOf(spec_, point);
    const ComparisonOptions options = OptionsOf(spec_, point);
    const ComparisonResult r = ScoreAgainstReference(
        problem, options, reference.run, RecordedHistories::kScored, ShortRunTiming(spec_.scoring));
    out.status = r.status;
    out.message = r.message;
    out.score = ToScoreRow({problem, options, r}, reference_id);
    if (r.status == RunStatus::kOk && point.r_k >= spec_.scoring.spread_from_rk)
      SetSpread(*out.score, SpreadAgainstReference(problem, options, r));
  } catch (const std::exception& e) {
    out.message = e.what();
  }
  return out;
}

void CanonicalStudy::EncodeReference(const Reference& reference, ByteWriter& out) const {
  PutRecord(ToReferenceRow(*reference.run, reference.key, reference.r_k, reference.window_s),
            kReferenceColumns, out);
}

CanonicalStudy::Reference CanonicalStudy::DecodeReference(ByteReader& in) const {
  const auto row = GetRecord<ReferenceRow>(in, kReferenceColumns);
  return {row.reference_key, row.r_k, row.window_s,
          std::make_shared<const ReferenceRun>(WithTipSpectrum(
              FromReferenceRow(row, "an MPI message"), spec_.scoring.psd, row.window_s))};
}

void CanonicalStudy::EncodeScore(const ScoreRow& score, ByteWriter& out) const {
  PutRecord(score, kScoreColumns, out);
}

ScoreRow CanonicalStudy::DecodeScore(ByteReader& in) const {
  return GetRecord<ScoreRow>(in, kScoreColumns);
}

}  // namespace shockmap
