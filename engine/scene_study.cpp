#include "engine/scene_study.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "compare/scene_run.h"
#include "core/input_error.h"
#include "validation/impulse_ratio.h"
#include "validation/spectral_error.h"

namespace shockmap {

SceneStudy::SceneStudy(SceneStudySpec spec)
    : spec_(std::move(spec)), header_{spec_.file, spec_.name, spec_.spec_json} {}

bool SceneStudy::KeepsSettingsOf(const nlohmann::json& stored, const std::string&) const {
  return stored.value("settings", nlohmann::json()) ==
         nlohmann::json::parse(SceneSettingsKey(spec_));
}

NewPoint SceneStudy::Describe(const Point& point) const {
  const std::string key = ParametersJson(point);
  return {key, SceneReferenceKey(spec_, ReferenceParameters(spec_, point)), {key}};
}

SceneStudy::Reference SceneStudy::ComputeReference(const Point& point) const {
  const SceneParameters parameters = ReferenceParameters(spec_, point);
  Reference ref;
  ref.reference_key = SceneReferenceKey(spec_, parameters);
  ref.parameters_json = ParametersJson(parameters);
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
    StudyDatabase& db, const std::string& key) const {
  auto row = FindSceneReference(db, key);
  if (!row) return std::nullopt;
  const std::int64_t id = row->reference_id;
  return StoredReference<Reference>{id, std::move(*row)};
}

std::int64_t SceneStudy::StoreReference(StudyDatabase& db, const Reference& reference,
                                        std::int64_t run_id) const {
  return StoreSceneReference(db, reference, run_id);
}

// Cost, bounds and the largest force of a run; the first shock of the scored zone.
SceneScoreRow SceneStudy::Measure(const Scene& scene, const SceneRun& run) const {
  const RunSummary& s = run.result.summary;
  SceneScoreRow score;
  score.coordinates = run.coordinates;
  score.zones = static_cast<int>(scene.zones.size());
  score.dt_used_s = s.dt_used_s;
  score.dt_paper_s = run.bounds.dt_paper_s;
  score.dt_sharp_s = run.bounds.dt_sharp_s;
  score.steps = s.steps_taken;
  score.wall_s = s.wall_s;
  score.cpu_s = s.cpu_s;
  score.max_energy_ratio = s.max_energy_ratio;
  const auto largest =
      std::max_element(run.max_contact_force_n.begin(), run.max_contact_force_n.end());
  score.largest_force_n = *largest;
  score.largest_force_zone =
      scene.zones[static_cast<std::size_t>(largest - run.max_contact_force_n.begin())].name;
  const auto& shocks = run.shocks[0];
  score.n_shocks = static_cast<int>(shocks.size());
  if (!shocks.empty()) {
    score.first_shock_peak_n = shocks.front().peak_force_n;
    score.first_shock_impulse_n_s = shocks.front().impulse_n_s;
  }
  return score;
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
    const RunSummary& s = run.result.summary;
    SceneScoreRow score = Measure(scene, run);
    score.reference_id = reference_id;
    out.status = s.status;
    out.message = s.message;
    // A window inside one step holds no history to compare: Err would be 0 and the point pass.
    if (s.status == RunStatus::kOk && spec_.scoring.window_s < s.dt_requested_s) {
      out.status = RunStatus::kFailed;
      out.message =
          fmt::format("the window {:g} s is shorter than one time step ({:g} s): nothing to score",
                      spec_.scoring.window_s, s.dt_requested_s);
    } else if (s.status == RunStatus::kOk) {
      const UniformSignal ref_displacement{0.0, ref.output_dt_s, ref.displacement_m};
      const UniformSignal ref_force{0.0, ref.output_dt_s, ref.force_n};
      ShockSegmentationOptions segmentation;
      segmentation.rest_duration_s = spec_.scoring.rest_duration_s;
      const double end =
          std::min(run.result.displacement_m[0].EndTime(), ref_displacement.EndTime());
      score.err =
          SpectralError(run.result.displacement_m[0], ref_displacement, 0.0, end, PsdOptions{});
      score.srf = FirstShockImpulseRatio(
          run.shocks[0],
          SegmentShocks(ref_force, segmentation, std::numeric_limits<double>::infinity()));
    }
    out.score = score;
  } catch (const std::exception& e) {
    out.message = e.what();
  }
  return out;
}

void SceneStudy::EncodeReference(const Reference& r, ByteWriter& out) const {
  out.Put(r.reference_id);
  for (const std::string* text : {&r.reference_key, &r.parameters_json, &r.status, &r.message}) {
    out.Put(*text);
  }
  out.Put(r.output_dt_s);
  out.Put(r.displacement_m);
  out.Put(r.force_n);
  out.Put(r.steps);
  out.Put(r.wall_s);
  out.Put(r.max_energy_ratio);
}

SceneStudy::Reference SceneStudy::DecodeReference(ByteReader& in) const {
  Reference r;
  r.reference_id = in.Get<std::int64_t>();
  for (std::string* text : {&r.reference_key, &r.parameters_json, &r.status, &r.message}) {
    *text = in.GetString();
  }
  r.output_dt_s = in.Get<double>();
  r.displacement_m = in.GetDoubles();
  r.force_n = in.GetDoubles();
  r.steps = in.Get<std::int64_t>();
  r.wall_s = in.Get<double>();
  r.max_energy_ratio = in.Get<double>();
  return r;
}

void SceneStudy::EncodeScore(const SceneScoreRow& s, ByteWriter& out) const {
  out.Put(s.reference_id);
  out.Put(s.err);
  out.Put(s.srf);
  for (int v : {s.coordinates, s.zones, s.n_shocks}) out.Put(v);
  for (double v : {s.dt_used_s, s.dt_paper_s, s.dt_sharp_s, s.wall_s, s.cpu_s, s.max_energy_ratio,
                   s.largest_force_n}) {
    out.Put(v);
  }
  out.Put(s.steps);
  out.Put(s.largest_force_zone);
  out.Put(s.first_shock_peak_n);
  out.Put(s.first_shock_impulse_n_s);
}

SceneScoreRow SceneStudy::DecodeScore(ByteReader& in) const {
  SceneScoreRow s;
  s.reference_id = in.Get<std::int64_t>();
  s.err = in.GetOptional<double>();
  s.srf = in.GetOptional<double>();
  for (int* v : {&s.coordinates, &s.zones, &s.n_shocks}) *v = in.Get<int>();
  for (double* v : {&s.dt_used_s, &s.dt_paper_s, &s.dt_sharp_s, &s.wall_s, &s.cpu_s,
                    &s.max_energy_ratio, &s.largest_force_n}) {
    *v = in.Get<double>();
  }
  s.steps = in.Get<std::int64_t>();
  s.largest_force_zone = in.GetString();
  s.first_shock_peak_n = in.GetOptional<double>();
  s.first_shock_impulse_n_s = in.GetOptional<double>();
  return s;
}

}  // namespace shockmap
