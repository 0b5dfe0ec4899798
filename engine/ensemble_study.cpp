#include "engine/ensemble_study.h"

#include <fmt/format.h>

#include <algorithm>

#include "compare/scene_run.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// Where each zone sits and what it joins, for the sizing view's tables and maps.
std::string ZonesJson(const Scene& scene) {
  Json zones = Json::array();
  for (const SceneZone& z : scene.zones) {
    zones.push_back({{"name", z.name},
                     {"beam_a", scene.beams[z.beam_a].name},
                     {"beam_b", z.beam_b >= 0 ? scene.beams[z.beam_b].name : "stop"},
                     {"height_m", z.height_m},
                     {"y_m", z.y_m},
                     {"z_m", z.z_m}});
  }
  return zones.dump();
}

// The member's zone rows of a run that ended ok: its largest force per zone and, when streamed,
// its impact statistics (the wear work rate where the scene carries the sliding).
std::vector<EnsembleZoneRow> ZoneRows(const SceneRun& run) {
  std::vector<EnsembleZoneRow> zones(run.max_contact_force_n.size());
  for (std::size_t i = 0; i < zones.size(); ++i) {
    EnsembleZoneRow& z = zones[i];
    z.max_force_n = run.max_contact_force_n[i];
    if (i >= run.impact_statistics.size()) continue;
    const ImpactStatistics& s = run.impact_statistics[i];
    z.impacts = s.impacts;
    z.impacts_per_s = s.impacts_per_s;
    z.rebounds_per_impact = s.rebounds_per_impact;
    z.mean_impact_duration_s = s.mean_impact_duration_s;
    z.longest_impact_duration_s = s.longest_impact_duration_s;
    z.contact_time_fraction = s.contact_time_fraction;
    z.mean_force_n = s.mean_force_n;
    z.mean_force_in_contact_n = s.mean_force_in_contact_n;
    z.rms_force_n = s.rms_force_n;
    z.impulse_n_s = s.impulse_n_s;
    if (s.wear_available) z.wear_work_rate_w = s.wear_work_rate_w;
  }
  return zones;
}

void EncodeZone(const EnsembleZoneRow& z, ByteWriter& out) {
  out.Put(z.max_force_n);
  out.Put(z.impacts);
  for (auto field : kZoneStatistics) out.Put(z.*field);
}

EnsembleZoneRow DecodeZone(ByteReader& in) {
  EnsembleZoneRow z;
  z.max_force_n = in.Get<double>();
  z.impacts = in.GetOptional<std::int64_t>();
  for (auto field : kZoneStatistics) z.*field = in.GetOptional<double>();
  return z;
}

}  // namespace

EnsembleStudy::EnsembleStudy(EnsembleStudySpec spec)
    : spec_(std::move(spec)), header_{spec_.file, spec_.name, spec_.spec_json} {}

bool EnsembleStudy::KeepsSettingsOf(const Json& stored, const std::string&) const {
  const Json was = stored.value("settings_key", Json());
  const Json now = Json::parse(EnsembleSettingsKey(spec_));
  if (!was.is_object()) return false;
  for (const char* key : {"scene", "seed", "draws", "window_s", "impact_counting"}) {
    if (was.value(key, Json()) != now.at(key)) return false;
  }
  const Json was_states = was.value("states", Json::object());
  for (const auto& [name, state] : now.at("states").items()) {
    if (was_states.contains(name) && was_states.at(name) != state) return false;
  }
  return true;
}

NewPoint EnsembleStudy::Describe(const Point& m) const {
  return {MemberKey(spec_, m),
          spec_.states[m.state].name,
          {spec_.states[m.state].name, spec_.settings[m.setting].dump(),
           static_cast<std::int64_t>(m.member)}};
}

EnsembleStudy::Reference EnsembleStudy::ComputeReference(const Point& point) const {
  Reference ref;
  ref.reference_key = NominalKey(spec_, point.state);
  ref.state = spec_.states[point.state].name;
  ref.status = ToString(RunStatus::kFailed);
  try {
    const Scene scene = NominalScene(spec_, point.state);
    ref.zones_json = ZonesJson(scene);
    const SceneRun run = RunScene(scene);
    const RunSummary& s = run.result.summary;
    ref.status = ToString(s.status);
    ref.message = s.message;
    if (s.status == RunStatus::kOk) ref.max_force_n = run.max_contact_force_n;
    ref.steps = s.steps_taken;
    ref.wall_s = s.wall_s;
  } catch (const std::exception& e) {
    ref.message = e.what();
  }
  return ref;
}

