#include "engine/scene_study.h"

#include "compare/scene_scoring.h"
#include "core/input_error.h"
#include "db/stored_json.h"
#include "engine/record_codec.h"

namespace shockmap {

SceneStudy::SceneStudy(SceneStudySpec spec)
    : spec_(std::move(spec)), header_{spec_.file, spec_.name, spec_.spec_json} {}

std::optional<SettingChange> SceneStudy::ChangedSetting(const nlohmann::json& stored,
                                                        const std::string&) const {
  return FirstChangedSetting(stored.value("settings", nlohmann::json()),
                             nlohmann::json::parse(SceneSettingsKey(spec_)), "settings");
}

NewPoint SceneStudy::Describe(const Point& point) const {
  const ScenePointParameters parameters{ParametersJson(point)};
  return {parameters.parameters_json, ParametersJson(ReferenceParameters(spec_, point)),
          CellsOf(parameters, kScenePointParameterColumns)};
}

SceneStudy::Reference SceneStudy::ComputeReference(const Point& point) const {
  const SceneParameters parameters = ReferenceParameters(spec_, point);
  Reference ref;
  ref.parameters_json = ParametersJson(parameters);
  ref.reference_key = SceneReferenceKey(spec_, nlohmann::json::parse(ref.parameters_json));
  ref.status = ToString(RunStatus::kFailed);
  try {
    const SceneRun run = RunScene(ScoredScene(spec_, parameters));
    const RunSummary& s = run.result.summary;
    ref.status = ToString(s.status);
    ref.message = s.message;
    ref.output_dt_s = run.result.displacement_m[0].dt_s;
    ref.displacement_m = run.result.displacement_m[0].values;
    ref.force_n = run.result.contact_force_n[0].values;
    ref.steps = s.steps_taken;
    ref.wall_s = s.wall_s;
    ref.max_energy_ratio = s.max_energy_ratio;
  } catch (const std::exception& e) {
    ref.message = e.what();
  }
  return ref;
}

std::optional<StoredReference<SceneStudy::Reference>> SceneStudy::FindReference(
    StudyDatabase& db, const std::string& reference_parameters) const {
  const StoredCell cell{db.Raw().Path(), "a scene point", "reference_key"};
  const nlohmann::json parameters = ParseStoredJson(cell, reference_parameters);
  if (!parameters.is_object()) ThrowCorruptCell(cell, "not an object of parameters");
  auto row = FindSceneReference(db, SceneReferenceKey(spec_, parameters));
  if (!row) return std::nullopt;
  const std::int64_t id = row->reference_id;
  return StoredReference<Reference>{id, std::move(*row)};
}

std::int64_t SceneStudy::StoreReference(StudyDatabase& db, const Reference& reference,
                                        std::int64_t run_id) const {
  return StoreSceneReference(db, reference, run_id);
}

SceneStudy::Outcome SceneStudy::Score(const Point& point, const Reference& ref,
                                      std::int64_t reference_id) const {
  if (ref.status != ToString(RunStatus::kOk)) {
    return {RunStatus::kFailed, "reference " + ref.status + ": " + ref.message, {}};
  }
  Outcome out;
  try {
    const Scene scene = ScoredScene(spec_, point);
    const SceneRun run = RunScene(scene);
    out.status = run.result.summary.status;
    out.message = run.result.summary.message;
    SceneScore scored =
        ScoreSceneRun(scene, run, ref, {spec_.scoring.window_s, spec_.scoring.rest_duration_s});
    scored.row.reference_id = reference_id;
    out.status = scored.status;
    out.message = std::move(scored.message);
    out.score = std::move(scored.row);
  } catch (const std::exception& e) {
    out.message = e.what();
  }
  return out;
}

void SceneStudy::EncodeReference(const Reference& reference, ByteWriter& out) const {
  out.Put(reference.reference_id);
  PutRecord(reference, kSceneReferenceColumns, out);
}

SceneStudy::Reference SceneStudy::DecodeReference(ByteReader& in) const {
  const auto id = in.Get<std::int64_t>();
  Reference reference = GetRecord<Reference>(in, kSceneReferenceColumns);
  reference.reference_id = id;
  return reference;
}

void SceneStudy::EncodeScore(const SceneScoreRow& score, ByteWriter& out) const {
  PutRecord(score, kSceneScoreColumns, out);
}

SceneScoreRow SceneStudy::DecodeScore(ByteReader& in) const {
  return GetRecord<SceneScoreRow>(in, kSceneScoreColumns);
}

}  // namespace shockmap
