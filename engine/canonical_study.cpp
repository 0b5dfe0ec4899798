#include "engine/canonical_study.h"

#include <nlohmann/json.hpp>

#include "engine/reference_store.h"
#include "formats/comparison_json.h"
#include "formats/json_reader.h"

namespace shockmap {
namespace {

ScoreRow ToScoreRow(const ComparisonResult& r, std::int64_t reference_id) {
  ScoreRow s;
  s.reference_id = reference_id;
  s.err = r.err;
  s.srf = r.srf;
  s.n_modes = r.n_modes;
  s.n_elements = r.n_elements;
  s.n_dofs = r.n_dofs;
  s.dt_requested_s = r.numerical.dt_requested_s;
  s.dt_used_s = r.numerical.dt_used_s;
  s.dt_paper_s = r.bounds.dt_paper_s;
  s.dt_sharp_s = r.bounds.dt_sharp_s;
  s.steps = r.numerical.steps_taken;
  s.wall_s = r.numerical.wall_s;
  s.cpu_s = r.numerical.cpu_s;
  s.max_energy_ratio = r.numerical.max_energy_ratio;
  s.n_shocks = static_cast<int>(r.shocks_numerical.size());
  nlohmann::json shocks = nlohmann::json::array();
  for (const auto& shock : r.shocks_numerical) shocks.push_back(ShockToJson(shock));
  s.shocks_json = shocks.dump();
  if (!r.shocks_numerical.empty()) {
    const Shock& f = r.shocks_numerical.front();
    s.first_shock =
        ShockColumns{f.start_s, f.impulse_n_s, f.peak_force_n, f.Duration(), f.Rebounds()};
  }
  return s;
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

void CanonicalStudy::CheckStoredSpec(const std::string& stored_json,
                                     const std::string& database_path) const {
  const nlohmann::json stored =
      ParseJsonText(stored_json, database_path + ": stored study " + spec_.name);
  if (StudyKindOf(stored, database_path) != StudyFileKind::kCanonical) {
    throw InputError(spec_.file + ": study \"" + spec_.name + "\" already exists in " +
                     database_path + " as a study of another kind; give this one a new name");
  }
  if (SettingsKey(ParseStudySpec(stored, database_path)) != SettingsKey(spec_)) {
    throw InputError(spec_.file + ": study \"" + spec_.name + "\" already exists in " +
                     database_path +
                     " with other problem or scoring settings; its stored scores depend on them. "
                     "Give the study a new name (grid axes may change freely).");
  }
}

NewPoint CanonicalStudy::Describe(const Point& point) const {
  return {PointKey(point), ReferenceKey(spec_, point), ParameterValues(ParametersOf(point))};
}

double CanonicalStudy::ReferenceCost(const Point& point) const {
  return spec_.scoring.reference.RFref(point.r_k);  // Cost grows with the truncation.
}

CanonicalStudy::Reference CanonicalStudy::ComputeReference(const Point& point) const {
  const ComparisonOptions o = OptionsOf(spec_, point);
  return {ReferenceKey(spec_, point), point.r_k, point.window_s,
          std::make_shared<const ReferenceRun>(ComputeReferenceRun(
              ProblemOf(spec_, point), o.reference, o.window_s, o.Shocks(spec_.problem.F1Hz())))};
}

std::optional<StoredReference<CanonicalStudy::Reference>> CanonicalStudy::FindReference(
    StudyDatabase& db, const std::string& key) const {
  const auto row = shockmap::FindReference(db, key);
  if (!row) return std::nullopt;
  return StoredReference<Reference>{
      row->reference_id,
      {key, row->r_k, row->window_s, std::make_shared<const ReferenceRun>(FromReferenceRow(*row))}};
}

std::int64_t CanonicalStudy::StoreReference(StudyDatabase& db, const Reference& reference,
                                            std::int64_t run_id) const {
  return shockmap::StoreReference(
      db, ToReferenceRow(*reference.run, reference.key, reference.r_k, reference.window_s), run_id);
}

CanonicalStudy::Outcome CanonicalStudy::Score(const Point& point, const Reference& reference,
                                              std::int64_t reference_id) const {
  Outcome out;
  try {
    const ComparisonResult r =
        ScoreAgainstReference(ProblemOf(spec_, point), OptionsOf(spec_, point), reference.run);
    out.status = r.status;
    out.message = r.message;
    out.score = ToScoreRow(r, reference_id);
  } catch (const std::exception& e) {
    out.message = e.what();
  }
  return out;
}

void CanonicalStudy::StoreOutcome(StudyDatabase& db, std::int64_t point_id, std::int64_t run_id,
                                  const Outcome& outcome) const {
  StoreCanonicalOutcome(db, point_id, run_id, ToString(outcome.status), outcome.message,
                        outcome.score);
}

}  // namespace shockmap