std::optional<StoredReference<EnsembleStudy::Reference>> EnsembleStudy::FindReference(
    StudyDatabase& db, const std::string& state) const {
  const auto& states = spec_.states;
  const auto found = std::ranges::find(states, state, &ClearanceState::name);
  if (found == states.end()) return std::nullopt;
  auto row = FindEnsembleReference(db, NominalKey(spec_, static_cast<int>(found - states.begin())));
  if (!row) return std::nullopt;
  const std::int64_t id = row->reference_id;
  return StoredReference<Reference>{id, std::move(*row)};
}

std::int64_t EnsembleStudy::StoreReference(StudyDatabase& db, const Reference& reference,
                                           std::int64_t run_id) const {
  return StoreEnsembleReference(db, reference, run_id);
}

// A member does not depend on its nominal run: a failed nominal run leaves the members alone
// (the sizing view shows the nominal's status).
EnsembleStudy::Outcome EnsembleStudy::Score(const Point& point, const Reference&,
                                            std::int64_t reference_id) const {
  Outcome out;
  try {
    const SceneRun run = RunScene(MemberScene(spec_, point));
    const RunSummary& s = run.result.summary;
    EnsembleMemberRow row;
    row.reference_id = reference_id;
    row.member_seed = fmt::format("0x{:016x}", MemberSeedOf(spec_, point));
    row.coordinates = run.coordinates;
    row.dt_used_s = s.dt_used_s;
    row.steps = s.steps_taken;
    row.wall_s = s.wall_s;
    row.cpu_s = s.cpu_s;
    row.max_energy_ratio = s.max_energy_ratio;
    if (s.status == RunStatus::kOk) row.zones = ZoneRows(run);
    out.status = s.status;
    out.message = s.message;
    out.score = std::move(row);
  } catch (const std::exception& e) {
    out.message = e.what();
  }
  return out;
}

void EnsembleStudy::EncodeReference(const Reference& r, ByteWriter& out) const {
  out.Put(r.reference_id);
  for (const std::string* text :
       {&r.reference_key, &r.state, &r.status, &r.message, &r.zones_json}) {
    out.Put(*text);
  }
  out.Put(r.max_force_n);
  out.Put(r.steps);
  out.Put(r.wall_s);
}

EnsembleStudy::Reference EnsembleStudy::DecodeReference(ByteReader& in) const {
  Reference r;
  r.reference_id = in.Get<std::int64_t>();
  for (std::string* text : {&r.reference_key, &r.state, &r.status, &r.message, &r.zones_json}) {
    *text = in.GetString();
  }
  r.max_force_n = in.GetDoubles();
  r.steps = in.Get<std::int64_t>();
  r.wall_s = in.Get<double>();
  return r;
}

void EnsembleStudy::EncodeScore(const EnsembleMemberRow& s, ByteWriter& out) const {
  out.Put(s.reference_id);
  out.Put(s.member_seed);
  out.Put(s.coordinates);
  out.Put(s.dt_used_s);
  out.Put(s.steps);
  for (double v : {s.wall_s, s.cpu_s, s.max_energy_ratio}) out.Put(v);
  out.Put(static_cast<std::uint64_t>(s.zones.size()));
  for (const EnsembleZoneRow& z : s.zones) EncodeZone(z, out);
}

EnsembleMemberRow EnsembleStudy::DecodeScore(ByteReader& in) const {
  EnsembleMemberRow s;
  s.reference_id = in.Get<std::int64_t>();
  s.member_seed = in.GetString();
  s.coordinates = in.Get<int>();
  s.dt_used_s = in.Get<double>();
  s.steps = in.Get<std::int64_t>();
  for (double* v : {&s.wall_s, &s.cpu_s, &s.max_energy_ratio}) *v = in.Get<double>();
  const auto zones = in.Get<std::uint64_t>();
  // A truncated message throws in DecodeZone before the count is reached.
  for (std::uint64_t i = 0; i < zones; ++i) s.zones.push_back(DecodeZone(in));
  return s;
}

}  // namespace shockmap
