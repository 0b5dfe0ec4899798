#include "engine/canonical_study.h"

#include <nlohmann/json.hpp>

#include "engine/reference_store.h"
#include "formats/comparison_json.h"

namespace shockmap {
namespace {

// A run of less CPU time than 0.5 ms is timed again until 2 runs total 0.5 ms of wall time
// (at most 101 runs), and the lower median is stored: single wall timings of runs of ~10 us
// differ a thousandfold between two runs of a study on a loaded machine, one preempted for
// 10 ms (docs/physics.md §4.4). The budget is about two of a typical point's runs, so that
// timing does not dominate a study's cost.
constexpr RepeatedTiming kShortRunTiming{5e-4, 2, 101};

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
  s.srf_definition = ToString(r.srf_definition);
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

void PutSignal(const UniformSignal& signal, ByteWriter& out) {
  out.Put(signal.t0_s);
  out.Put(signal.dt_s);
  out.Put(signal.values);
}

UniformSignal GetSignal(ByteReader& in) {
  UniformSignal signal;
  signal.t0_s = in.Get<double>();
  signal.dt_s = in.Get<double>();
  signal.values = in.GetDoubles();
  return signal;
}

void PutShock(const Shock& s, ByteWriter& out) {
  for (double v : {s.start_s, s.end_s, s.peak_force_n, s.peak_time_s, s.impulse_n_s}) out.Put(v);
  out.Put(s.n_contacts);
  out.Put(static_cast<std::uint8_t>(s.truncated));
}

Shock GetShock(ByteReader& in) {
  Shock s;
  for (double* v : {&s.start_s, &s.end_s, &s.peak_force_n, &s.peak_time_s, &s.impulse_n_s}) {
    *v = in.Get<double>();
  }
  s.n_contacts = in.Get<int>();
  s.truncated = in.Get<std::uint8_t>() != 0;
  return s;
}

}  // namespace

CanonicalStudy::CanonicalStudy(StudySpec spec)
    : spec_(std::move(spec)), header_{spec_.file, spec_.name, spec_.spec_json} {}

bool CanonicalStudy::KeepsSettingsOf(const nlohmann::json& stored,
                                     const std::string& database_path) const {
  return SettingsKey(ParseStudySpec(stored, database_path)) == SettingsKey(spec_);
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
    const ComparisonResult r =
        ScoreAgainstReference(ProblemOf(spec_, point), OptionsOf(spec_, point), reference.run,
                              RecordedHistories::kScored, kShortRunTiming);
    out.status = r.status;
    out.message = r.message;
    out.score = ToScoreRow(r, reference_id);
  } catch (const std::exception& e) {
    out.message = e.what();
  }
  return out;
}

void CanonicalStudy::EncodeReference(const Reference& reference, ByteWriter& out) const {
  out.Put(reference.key);
  out.Put(reference.r_k);
  out.Put(reference.window_s);
  const ReferenceRun& run = *reference.run;
  PutSignal(run.tip_m, out);
  PutSignal(run.force_n, out);
  out.Put(static_cast<std::uint64_t>(run.shocks.size()));
  for (const Shock& shock : run.shocks) PutShock(shock, out);
  const ReferenceSummary& s = run.summary;
  out.Put(s.n_modes_free);
  out.Put(s.n_modes_contact);
  out.Put(s.n_transitions);
  out.Put(s.shortest_period_s);
  out.Put(s.wall_s);
  const ReferenceConvergence& c = run.convergence;
  for (double v : {c.r_fref, c.r_fref_check, c.difference, c.wall_check_s}) out.Put(v);
  out.Put(run.wall_s);
}

CanonicalStudy::Reference CanonicalStudy::DecodeReference(ByteReader& in) const {
  Reference reference;
  reference.key = in.GetString();
  reference.r_k = in.Get<double>();
  reference.window_s = in.Get<double>();
  ReferenceRun run;
  run.tip_m = GetSignal(in);
  run.force_n = GetSignal(in);
  const auto n_shocks = in.Get<std::uint64_t>();
  for (std::uint64_t i = 0; i < n_shocks && !in.AtEnd(); ++i) run.shocks.push_back(GetShock(in));
  ReferenceSummary& s = run.summary;
  s.n_modes_free = in.Get<int>();
  s.n_modes_contact = in.Get<int>();
  s.n_transitions = in.Get<int>();
  s.shortest_period_s = in.Get<double>();
  s.wall_s = in.Get<double>();
  ReferenceConvergence& c = run.convergence;
  for (double* v : {&c.r_fref, &c.r_fref_check, &c.difference, &c.wall_check_s}) {
    *v = in.Get<double>();
  }
  run.wall_s = in.Get<double>();
  reference.run = std::make_shared<const ReferenceRun>(
      WithTipSpectrum(std::move(run), spec_.scoring.psd, reference.window_s));
  return reference;
}

void CanonicalStudy::EncodeScore(const ScoreRow& s, ByteWriter& out) const {
  out.Put(s.reference_id);
  out.Put(s.err);
  out.Put(s.srf);
  for (int v : {s.n_modes, s.n_elements, s.n_dofs, s.n_shocks}) out.Put(v);
  for (double v : {s.dt_requested_s, s.dt_used_s, s.dt_paper_s, s.dt_sharp_s, s.wall_s, s.cpu_s,
                   s.max_energy_ratio}) {
    out.Put(v);
  }
  out.Put(s.steps);
  out.Put(static_cast<std::uint8_t>(s.first_shock.has_value()));
  if (const auto& f = s.first_shock) {
    for (double v : {f->start_s, f->impulse_n_s, f->peak_n, f->duration_s}) out.Put(v);
    out.Put(f->rebounds);
  }
  out.Put(s.shocks_json);
  out.Put(s.srf_definition);
}

ScoreRow CanonicalStudy::DecodeScore(ByteReader& in) const {
  ScoreRow s;
  s.reference_id = in.Get<std::int64_t>();
  s.err = in.GetOptional<double>();
  s.srf = in.GetOptional<double>();
  for (int* v : {&s.n_modes, &s.n_elements, &s.n_dofs, &s.n_shocks}) *v = in.Get<int>();
  for (double* v : {&s.dt_requested_s, &s.dt_used_s, &s.dt_paper_s, &s.dt_sharp_s, &s.wall_s,
                    &s.cpu_s, &s.max_energy_ratio}) {
    *v = in.Get<double>();
  }
  s.steps = in.Get<std::int64_t>();
  if (in.Get<std::uint8_t>() != 0) {
    ShockColumns& f = s.first_shock.emplace();
    for (double* v : {&f.start_s, &f.impulse_n_s, &f.peak_n, &f.duration_s}) *v = in.Get<double>();
    f.rebounds = in.Get<int>();
  }
  s.shocks_json = in.GetString();
  s.srf_definition = in.GetString();
  return s;
}

}  // namespace shockmap
