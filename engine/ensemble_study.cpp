#include "engine/ensemble_study.h"

#include <fmt/format.h>

#include <algorithm>

#include "compare/scene_scoring.h"
#include "engine/record_codec.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// Where each zone sits and what it joins, for the sizing view's tables and maps.
std::string ZonesJson(const Scene& scene) {
  Json zones = Json::array();
  for (const SceneZone& z : scene.zones) {
    zones.push_back({{"name", z.name},
                     {"beam_a", scene.SideName(z, false)},
                     {"beam_b", scene.SideName(z, true)},
                     {"height_m", z.height_m},
                     {"y_m", z.y_m},
                     {"z_m", z.z_m}});
  }
  return zones.dump();
}

}  // namespace

EnsembleStudy::EnsembleStudy(EnsembleStudySpec spec)
    : spec_(std::move(spec)), header_{spec_.file, spec_.name, spec_.spec_json} {}

// Clearance states may be added; one of the same name keeps its settings.
std::optional<SettingChange> EnsembleStudy::ChangedSetting(const Json& stored,
                                                           const std::string&) const {
  const Json was = stored.value("settings_key", Json());
  const Json now = Json::parse(EnsembleSettingsKey(spec_));
  if (!was.is_object()) return FirstChangedSetting(was, now, "settings");
  for (const char* key : {"scene", "seed", "draws", "window_s", "impact_counting"}) {
    if (auto change = FirstChangedSetting(was.value(key, Json()), now.at(key), key)) return change;
  }
  const Json was_states = was.value("states", Json::object());
  for (const auto& [name, state] : now.at("states").items()) {
    if (!was_states.contains(name)) continue;
    if (auto change = FirstChangedSetting(was_states.at(name), state, "states." + name)) {
      return change;
    }
  }
  return std::nullopt;
}

NewPoint EnsembleStudy::Describe(const Point& m) const {
  const EnsembleMemberParameters parameters{spec_.states[m.state].name,
                                            spec_.settings[m.setting].dump(), m.member};
  return {MemberKey(spec_, m), parameters.state,
          CellsOf(parameters, kEnsembleMemberParameterColumns)};
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
    const Scene scene = MemberScene(spec_, point);
    const SceneRun run = RunScene(scene);
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
    out.status = s.status;
    out.message = s.message;
    if (s.status == RunStatus::kOk && spec_.window_s < s.dt_requested_s) {
      // Its draws made the step longer than the window the study file was checked for.
      out.status = RunStatus::kFailed;
      out.message =
          fmt::format("the window {:g} s is shorter than one time step ({:g} s): nothing to size",
                      spec_.window_s, s.dt_requested_s);
    } else if (s.status == RunStatus::kOk) {
      row.zones = MemberZoneRows(scene, run);
      row.impacts = MemberImpactRows(scene, run);
    }
    out.score = std::move(row);
  } catch (const std::exception& e) {
    out.message = e.what();
  }
  return out;
}

void EnsembleStudy::EncodeReference(const Reference& reference, ByteWriter& out) const {
  out.Put(reference.reference_id);
  PutRecord(reference, kEnsembleReferenceColumns, out);
}

EnsembleStudy::Reference EnsembleStudy::DecodeReference(ByteReader& in) const {
  const auto id = in.Get<std::int64_t>();
  Reference reference = GetRecord<Reference>(in, kEnsembleReferenceColumns);
  reference.reference_id = id;
  return reference;
}

void EnsembleStudy::EncodeScore(const EnsembleMemberRow& score, ByteWriter& out) const {
  PutRecord(score, kEnsembleMemberColumns, out);
  out.Put(static_cast<std::uint64_t>(score.zones.size()));
  for (const EnsembleZoneRow& zone : score.zones) PutRecord(zone, kEnsembleZoneColumns, out);
  out.Put(static_cast<std::uint64_t>(score.impacts.size()));
  for (const EnsembleImpactRow& impact : score.impacts)
    PutRecord(impact, kEnsembleImpactColumns, out);
}

EnsembleMemberRow EnsembleStudy::DecodeScore(ByteReader& in) const {
  EnsembleMemberRow score = GetRecord<EnsembleMemberRow>(in, kEnsembleMemberColumns);
  const auto zones = in.Get<std::uint64_t>();
  // A truncated message throws in GetRecord before the count is reached.
  for (std::uint64_t i = 0; i < zones; ++i) {
    score.zones.push_back(GetRecord<EnsembleZoneRow>(in, kEnsembleZoneColumns));
  }
  const auto impacts = in.Get<std::uint64_t>();
  for (std::uint64_t i = 0; i < impacts; ++i) {
    score.impacts.push_back(GetRecord<EnsembleImpactRow>(in, kEnsembleImpactColumns));
  }
  return score;
}

}  // namespace shockmap
