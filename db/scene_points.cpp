#include "db/scene_points.h"

namespace shockmap {

const PointTable kScenePoints{"scene_points", {"parameters_json"}};

namespace {

void WriteScore(Connection& c, std::int64_t point_id, const std::optional<SceneScoreRow>& score) {
  Statement update = c.Prepare(
      "UPDATE scene_points SET reference_id = ?, err = ?, srf = ?, coordinates = ?, zones = ?, "
      "dt_used_s = ?, dt_paper_s = ?, dt_sharp_s = ?, steps = ?, wall_s = ?, cpu_s = ?, "
      "max_energy_ratio = ?, largest_force_n = ?, largest_force_zone = ?, n_shocks = ?, "
      "first_shock_peak_n = ?, first_shock_impulse_n_s = ? WHERE point_id = ?");
  if (score) {
    const SceneScoreRow& r = *score;
    update.BindAll(r.reference_id, r.err, r.srf, r.coordinates, r.zones, r.dt_used_s, r.dt_paper_s,
                   r.dt_sharp_s, r.steps, r.wall_s, r.cpu_s, r.max_energy_ratio, r.largest_force_n,
                   r.largest_force_zone, r.n_shocks, r.first_shock_peak_n,
                   r.first_shock_impulse_n_s);
  } else {
    for (int i = 1; i <= 17; ++i) update.BindNull(i);
  }
  update.Bind(18, point_id).Run();
}

}  // namespace

void StoreSceneOutcome(StudyDatabase& db, std::int64_t point_id, std::int64_t run_id,
                       const PointOrigin& origin, const std::string& status,
                       const std::string& message, const std::optional<SceneScoreRow>& score) {
  StorePointOutcome(db, kScenePoints, point_id, run_id, origin, status, message,
                    [&](Connection& c) { WriteScore(c, point_id, score); });
}

std::optional<SceneReferenceRow> FindSceneReference(StudyDatabase& db, const std::string& key) {
  Statement s = db.Raw().Prepare(
      "SELECT reference_id, parameters_json, status, message, output_dt_s, displacement_m, "
      "force_n, steps, wall_s, max_energy_ratio FROM scene_references WHERE reference_key = ?");
  s.Bind(1, key);
  if (!s.Step()) return std::nullopt;
  SceneReferenceRow r;
  r.reference_key = key;
  s.ReadColumns(r.reference_id, r.parameters_json, r.status, r.message, r.output_dt_s,
                r.displacement_m, r.force_n, r.steps, r.wall_s, r.max_energy_ratio);
  return r;
}

std::int64_t StoreSceneReference(StudyDatabase& db, const SceneReferenceRow& r,
                                 std::int64_t run_id) {
  return InsertRow(db,
                   "INSERT INTO scene_references(reference_key, parameters_json, status, message, "
                   "output_dt_s, displacement_m, force_n, steps, wall_s, max_energy_ratio, run_id, "
                   "created_utc) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)",
                   r.reference_key, r.parameters_json, r.status, r.message, r.output_dt_s,
                   r.displacement_m, r.force_n, r.steps, r.wall_s, r.max_energy_ratio, run_id,
                   UtcNow());
}

}  // namespace shockmap
